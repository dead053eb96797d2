#include "core/surface/read_mesh.h"

#include <algorithm>
#include <fstream>
#include <vector>

#include "core/base/errors.h"
#include "core/surface/readers.h"

namespace zomeify {

namespace {

// Files larger than this are refused before reading (the page could not hold them either).
constexpr unsigned long long max_mesh_file_bytes = 1ull << 30;

enum class Format
{
    obj,
    stl,
    ply,
    off,
    gltf,
    glb,
    unknown
};

std::string lower_extension(std::string_view file_name)
{
    const size_t slash = file_name.find_last_of("/\\");
    const std::string_view base = slash == std::string_view::npos ? file_name : file_name.substr(slash + 1);
    const size_t dot = base.rfind('.');
    if (dot == std::string_view::npos)
        return {};
    std::string ext(base.substr(dot + 1));
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](char c) { return static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c); });
    return ext;
}

Format format_of(std::string_view file_name)
{
    const std::string ext = lower_extension(file_name);
    if (ext == "obj")
        return Format::obj;
    if (ext == "stl")
        return Format::stl;
    if (ext == "ply")
        return Format::ply;
    if (ext == "off")
        return Format::off;
    if (ext == "gltf")
        return Format::gltf;
    if (ext == "glb")
        return Format::glb;
    return Format::unknown;
}

std::string base_name(std::string_view path)
{
    const size_t slash = path.find_last_of("/\\");
    return std::string(slash == std::string_view::npos ? path : path.substr(slash + 1));
}

PolygonSoup read_format(std::span<const uint8_t> bytes, std::string_view file_name, const std::string& base_dir)
{
    switch (format_of(file_name))
    {
    case Format::obj:
        return detail::read_obj(bytes);
    case Format::stl:
        return detail::read_stl(bytes);
    case Format::ply:
        return detail::read_ply(bytes);
    case Format::off:
        return detail::read_off(bytes);
    case Format::gltf:
        return detail::read_gltf(bytes, false, base_dir);
    case Format::glb:
        return detail::read_gltf(bytes, true, base_dir);
    case Format::unknown:
        break;
    }
    throw InvalidInputError("unknown mesh format '." + lower_extension(file_name) +
                            "' (expected .obj, .stl, .ply, .off, .gltf or .glb)");
}

// Prefixes reader messages with the file's name, so a message on its own says which input is bad.
PolygonSoup read_named(std::span<const uint8_t> bytes, std::string_view file_name, const std::string& base_dir)
{
    try
    {
        return read_format(bytes, file_name, base_dir);
    }
    catch (const InvalidInputError& e)
    {
        throw InvalidInputError(base_name(file_name) + ": " + e.what());
    }
}

} // namespace

bool is_mesh_file_name(std::string_view file_name) { return format_of(file_name) != Format::unknown; }

PolygonSoup read_mesh_file(const std::string& path)
{
    if (!is_mesh_file_name(path))
        return read_named({}, path, {}); // throws the unknown-format message
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw IoError("cannot open '" + path + "'");
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0)
        throw IoError("cannot read '" + path + "'");
    if (static_cast<unsigned long long>(size) > max_mesh_file_bytes)
        throw InvalidInputError(base_name(path) + ": file is larger than 1 GiB");
    in.seekg(0, std::ios::beg);
    std::vector<uint8_t> bytes(static_cast<size_t>(size));
    if (size > 0 && !in.read(reinterpret_cast<char*>(bytes.data()), size))
        throw IoError("cannot read '" + path + "'");
    const size_t slash = path.find_last_of("/\\");
    const std::string base_dir = slash == std::string::npos ? std::string(".") : path.substr(0, slash);
    return read_named(bytes, path, base_dir);
}

PolygonSoup read_mesh_buffer(std::span<const uint8_t> bytes, std::string_view file_name)
{
    return read_named(bytes, file_name, {});
}

} // namespace zomeify
