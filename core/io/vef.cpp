#include "core/io/vef.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "core/base/errors.h"
#include "core/io/file_bytes.h"
#include "core/io/model_check.h"
#include "core/io/vef_number.h"
#include "core/zome/slots.h"

namespace zomeify {

namespace {

[[noreturn]] void fail(const std::string& what) { throw InvalidInputError("not a valid VEF file: " + what); }

// Whitespace tokenizer over the whole text, counting tokens left for size checks.
class Tokens
{
public:
    explicit Tokens(std::string_view text)
    {
        size_t i = 0;
        while (i < text.size())
        {
            while (i < text.size() && is_space(text[i]))
                ++i;
            const size_t start = i;
            while (i < text.size() && !is_space(text[i]))
                ++i;
            if (i > start)
                tokens_.push_back(text.substr(start, i - start));
        }
    }
    bool done() const { return pos_ >= tokens_.size(); }
    size_t left() const { return tokens_.size() - pos_; }
    std::string_view next(const char* what)
    {
        if (done())
            fail("the file ends early, while reading " + std::string(what));
        return tokens_[pos_++];
    }
    std::string_view peek() const { return done() ? std::string_view() : tokens_[pos_]; }

private:
    static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
    std::vector<std::string_view> tokens_;
    size_t pos_ = 0;
};

int64_t parse_int(std::string_view s, const std::string& what)
{
    int64_t x = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), x);
    if (ec != std::errc() || end != s.data() + s.size())
        fail(what + ": '" + std::string(s.substr(0, 40)) + "' is not an integer");
    return x;
}

// A count that must fit in the tokens left (each item takes at least `tokens_per_item`).
size_t parse_count(Tokens& t, const char* what, size_t tokens_per_item, size_t limit)
{
    const int64_t n = parse_int(t.next(what), std::string(what) + " count");
    if (n < 0)
        fail(std::string(what) + " count is negative");
    if (static_cast<uint64_t>(n) > limit)
        fail(std::string(what) + " count " + std::to_string(n) + " is larger than the limit " + std::to_string(limit));
    if (static_cast<uint64_t>(n) * tokens_per_item > t.left())
        fail(std::string(what) + " count " + std::to_string(n) +
             " is larger than the file holds (is the file truncated?)");
    return static_cast<size_t>(n);
}

// Field names whose numbers read as golden ones: the golden field under its names, fields whose
// first two irrationals are 1 and φ (their other factors must be zero), and "rational".
bool golden_compatible(std::string_view field)
{
    return field == "golden" || field == "polygon5" || field == "snubDodecahedron" || field == "snubDodec" ||
           field == "rational";
}

// What comes between the header and the vertex count (vZome's order): field, actual,
// dimension, scale, offset.
struct VefPreamble
{
    bool rational_only = false;
    size_t dimension = 4;
    std::vector<GoldenFraction> scale;  // one per dimension
    std::vector<GoldenFraction> offset; // one per dimension
    bool uniform_scale = false;         // `scale s`: one factor for every coordinate
};

VefPreamble read_preamble(Tokens& t)
{
    VefPreamble p;
    if (t.peek() == "field")
    {
        t.next("field");
        const std::string_view field = t.next("the field name");
        if (!golden_compatible(field))
            fail("it is made in vZome's '" + std::string(field.substr(0, 40)) +
                 "' field; Zometool models are made in the golden field (files of the golden, polygon5, "
                 "snubDodecahedron or rational field are read)");
        p.rational_only = field == "rational";
    }
    if (t.peek() == "actual")
        t.next("actual"); // vZome ignores it now: the scale is the user's
    if (t.peek() == "dimension")
    {
        t.next("dimension");
        const int64_t d = parse_int(t.next("the dimension"), "dimension");
        if (d != 3 && d != 4)
            fail("dimension " + std::to_string(d) + " is not supported (3 or 4)");
        p.dimension = static_cast<size_t>(d);
    }
    p.scale.assign(p.dimension, GoldenFraction{QPhi{1, 0}, 1});
    if (t.peek() == "scale")
    {
        t.next("scale");
        if (t.peek() == "vector")
        {
            t.next("vector");
            for (auto& s : p.scale)
                s = parse_vef_number(t.next("the scale vector"), p.rational_only, "scale");
        }
        else
        {
            p.scale.assign(p.dimension, parse_vef_number(t.next("the scale"), p.rational_only, "scale"));
            p.uniform_scale = true;
        }
    }
    p.offset.assign(p.dimension, GoldenFraction{});
    if (t.peek() == "offset")
    {
        t.next("offset");
        for (auto& o : p.offset)
            o = parse_vef_number(t.next("the offset"), p.rational_only, "offset");
    }
    return p;
}

