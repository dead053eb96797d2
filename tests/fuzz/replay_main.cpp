// fuzz_replay: runs stored inputs through the fuzz targets without libFuzzer, so every normal build
// (and its sanitizers) replays the regression corpus and the seeds as an ordinary ctest test.
//   fuzz_replay CORPUS_ROOT...        every file in CORPUS_ROOT/<target>/ through <target>
//   fuzz_replay --target NAME PATH... files (or folders of files) through one target
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "tests/fuzz/fuzz_target.h"

namespace zomeify::fuzz {

namespace {

std::map<std::string, TargetFn>& targets()
{
    static std::map<std::string, TargetFn> table;
    return table;
}

std::vector<uint8_t> file_bytes(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Sorted so a failure names the same first file on every run.
std::vector<std::filesystem::path> files_in(const std::filesystem::path& path)
{
    std::vector<std::filesystem::path> files;
    if (std::filesystem::is_directory(path))
    {
        for (const auto& entry : std::filesystem::directory_iterator(path))
            if (entry.is_regular_file() && entry.path().filename().string().front() != '.')
                files.push_back(entry.path());
    }
    else
        files.push_back(path);
    std::sort(files.begin(), files.end());
    return files;
}

size_t replay(const std::string& name, TargetFn fn, const std::filesystem::path& path)
{
    size_t count = 0;
    for (const auto& file : files_in(path))
    {
        const std::vector<uint8_t> bytes = file_bytes(file);
        std::fprintf(stderr, "%s %s\n", name.c_str(), file.string().c_str()); // names the culprit of a crash
        fn(bytes.data(), bytes.size());
        ++count;
    }
    return count;
}

} // namespace

bool register_target(const char* name, TargetFn fn)
{
    targets()[name] = fn;
    return true;
}

} // namespace zomeify::fuzz

int main(int argc, char** argv)
{
    using namespace zomeify::fuzz;
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty())
    {
        std::fprintf(stderr, "usage: fuzz_replay CORPUS_ROOT... | fuzz_replay --target NAME PATH...\n");
        return 2;
    }
    size_t inputs = 0;
    if (args[0] == "--target")
    {
        if (args.size() < 3 || !targets().count(args[1]))
        {
            std::fprintf(stderr, "fuzz_replay: unknown target or no input\n");
            return 2;
        }
        for (size_t i = 2; i < args.size(); ++i)
            inputs += replay(args[1], targets()[args[1]], args[i]);
    }
    else
    {
        for (const std::string& root : args)
        {
            if (!std::filesystem::is_directory(root))
            {
                std::fprintf(stderr, "fuzz_replay: '%s' is not a folder\n", root.c_str());
                return 2;
            }
            for (const auto& [name, fn] : targets())
                if (std::filesystem::is_directory(std::filesystem::path(root) / name))
                    inputs += replay(name, fn, std::filesystem::path(root) / name);
        }
    }
    std::printf("fuzz_replay: %zu inputs, no crash\n", inputs);
    return 0;
}
