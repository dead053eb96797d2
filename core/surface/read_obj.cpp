// Wavefront OBJ: only `v` and `f` matter; every other statement (vt, vn, o, g, s, usemtl, mtllib,
// l, p, ...) is skipped. Face corners may be `a`, `a/b`, `a//c` or `a/b/c`, indices 1-based or
// negative (relative to the vertices read so far).
#include <cmath>
#include <limits>

#include "core/base/errors.h"
#include "core/surface/readers.h"
#include "core/surface/text_scan.h"

namespace zomeify::detail {

namespace {

Vec3 parse_vertex(TokenSplitter& tokens, size_t line)
{
    Vec3 p;
    for (int axis = 0; axis < 3; ++axis)
    {
        std::string_view token;
        if (!tokens.next(token))
            throw InvalidInputError(at_line(line) + "vertex has fewer than 3 coordinates");
        double value = 0;
        if (!parse_double(token, value))
            throw InvalidInputError(at_line(line) + "bad vertex coordinate " + quote_token(token));
        if (!std::isfinite(value))
            throw InvalidInputError(at_line(line) + "vertex coordinate is NaN or infinite");
        p[axis] = value;
    }
    return p;
}

// The position index of one face corner ("7", "7/2", "7//3", "-1/2/3"), made 0-based. Positive
// indices may refer to vertices defined later in the file, so they are range-checked at the end.
long long parse_corner(std::string_view token, size_t vertices_so_far, size_t line)
{
    const std::string_view index = token.substr(0, token.find('/'));
    long long value = 0;
    if (!parse_int(index, value))
        throw InvalidInputError(at_line(line) + "bad face index " + quote_token(token));
    if (value == 0)
        throw InvalidInputError(at_line(line) + "face index 0 (OBJ indices start at 1)");
    if (value < 0)
    {
        const long long resolved = static_cast<long long>(vertices_so_far) + value;
        if (resolved < 0)
            throw InvalidInputError(at_line(line) + "relative face index " + std::to_string(value) +
                                    " reaches before the first vertex");
        return resolved;
    }
    return value - 1;
}

} // namespace

PolygonSoup read_obj(std::span<const uint8_t> bytes)
{
    if (bytes.empty())
        throw InvalidInputError("file is empty");
    PolygonSoup soup;
    LineScanner lines(bytes);
    std::string_view line;
    long long max_index = -1;
    size_t max_index_line = 0;
    while (lines.next(line))
    {
        TokenSplitter tokens(line);
        std::string_view keyword;
        if (!tokens.next(keyword) || keyword[0] == '#')
            continue;
        if (keyword == "v")
            soup.positions.push_back(parse_vertex(tokens, lines.line_number()));
        else if (keyword == "f")
        {
            std::vector<uint32_t> polygon;
            std::string_view token;
            while (tokens.next(token))
            {
                if (token[0] == '#')
                    break;
                const long long index = parse_corner(token, soup.positions.size(), lines.line_number());
                if (index > std::numeric_limits<uint32_t>::max() - 1)
                    throw InvalidInputError(at_line(lines.line_number()) + "face index " + std::to_string(index + 1) +
                                            " is too large");
                if (index > max_index)
                {
                    max_index = index;
                    max_index_line = lines.line_number();
                }
                polygon.push_back(static_cast<uint32_t>(index));
            }
            soup.polygons.push_back(std::move(polygon));
        }
    }
    if (soup.positions.empty())
        throw InvalidInputError("no vertices ('v' lines) found");
    if (max_index >= static_cast<long long>(soup.positions.size()))
        throw InvalidInputError(at_line(max_index_line) + "face index " + std::to_string(max_index + 1) +
                                " is out of range (the file has " + std::to_string(soup.positions.size()) +
                                " vertices)");
    return soup;
}

} // namespace zomeify::detail