// Exact positions at `phi_power` m: twice our coordinate = raw · φ^(−m). Returns false if some
// strut is then no Zome vector. Positions off the lattice (a fractional offset) are moved by
// the first vertex's position when the struts allow it. Returns the first bad strut, or −1.
long place_at(int m, const std::vector<std::array<GoldenFraction, 3>>& raw, ZomeModel& model, bool& moved)
{
    const GoldenFraction f{phi_power(-m), 1};
    std::vector<std::array<GoldenFraction, 3>> t(raw.size());
    bool integral = true;
    for (size_t i = 0; i < raw.size(); ++i)
        for (size_t k = 0; k < 3; ++k)
        {
            t[i][k] = raw[i][k] * f;
            integral = integral && t[i][k].is_integral();
        }
    auto zvec = [](const std::array<GoldenFraction, 3>& x) { return ZVec::from_twice(x[0].n, x[1].n, x[2].n); };
    for (size_t e = 0; e < model.struts.size(); ++e)
    {
        const auto& s = model.struts[e];
        std::array<GoldenFraction, 3> d;
        bool whole = true;
        for (size_t k = 0; k < 3; ++k)
        {
            d[k] = t[s[1]][k] - t[s[0]][k];
            whole = whole && d[k].is_integral();
        }
        if (!whole || vector_id_of(zvec(d)) < 0)
            return static_cast<long>(e);
    }
    moved = !integral;
    model.nodes.resize(raw.size());
    for (size_t i = 0; i < raw.size(); ++i)
    {
        std::array<GoldenFraction, 3> x = t[i];
        if (moved)
            for (size_t k = 0; k < 3; ++k)
            {
                x[k] = x[k] - t[0][k];
                if (!x[k].is_integral())
                    fail("vertex " + std::to_string(i) + " is not on the Zome lattice of vertex 0");
            }
        model.nodes[i] = zvec(x);
    }
    return -1;
}

using Vec3d = std::array<double, 3>;

constexpr int64_t kVefVersionExplicitBalls = 6; // vZome's VERSION_EXPLICIT_BALLS

using RawPoints = std::vector<std::array<GoldenFraction, 3>>;

uint32_t vertex_index(Tokens& t, const std::string& where, size_t nv)
{
    const int64_t v = parse_int(t.next("a vertex index"), where);
    if (v < 0 || static_cast<uint64_t>(v) >= nv)
        fail(where + " refers to vertex " + std::to_string(v) + " of " + std::to_string(nv));
    return static_cast<uint32_t>(v);
}

