#include "tests/support/paths.h"

#include <filesystem>

#include <unistd.h>

namespace zomeify::test {

std::string temp_path(const std::string& name)
{
    const auto dir = std::filesystem::temp_directory_path() / ("zomeify-tests-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

} // namespace zomeify::test
