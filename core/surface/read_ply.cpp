// PLY (ascii, binary_little_endian, binary_big_endian). Only vertex x/y/z and the face list
// vertex_indices (or vertex_index) are kept; every other element and property is read past.
// Counts in the header are checked against the bytes that follow before anything is reserved.
#include <cmath>
#include <limits>

#include "core/base/errors.h"
#include "core/surface/byte_order.h"
#include "core/surface/readers.h"
#include "core/surface/text_scan.h"

namespace zomeify::detail {

namespace {

enum class Kind
{
    signed_int,
    unsigned_int,
    floating
};

struct Type
{
    Kind kind = Kind::floating;
    int size = 0;
};

struct Property
{
    std::string name;
    Type type;
    bool is_list = false;
    Type count_type;
};

struct Element
{
    std::string name;
    unsigned long long count = 0;
    std::vector<Property> properties;
};

enum class Encoding
{
    ascii,
    little_endian,
    big_endian
};

struct Header
{
    Encoding encoding = Encoding::ascii;
    std::vector<Element> elements;
    size_t body_offset = 0;
};

bool parse_type(std::string_view name, Type& type)
{
    struct Named
    {
        std::string_view name;
        Type type;
    };
    static const Named table[] = {
        {"char", {Kind::signed_int, 1}},     {"int8", {Kind::signed_int, 1}},     {"uchar", {Kind::unsigned_int, 1}},
        {"uint8", {Kind::unsigned_int, 1}},  {"short", {Kind::signed_int, 2}},    {"int16", {Kind::signed_int, 2}},
        {"ushort", {Kind::unsigned_int, 2}}, {"uint16", {Kind::unsigned_int, 2}}, {"int", {Kind::signed_int, 4}},
        {"int32", {Kind::signed_int, 4}},    {"uint", {Kind::unsigned_int, 4}},   {"uint32", {Kind::unsigned_int, 4}},
        {"float", {Kind::floating, 4}},      {"float32", {Kind::floating, 4}},    {"double", {Kind::floating, 8}},
        {"float64", {Kind::floating, 8}},
    };
    for (const Named& n : table)
        if (n.name == name)
        {
            type = n.type;
            return true;
        }
    return false;
}

// Finds the end of the header ("end_header" line) and parses everything before it.
Header parse_header(std::span<const uint8_t> bytes)
{
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    if (text.substr(0, 3) != "ply" || text.size() < 4 || (text[3] != '\n' && text[3] != '\r'))
        throw InvalidInputError("not a PLY file (no 'ply' magic line)");
    size_t end = text.find("end_header");
    while (end != std::string_view::npos && text[end - 1] != '\n')
        end = text.find("end_header", end + 1);
    if (end == std::string_view::npos)
        throw InvalidInputError("no 'end_header' line");
    Header header;
    const size_t newline = text.find('\n', end);
    header.body_offset = newline == std::string_view::npos ? text.size() : newline + 1;

    LineScanner lines(bytes.subspan(0, end));
    std::string_view line;
    lines.next(line); // "ply"
    bool have_format = false;
    while (lines.next(line))
    {
        const std::string where = at_line(lines.line_number());
        TokenSplitter tokens(line);
        std::string_view keyword;
        if (!tokens.next(keyword) || keyword == "comment" || keyword == "obj_info")
            continue;
        std::string_view a, b, c, d;
        if (keyword == "format")
        {
            tokens.next(a);
            if (a == "ascii")
                header.encoding = Encoding::ascii;
            else if (a == "binary_little_endian")
                header.encoding = Encoding::little_endian;
            else if (a == "binary_big_endian")
                header.encoding = Encoding::big_endian;
            else
                throw InvalidInputError(where + "unknown PLY format " + quote_token(a));
            have_format = true;
        }
        else if (keyword == "element")
        {
            Element e;
            long long count = 0;
            if (!tokens.next(a) || !tokens.next(b) || !parse_int(b, count) || count < 0)
                throw InvalidInputError(where + "bad element line");
            e.name = std::string(a);
            e.count = static_cast<unsigned long long>(count);
            header.elements.push_back(std::move(e));
        }
        else if (keyword == "property")
        {
            if (header.elements.empty())
                throw InvalidInputError(where + "property before any element");
            Property p;
            if (!tokens.next(a))
                throw InvalidInputError(where + "bad property line");
            if (a == "list")
            {
                p.is_list = true;
                if (!tokens.next(b) || !tokens.next(c) || !tokens.next(d) || !parse_type(b, p.count_type) ||
                    !parse_type(c, p.type) || p.count_type.kind == Kind::floating)
                    throw InvalidInputError(where + "bad list property");
                p.name = std::string(d);
            }
            else
            {
                if (!tokens.next(b) || !parse_type(a, p.type))
                    throw InvalidInputError(where + "bad property line");
                p.name = std::string(b);
            }
            header.elements.back().properties.push_back(std::move(p));
        }
        else
            throw InvalidInputError(where + "unknown header line " + quote_token(keyword));
    }
    if (!have_format)
        throw InvalidInputError("no 'format' line in the header");
    return header;
}

// Values of the body, one at a time, from either encoding.
class BodyReader
{
public:
    BodyReader(std::span<const uint8_t> body, Encoding encoding) : body_(body), encoding_(encoding), lines_(body) {}