// The parts: a vertex with a ball or a strut end is a node (in file order); faces on a vertex that
// is neither go. Returns the file's vertex index of every node.
std::vector<uint32_t> keep_parts(size_t nv, const std::vector<std::array<uint32_t, 2>>& struts,
                                 const std::vector<std::vector<uint32_t>>& faces, const std::vector<char>& ball,
                                 ZomeModel& model, VefReadInfo& read)
{
    std::vector<char> end(nv, 0);
    for (const auto& s : struts)
        end[s[0]] = end[s[1]] = 1;
    std::vector<long> node(nv, -1);
    std::vector<uint32_t> file_vertex;
    for (size_t v = 0; v < nv; ++v)
    {
        read.ends_without_ball += end[v] && !ball[v];
        read.vertices_dropped += !end[v] && !ball[v];
        if (end[v] || ball[v])
        {
            node[v] = static_cast<long>(file_vertex.size());
            file_vertex.push_back(static_cast<uint32_t>(v));
        }
    }
    for (const auto& s : struts)
        model.struts.push_back({static_cast<uint32_t>(node[s[0]]), static_cast<uint32_t>(node[s[1]])});
    size_t faces_dropped = 0;
    for (const auto& f : faces)
    {
        std::vector<uint32_t> kept;
        for (uint32_t v : f)
            if (node[v] >= 0)
                kept.push_back(static_cast<uint32_t>(node[v]));
        if (kept.size() == f.size())
            model.faces.push_back(std::move(kept));
        else
            ++faces_dropped;
    }
    if (read.ends_without_ball > 0)
        read.notes.push_back(std::to_string(read.ends_without_ball) +
                             (read.ends_without_ball == 1 ? " strut end has" : " strut ends have") +
                             " no ball in the file (vZome draws none there); a builder needs one at each, so they "
                             "are counted as balls");
    if (read.vertices_dropped > 0)
        read.notes.push_back(std::to_string(read.vertices_dropped) +
                             (read.vertices_dropped == 1 ? " vertex has" : " vertices have") +
                             " neither a ball nor a strut: no part, left out" +
                             (faces_dropped ? " with the " + std::to_string(faces_dropped) + " faces on them" : ""));
    return file_vertex;
}

RawPoints of_nodes(const RawPoints& points, const std::vector<uint32_t>& file_vertex)
{
    RawPoints out(file_vertex.size());
    for (size_t i = 0; i < file_vertex.size(); ++i)
        out[i] = points[file_vertex[i]];
    return out;
}

// The φ-power at which every strut is a Zome vector, vZome's own (m = 2) first: the nodes placed,
// read.phi_power and read.moved set. Returns −1, or the first strut that is no Zome vector at m = 2.
long choose_scale(const RawPoints& raw, ZomeModel& model, VefReadInfo& read)
{
    static constexpr int kPowers[] = {2, 3, 1, 4, 0, 5, -1, 6, -2, 7, -3, 8};
    long first_bad = 0;
    for (int m : kPowers)
    {
        try
        {
            bool moved = false;
            const long bad = place_at(m, raw, model, moved);
            if (bad < 0)
            {
                read.phi_power = m;
                read.moved = moved;
                return -1;
            }
            if (m == 2)
                first_bad = bad;
        }
        catch (const OverflowError&)
        {
            if (m == 2)
                fail("coordinates are too large");
        }
    }
    return first_bad;
}

// Whether v points along one of Zometool's 60 green directions: the sums of two perpendicular blue
// strut vectors of equal length.
bool is_green_direction(const Vec3d& v)
{
    std::vector<Vec3d> blue;
    for (int slot = 0; slot < kBlueSlots; ++slot)
    {
        const auto c = zome_vector(vector_id(slot, 0)).to_double();
        blue.push_back(Vec3d{c[0], c[1], c[2]});
    }
    const auto dot = [](const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    const double vv = dot(v, v);
    for (size_t i = 0; i < blue.size(); ++i)
        for (size_t j = i + 1; j < blue.size(); ++j)
        {
            if (std::abs(dot(blue[i], blue[j])) > 1e-9 * dot(blue[i], blue[i]))
                continue;
            const Vec3d g{blue[i][0] + blue[j][0], blue[i][1] + blue[j][1], blue[i][2] + blue[j][2]};
            const double c = dot(v, g);
            if (c * c > (1.0 - 1e-12) * vv * dot(g, g))
                return true;
        }
    return false;
}

double to_double(const GoldenFraction& x) { return x.n.to_double() / static_cast<double>(x.d); }

std::string not_zome_message(const ZomeModel& model, long e, const RawPoints& raw,
                             const std::vector<uint32_t>& file_vertex)
{
    const auto& s = model.struts[static_cast<size_t>(e)];
    Vec3d d;
    for (size_t k = 0; k < 3; ++k)
        d[k] = to_double(raw[s[1]][k]) - to_double(raw[s[0]][k]);
    const std::string which = "edge " + std::to_string(e) + " (vertices " + std::to_string(file_vertex[s[0]]) + "-" +
                              std::to_string(file_vertex[s[1]]) + ")";
    if (is_green_direction(d))
        return which + " is a green strut: green struts are not supported yet (blue, yellow and red are)";
    return which + " is not a Zome strut at any scale";
}

} // namespace

