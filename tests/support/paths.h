#pragma once
//! \file paths.h
//! Where tests find data: the shared folder beside the project and the project's tests/data.

#include <string>

#include <gtest/gtest.h>

#include "tests/support/shared_paths.h"

//! First statement of a test that reads ../shared/data: skips it, naming the folder looked for, when absent.
#define ZOME_REQUIRE_SHARED()                                                                                          \
    if (!::zomeify::test::shared_available())                                                                          \
    GTEST_SKIP() << "needs the shared data folder " << ::zomeify::test::shared_path("data")                            \
                 << ", which is absent (set ZOMEIFY_SHARED to the folder that holds data/)"

namespace zomeify::test {

inline std::string test_data_path(const std::string& rel) { return std::string(ZOME_TEST_DATA_DIR) + "/" + rel; }

//! A scratch file path unique to this test process.
std::string temp_path(const std::string& name);

} // namespace zomeify::test
