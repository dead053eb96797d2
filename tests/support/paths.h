#pragma once
//! \file paths.h
//! Where tests find data: the shared folder beside the project and the project's tests/data.

#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace zomeify::test {

//! The shared data folder: $ZOMEIFY_SHARED when set, else ../shared beside the project (ZOME_SHARED_DIR).
inline std::string shared_dir()
{
    const char* env = std::getenv("ZOMEIFY_SHARED");
    return env && *env ? std::string(env) : std::string(ZOME_SHARED_DIR);
}

inline std::string shared_path(const std::string& rel) { return shared_dir() + "/" + rel; }

//! True when the shared meshes and models are there (a user's clone has no ../shared).
inline bool shared_available() { return std::filesystem::is_directory(shared_path("data")); }

} // namespace zomeify::test

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
