// OFF (Geomview): a header keyword (OFF, COFF, NOFF, STOFF, ... ending in "OFF"), the counts
// "V F E", V vertex lines and F face lines "n i1 .. in". Extra columns (colours, normals, texture
// coordinates) are ignored, so reading is line by line; '#' starts a comment anywhere.
#include <cmath>

#include "core/base/errors.h"
#include "core/surface/readers.h"
#include "core/surface/text_scan.h"

namespace zomeify::detail {

namespace {

// The next line that has something besides blanks and a comment, with the comment cut off.
bool next_content_line(LineScanner& lines, std::string_view& line)
{
    while (lines.next(line))
    {
        const size_t hash = line.find('#');
        if (hash != std::string_view::npos)
            line = line.substr(0, hash);
        std::string_view token;
        if (TokenSplitter(line).next(token))
            return true;
    }
    return false;
}

long long parse_count(TokenSplitter& tokens, size_t line, const char* what)
{
    std::string_view token;
    long long n = 0;
    if (!tokens.next(token) || !parse_int(token, n) || n < 0)
        throw InvalidInputError(at_line(line) + "bad or missing " + what + " count in the OFF header");
    return n;
}

} // namespace

PolygonSoup read_off(std::span<const uint8_t> bytes)
{
    if (bytes.empty())
        throw InvalidInputError("file is empty");
    LineScanner lines(bytes);
    std::string_view line;
    if (!next_content_line(lines, line))
        throw InvalidInputError("no OFF header");
    TokenSplitter header(line);
    std::string_view keyword;
    header.next(keyword);
    if (keyword.size() < 3 || keyword.substr(keyword.size() - 3) != "OFF")
        throw InvalidInputError(at_line(lines.line_number()) + "not an OFF file (header " + quote_token(keyword) + ")");
    if (keyword.find('4') != std::string_view::npos || keyword.find('n') != std::string_view::npos)
        throw InvalidInputError(at_line(lines.line_number()) + "only 3-dimensional OFF is supported");
    std::string_view token;
    TokenSplitter after(header.rest());
    if (after.next(token) && token == "BINARY")
        throw InvalidInputError(at_line(lines.line_number()) + "binary OFF is not supported");

    // The counts follow on the same line or on the next content line.
    TokenSplitter counts(header.rest());
    if (!TokenSplitter(header.rest()).next(token))
    {
        if (!next_content_line(lines, line))
            throw InvalidInputError("missing vertex and face counts");
        counts = TokenSplitter(line);
    }
    const size_t count_line = lines.line_number();
    const long long nv = parse_count(counts, count_line, "vertex");
    const long long nf = parse_count(counts, count_line, "face");
    // Each vertex and face takes a line, so the counts cannot exceed the lines left: checked
    // before reserving, so a header claiming 2^31 faces is an error and not an allocation.
    const size_t available = lines.remaining_lines();
    if (static_cast<unsigned long long>(nv) + static_cast<unsigned long long>(nf) > available)
        throw InvalidInputError(at_line(count_line) + "header says " + std::to_string(nv) + " vertices and " +
                                std::to_string(nf) + " faces, but only " + std::to_string(available) + " lines follow");
    if (nv == 0)
        throw InvalidInputError(at_line(count_line) + "no vertices");
    PolygonSoup soup;
    soup.positions.reserve(static_cast<size_t>(nv));
    soup.polygons.reserve(static_cast<size_t>(nf));
    for (long long i = 0; i < nv; ++i)
    {
        if (!next_content_line(lines, line))
            throw InvalidInputError("file ends after " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
        TokenSplitter tokens(line);
        Vec3 p;
        for (int a = 0; a < 3; ++a)
        {
            double x = 0;
            if (!tokens.next(token) || !parse_double(token, x))
                throw InvalidInputError(at_line(lines.line_number()) + "vertex " + std::to_string(i) +
                                        " needs 3 numbers");
            if (!std::isfinite(x))
                throw InvalidInputError(at_line(lines.line_number()) + "vertex " + std::to_string(i) +
                                        " has a NaN or infinite coordinate");
            p[a] = x;
        }
        soup.positions.push_back(p);
    }
    for (long long f = 0; f < nf; ++f)
    {
        if (!next_content_line(lines, line))
            throw InvalidInputError("file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
        const size_t n = lines.line_number();
        TokenSplitter tokens(line);
        long long k = 0;
        if (!tokens.next(token) || !parse_int(token, k) || k < 0)
            throw InvalidInputError(at_line(n) + "face " + std::to_string(f) + ": bad vertex count");
        if (static_cast<unsigned long long>(k) > line.size())
            throw InvalidInputError(at_line(n) + "face " + std::to_string(f) + " claims " + std::to_string(k) +
                                    " vertices, more than the line holds");
        std::vector<uint32_t> polygon;
        polygon.reserve(static_cast<size_t>(k));
        for (long long c = 0; c < k; ++c)
        {
            long long index = 0;
            if (!tokens.next(token) || !parse_int(token, index))
                throw InvalidInputError(at_line(n) + "face " + std::to_string(f) + " has fewer than " +
                                        std::to_string(k) + " indices");
            if (index < 0 || index >= nv)
                throw InvalidInputError(at_line(n) + "face " + std::to_string(f) + ": index " + std::to_string(index) +
                                        " is out of range (" + std::to_string(nv) + " vertices)");
            polygon.push_back(static_cast<uint32_t>(index));
        }
        soup.polygons.push_back(std::move(polygon));
    }
    return soup;
}

} // namespace zomeify::detail
