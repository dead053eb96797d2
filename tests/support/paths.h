#pragma once
//! \file paths.h
//! Where tests find data: the shared folder beside the project and the project's tests/data.

#include <string>

namespace zomeify::test {

inline std::string shared_path(const std::string& rel)
{
    return std::string(ZOME_SHARED_DIR) + "/" + rel;
}

inline std::string test_data_path(const std::string& rel)
{
    return std::string(ZOME_TEST_DATA_DIR) + "/" + rel;
}

//! A scratch file path unique to this test process.
std::string temp_path(const std::string& name);

} // namespace zomeify::test
