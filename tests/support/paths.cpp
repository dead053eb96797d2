#include "tests/support/paths.h"

#include <filesystem>

namespace zomeify::test {

std::string temp_path(const std::string& name)
{
    const auto dir = std::filesystem::temp_directory_path() / "zomeify-tests";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

} // namespace zomeify::test