ZomeModel read_vef(std::string_view text, VefReadInfo* info)
{
    Tokens t(text);
    if (t.done())
        fail("the file is empty");
    // vZome reads files without the header too (version 0).
    int64_t version = 0;
    if (t.peek() == "vZome")
    {
        t.next("header");
        if (t.next("header") != "VEF")
            fail("'vZome' is not followed by 'VEF'");
        version = parse_int(t.next("version"), "version");
    }
    else
    {
        const std::string_view first = t.peek();
        int64_t count = 0;
        const bool number =
            std::from_chars(first.data(), first.data() + first.size(), count).ptr == first.data() + first.size();
        if (!number && first != "field" && first != "actual" && first != "dimension" && first != "scale" &&
            first != "offset")
            fail("it does not start with 'vZome VEF' (nor as a VEF without its header, with a field, a scale or "
                 "the vertex count)");
    }
    VefReadInfo read;
    read.version = static_cast<int>(std::clamp<int64_t>(version, 0, 1'000'000));
    RawPoints raw, unscaled;
    bool uniform_scale = false;
    try
    {
        const VefPreamble pre = read_preamble(t);
        uniform_scale = pre.uniform_scale && !(pre.scale[0] == GoldenFraction{QPhi{1, 0}, 1});
        // Raw exact coordinates first; the scale is decided once the struts are known.
        const size_t nv = parse_count(t, "vertex", pre.dimension, kMaxModelNodes);
        raw.resize(nv);
        unscaled.resize(nv);
        const size_t first = pre.dimension - 3; // 4D: W X Y Z, W dropped as vZome projects
        for (size_t i = 0; i < nv; ++i)
        {
            const std::string where = "vertex " + std::to_string(i);
            for (size_t k = 0; k < pre.dimension; ++k)
            {
                const GoldenFraction x = parse_vef_number(t.next("a vertex"), pre.rational_only, where);
                if (k >= first)
                {
                    raw[i][k - first] = x * pre.scale[k] + pre.offset[k];
                    unscaled[i][k - first] = x + pre.offset[k];
                }
                else if (!x.n.is_zero())
                    fail("a 4D model (vertex " + std::to_string(i) +
                         " has a W coordinate): vZome shows it projected, zomeify builds 3D Zometool models");
            }
        }
    }
    catch (const OverflowError&)
    {
        fail("coordinates are too large");
    }
    const size_t nv = raw.size();
    std::vector<std::array<uint32_t, 2>> struts;
    std::vector<std::vector<uint32_t>> faces;
    if (!t.done())
    {
        struts.resize(parse_count(t, "edge", 2, kMaxModelStruts));
        for (size_t e = 0; e < struts.size(); ++e)
            for (int k = 0; k < 2; ++k)
                struts[e][static_cast<size_t>(k)] = vertex_index(t, "edge " + std::to_string(e), nv);
    }
    if (!t.done())
    {
        faces.resize(parse_count(t, "face", 1, kMaxModelFaces));
        for (size_t f = 0; f < faces.size(); ++f)
        {
            const int64_t k = parse_int(t.next("a face"), "face " + std::to_string(f));
            if (k < 3 || static_cast<size_t>(k) > kMaxFaceSize || static_cast<size_t>(k) > t.left())
                fail("face " + std::to_string(f) + " has a bad corner count " + std::to_string(k));
            for (int64_t c = 0; c < k; ++c)
                faces[f].push_back(vertex_index(t, "face " + std::to_string(f), nv));
        }
    }
    // Before version 6 there is no ball list and every vertex is a ball (vZome's VefParser).
    std::vector<char> ball(nv, version < kVefVersionExplicitBalls ? 1 : 0);
    if (!t.done())
    {
        std::fill(ball.begin(), ball.end(), 0);
        const size_t balls = parse_count(t, "ball", 1, kMaxModelNodes);
        for (size_t b = 0; b < balls; ++b)
            ball[vertex_index(t, "ball " + std::to_string(b), nv)] = 1;
    }
    // Anything after the ball list is ignored, as vZome does.
    read.balls = static_cast<size_t>(std::count(ball.begin(), ball.end(), 1));
    if (struts.empty() && read.balls == 0)
        fail("it is a shape, not a Zome model: it has no struts and no balls" +
             std::string(faces.empty() ? "" : " (only faces, as vZome's part shapes)"));

    ZomeModel model;
    const std::vector<uint32_t> file_vertex = keep_parts(nv, struts, faces, ball, model, read);
    const RawPoints points = of_nodes(raw, file_vertex);
    const long first_bad = choose_scale(points, model, read);
    if (first_bad >= 0 && uniform_scale)
    {
        // A uniform scale that is no power of φ (`scale 2`): the struts may be Zome struts without it.
        if (choose_scale(of_nodes(unscaled, file_vertex), model, read) >= 0)
            fail(not_zome_message(model, first_bad, points, file_vertex) + " (nor without the file's scale)");
        read.scale_set_aside = true;
        read.notes.push_back("at the file's scale no strut is a Zometool strut, so it was read without it (a "
                             "Zometool model's size is that of its struts)");
    }
    else if (first_bad >= 0)
        fail(not_zome_message(model, first_bad, points, file_vertex));
    check_model(model);
    if (info)
        *info = std::move(read);
    return model;
}

