#include "core/io/file_bytes.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "core/base/errors.h"

namespace zomeify {

std::string read_file_bytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in)
        throw IoError("cannot open '" + path + "'");
    const std::streamoff size = in.tellg();
    if (size < 0)
        throw IoError("cannot read '" + path + "'");
    if (static_cast<unsigned long long>(size) > kMaxInputFileBytes)
        throw IoError("'" + path + "' is larger than 1 GiB");
    std::string bytes(static_cast<size_t>(size), '\0');
    in.seekg(0);
    if (!in.read(bytes.data(), size))
        throw IoError("cannot read '" + path + "'");
    return bytes;
}

void write_file_bytes(const std::string& path, const std::string& bytes)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out || !out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())) || !out.flush())
        throw IoError("cannot write '" + path + "'");
}

std::string model_extension(const std::string& path)
{
    const size_t slash = path.find_last_of("/\\");
    std::string name = path.substr(slash == std::string::npos ? 0 : slash + 1);
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
    for (const char* two : {".zome.json"})
        if (name.size() > std::string(two).size() && name.ends_with(two))
            return two;
    const size_t dot = name.find_last_of('.');
    return dot == std::string::npos ? std::string() : name.substr(dot);
}

} // namespace zomeify