    double value(const Type& type) { return encoding_ == Encoding::ascii ? ascii_value() : binary_value(type); }

    bool is_ascii() const { return encoding_ == Encoding::ascii; }
    size_t remaining_bytes() const { return is_ascii() ? body_.size() : body_.size() - pos_; }
    //! Where the reader is, for messages.
    std::string where() const { return is_ascii() ? at_line(lines_.line_number()) : ""; }

private:
    double binary_value(const Type& type)
    {
        if (body_.size() - pos_ < static_cast<size_t>(type.size))
            throw InvalidInputError("file ends inside the data");
        const uint8_t* p = body_.data() + pos_;
        pos_ += static_cast<size_t>(type.size);
        const bool big = encoding_ == Encoding::big_endian;
        if (type.kind == Kind::floating)
            return type.size == 4 ? static_cast<double>(load_f32(p, big)) : load_f64(p, big);
        const uint64_t u = load_uint(p, type.size, big);
        if (type.kind == Kind::unsigned_int)
            return static_cast<double>(u);
        const int shift = 64 - 8 * type.size; // sign-extend
        return static_cast<double>(static_cast<int64_t>(u << shift) >> shift);
    }

    double ascii_value()
    {
        std::string_view token;
        while (!tokens_.next(token))
        {
            std::string_view line;
            if (!lines_.next(line))
                throw InvalidInputError("file ends inside the data");
            tokens_ = TokenSplitter(line);
        }
        double v = 0;
        if (!parse_double(token, v))
            throw InvalidInputError(at_line(lines_.line_number()) + "bad number " + quote_token(token));
        return v;
    }

