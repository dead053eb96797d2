#include "tests/support/paths.h"

#include <chrono>
#include <filesystem>
#include <system_error>

#include <unistd.h>

namespace zomeify::test {
namespace {

// One folder per test process, removed when the process ends (ctest runs one process per test).
// The clock is in the name because Emscripten's getpid() is 42 in every process.
struct ProcessTempDir
{
    std::filesystem::path path = std::filesystem::temp_directory_path() /
                                 ("zomeify-tests-" + std::to_string(getpid()) + "-" +
                                  std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
    ~ProcessTempDir()
    {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
};

} // namespace

std::string temp_path(const std::string& name)
{
    static ProcessTempDir dir;
    std::filesystem::create_directories(dir.path);
    return (dir.path / name).string();
}

} // namespace zomeify::test