ZomeModel read_vef_file(const std::string& path, VefReadInfo* info) { return read_vef(read_file_bytes(path), info); }

std::string write_vef(const ZomeModel& model, const VefWriteOptions& options)
{
    // vZome's raw scale: raw = (twice our coordinate) · φ².
    const QPhi phi2 = phi_power(2);
    std::ostringstream out;
    auto golden = [&out](QPhi q) { out << ' ' << '(' << q.b << ',' << q.a << ')'; };
    out << "vZome VEF 6 field golden\n\n" << model.nodes.size() << "\n";
    for (const ZVec& p : model.nodes)
    {
        out << "(0,0)";
        for (int k = 0; k < 3; ++k)
            golden(p.twice(k) * phi2);
        out << "\n";
    }
    out << "\n" << model.struts.size() << "\n";
    for (const auto& s : model.struts)
        out << s[0] << " " << s[1] << "\n";
    const size_t faces = options.faces ? model.faces.size() : 0;
    out << "\n" << faces << "\n";
    for (const auto& f : options.faces ? model.faces : std::vector<std::vector<uint32_t>>{})
    {
        out << f.size();
        for (uint32_t v : f)
            out << " " << v;
        out << "\n";
    }
    out << "\n" << model.nodes.size() << "\n";
    for (size_t i = 0; i < model.nodes.size(); ++i)
        out << i << ((i + 1) % 10 == 0 || i + 1 == model.nodes.size() ? "\n" : " ");
    return out.str();
}

} // namespace zomeify
