// STL, ASCII or binary. Every triangle gets its own three vertices, as the format has no sharing;
// prepare_surface welds them. The facet normals are ignored (the winding order decides).
#include <cmath>

#include "core/base/errors.h"
#include "core/surface/byte_order.h"
#include "core/surface/readers.h"
#include "core/surface/text_scan.h"

namespace zomeify::detail {

namespace {

constexpr size_t header_size = 84;   // 80-byte header + uint32 triangle count
constexpr size_t triangle_size = 50; // normal, 3 vertices (12 floats) + uint16 attribute

bool starts_with_solid(std::span<const uint8_t> bytes)
{
    size_t i = 0;
    while (i < bytes.size() && (bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\r' || bytes[i] == '\n'))
        ++i;
    const std::string_view word = "solid";
    if (bytes.size() - i < word.size())
        return false;
    for (size_t k = 0; k < word.size(); ++k)
        if (static_cast<char>(bytes[i + k] | 0x20) != word[k])
            return false;
    return true;
}

PolygonSoup read_binary(std::span<const uint8_t> bytes, uint32_t count)
{
    PolygonSoup soup;
    soup.positions.reserve(3 * static_cast<size_t>(count));
    soup.polygons.reserve(count);
    for (size_t t = 0; t < count; ++t)
    {
        const uint8_t* p = bytes.data() + header_size + t * triangle_size + 12;
        std::vector<uint32_t> polygon;
        for (int corner = 0; corner < 3; ++corner)
        {
            Vec3 v;
            for (int a = 0; a < 3; ++a)
            {
                const float x = load_f32(p + 12 * corner + 4 * a, false);
                if (!std::isfinite(x))
                    throw InvalidInputError("triangle " + std::to_string(t) + ": vertex coordinate is NaN or infinite");
                v[a] = x;
            }
            polygon.push_back(static_cast<uint32_t>(soup.positions.size()));
            soup.positions.push_back(v);
        }
        soup.polygons.push_back(std::move(polygon));
    }
    return soup;
}

PolygonSoup read_ascii(std::span<const uint8_t> bytes)
{
    PolygonSoup soup;
    LineScanner lines(bytes);
    std::string_view line;
    bool in_loop = false;
    std::vector<uint32_t> polygon;
    while (lines.next(line))
    {
        TokenSplitter tokens(line);
        std::string_view token;
        if (!tokens.next(token))
            continue;
        // Some exporters write the keywords in capitals.
        std::string keyword(token);
        for (char& c : keyword)
            c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
        const size_t n = lines.line_number();
        if (keyword == "outer")
        {
            if (in_loop)
                throw InvalidInputError(at_line(n) + "'outer loop' inside another loop");
            in_loop = true;
            polygon.clear();
        }
        else if (keyword == "endloop")
        {
            if (!in_loop)
                throw InvalidInputError(at_line(n) + "'endloop' without 'outer loop'");
            in_loop = false;
            soup.polygons.push_back(polygon);
        }
        else if (keyword == "vertex")
        {
            if (!in_loop)
                throw InvalidInputError(at_line(n) + "'vertex' outside 'outer loop'");
            Vec3 v;
            for (int a = 0; a < 3; ++a)
            {
                double x = 0;
                if (!tokens.next(token) || !parse_double(token, x))
                    throw InvalidInputError(at_line(n) + "vertex needs 3 numbers");
                if (!std::isfinite(x))
                    throw InvalidInputError(at_line(n) + "vertex coordinate is NaN or infinite");
                v[a] = x;
            }
            polygon.push_back(static_cast<uint32_t>(soup.positions.size()));
            soup.positions.push_back(v);
        }
        else if (keyword != "solid" && keyword != "endsolid" && keyword != "facet" && keyword != "endfacet")
            throw InvalidInputError(at_line(n) + "unexpected " + quote_token(keyword) + " in an ASCII STL file");
    }
    if (in_loop)
        throw InvalidInputError("file ends inside a facet");
    if (soup.polygons.empty())
        throw InvalidInputError("no facets found");
    return soup;
}

} // namespace

PolygonSoup read_stl(std::span<const uint8_t> bytes)
{
    if (bytes.empty())
        throw InvalidInputError("file is empty");
    // Many binary files start with "solid" too, so the size rule decides first: a binary file is
    // exactly 84 + 50 n bytes. The count is checked against the size before anything is allocated.
    if (bytes.size() >= header_size)
    {
        const uint32_t count = load_u32_le(bytes.data() + 80);
        if (bytes.size() == header_size + triangle_size * static_cast<size_t>(count))
        {
            if (count == 0)
                throw InvalidInputError("binary STL with no triangles");
            return read_binary(bytes, count);
        }
        if (!starts_with_solid(bytes))
            throw InvalidInputError("not an STL file: binary header says " + std::to_string(count) +
                                    " triangles, which needs " +
                                    std::to_string(header_size + triangle_size * static_cast<uint64_t>(count)) +
                                    " bytes, but the file has " + std::to_string(bytes.size()));
    }
    else if (!starts_with_solid(bytes))
        throw InvalidInputError("not an STL file (too short for binary, no 'solid' header)");
    return read_ascii(bytes);
}

} // namespace zomeify::detail