    std::span<const uint8_t> body_;
    Encoding encoding_;
    size_t pos_ = 0;
    LineScanner lines_;
    TokenSplitter tokens_{std::string_view()};
};

// The smallest number of bytes one instance of `e` can take, for the size check.
unsigned long long min_element_bytes(const Element& e, Encoding encoding)
{
    unsigned long long bytes = 0;
    for (const Property& p : e.properties)
        // An ASCII value is at least one character and a separator.
        bytes += encoding == Encoding::ascii
                     ? 2
                     : static_cast<unsigned long long>(p.is_list ? p.count_type.size : p.type.size);
    return bytes;
}

std::string number_text(double v)
{
    if (std::isfinite(v) && v == std::floor(v) && std::abs(v) < 1e18)
        return std::to_string(static_cast<long long>(v));
    return std::to_string(v);
}

int find_property(const Element& e, std::string_view name)
{
    for (size_t i = 0; i < e.properties.size(); ++i)
        if (e.properties[i].name == name)
            return static_cast<int>(i);
    return -1;
}

} // namespace

PolygonSoup read_ply(std::span<const uint8_t> bytes)
{
    if (bytes.empty())
        throw InvalidInputError("file is empty");
    const Header header = parse_header(bytes);
    const std::span<const uint8_t> body = bytes.subspan(header.body_offset);

    // Every element's claimed count against the body's size, before any allocation.
    unsigned long long budget = body.size() + 1; // +1: the last ASCII value needs no separator
    const Element* vertex = nullptr;
    const Element* face = nullptr;
    for (const Element& e : header.elements)
    {
        const unsigned long long per = min_element_bytes(e, header.encoding);
        if (e.count > 0 && per == 0)
            throw InvalidInputError("element '" + e.name + "' has no properties");
        if (e.count > 0 && e.count > budget / per)
            throw InvalidInputError("header says " + std::to_string(e.count) + " " + e.name +
                                    " elements, but the file has only " + std::to_string(body.size()) +
                                    " bytes of data");
        budget -= e.count * per;
        if (e.name == "vertex")
            vertex = &e;
        else if (e.name == "face")
            face = &e;
    }
    if (!vertex)
        throw InvalidInputError("no 'vertex' element");
    static const char* const axis_names[3] = {"x", "y", "z"};
    int axis_property[3];
    for (int a = 0; a < 3; ++a)
    {
        axis_property[a] = find_property(*vertex, axis_names[a]);
        if (axis_property[a] < 0 || vertex->properties[static_cast<size_t>(axis_property[a])].is_list)
            throw InvalidInputError(std::string("vertex element has no '") + axis_names[a] + "' property");
    }
    int index_property = -1;
    if (face)
    {
        index_property = find_property(*face, "vertex_indices");
        if (index_property < 0)
            index_property = find_property(*face, "vertex_index");
        if (index_property < 0 || !face->properties[static_cast<size_t>(index_property)].is_list)
            throw InvalidInputError("face element has no 'vertex_indices' list");
    }
    if (!face || face->count == 0)
        throw InvalidInputError("no faces (a point cloud?)");

    PolygonSoup soup;
    soup.positions.reserve(static_cast<size_t>(vertex->count));
    soup.polygons.reserve(static_cast<size_t>(face->count));
    BodyReader reader(body, header.encoding);
    for (const Element& e : header.elements)
    {
        const bool is_vertex = &e == vertex;
        const bool is_face = &e == face;
        for (unsigned long long i = 0; i < e.count; ++i)
        {
            Vec3 p = Vec3::Zero();
            std::vector<uint32_t> polygon;
            for (size_t k = 0; k < e.properties.size(); ++k)
            {
                const Property& prop = e.properties[k];
                if (!prop.is_list)
                {
                    const double v = reader.value(prop.type);
                    for (int a = 0; a < 3 && is_vertex; ++a)
                        if (static_cast<int>(k) == axis_property[a])
                        {
                            if (!std::isfinite(v))
                                throw InvalidInputError(reader.where() + "vertex " + std::to_string(i) +
                                                        " has a NaN or infinite coordinate");
                            p[a] = v;
                        }
                    continue;
                }
                const double n = reader.value(prop.count_type);
                const std::string what = reader.where() + e.name + " " + std::to_string(i);
                // A list cannot hold more values than there are bytes left (ASCII: 2 per value).
                const double limit =
                    static_cast<double>(reader.remaining_bytes()) / (reader.is_ascii() ? 1 : prop.type.size);
                if (!(n >= 0) || n > limit)
                    throw InvalidInputError(what + ": list length " + number_text(n) + " does not fit in the file");
                const bool keep = is_face && static_cast<int>(k) == index_property;
                if (keep)
                    polygon.reserve(static_cast<size_t>(n));
                for (double c = 0; c < n; ++c)
                {
                    const double index = reader.value(prop.type);
                    if (!keep)
                        continue;
                    if (!(index >= 0) || index != std::floor(index) || index >= static_cast<double>(vertex->count))
                        throw InvalidInputError(what + ": index " + number_text(index) + " is out of range (" +
                                                std::to_string(vertex->count) + " vertices)");
                    polygon.push_back(static_cast<uint32_t>(index));
                }
            }
            if (is_vertex)
                soup.positions.push_back(p);
            else if (is_face)
                soup.polygons.push_back(std::move(polygon));
        }
    }
    return soup;
}

} // namespace zomeify::detail
