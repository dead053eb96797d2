#include "core/io/vef.h"

#include <algorithm>
#include <charconv>
#include <limits>
#include <sstream>

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
};

VefPreamble read_preamble(Tokens& t)
{
    VefPreamble p;
    if (t.peek() == "field")
    {
        t.next("field");
        const std::string_view field = t.next("the field name");
        if (!golden_compatible(field))
            fail("field '" + std::string(field.substr(0, 40)) +
                 "' is not the golden field Zometool uses (golden, polygon5, snubDodecahedron or rational)");
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
            p.scale.assign(p.dimension, parse_vef_number(t.next("the scale"), p.rational_only, "scale"));
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

} // namespace

ZomeModel read_vef(std::string_view text, VefReadInfo* info)
{
    Tokens t(text);
    if (t.done())
        fail("the file is empty");
    if (t.next("header") != "vZome" || t.next("header") != "VEF")
        fail("it does not start with 'vZome VEF'");
    const int64_t version = parse_int(t.next("version"), "version");
    ZomeModel model;
    std::vector<std::array<GoldenFraction, 3>> raw;
    try
    {
        const VefPreamble pre = read_preamble(t);
        // Raw exact coordinates first; the scale is decided once the struts are known.
        const size_t nv = parse_count(t, "vertex", pre.dimension, kMaxModelNodes);
        raw.resize(nv);
        const size_t first = pre.dimension - 3; // 4D: W X Y Z, W dropped as vZome projects
        for (size_t i = 0; i < nv; ++i)
        {
            const std::string where = "vertex " + std::to_string(i);
            for (size_t k = 0; k < pre.dimension; ++k)
            {
                const GoldenFraction x = parse_vef_number(t.next("a vertex"), pre.rational_only, where);
                if (k >= first)
                    raw[i][k - first] = x * pre.scale[k] + pre.offset[k];
            }
        }
    }
    catch (const OverflowError&)
    {
        fail("coordinates are too large");
    }
    const size_t nv = raw.size();
    const size_t ne = parse_count(t, "edge", 2, kMaxModelStruts);
    model.struts.resize(ne);
    for (size_t e = 0; e < ne; ++e)
        for (int k = 0; k < 2; ++k)
        {
            const int64_t v = parse_int(t.next("an edge"), "edge " + std::to_string(e));
            if (v < 0 || static_cast<uint64_t>(v) >= nv)
                fail("edge " + std::to_string(e) + " refers to vertex " + std::to_string(v) + " of " +
                     std::to_string(nv));
            model.struts[e][static_cast<size_t>(k)] = static_cast<uint32_t>(v);
        }
    if (!t.done())
    {
        const size_t nf = parse_count(t, "face", 1, kMaxModelFaces);
        model.faces.resize(nf);
        for (size_t f = 0; f < nf; ++f)
        {
            const int64_t k = parse_int(t.next("a face"), "face " + std::to_string(f));
            if (k < 3 || static_cast<size_t>(k) > kMaxFaceSize || static_cast<size_t>(k) > t.left())
                fail("face " + std::to_string(f) + " has a bad corner count " + std::to_string(k));
            for (int64_t c = 0; c < k; ++c)
            {
                const int64_t v = parse_int(t.next("a face"), "face " + std::to_string(f));
                if (v < 0 || static_cast<uint64_t>(v) >= nv)
                    fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(v));
                model.faces[f].push_back(static_cast<uint32_t>(v));
            }
        }
    }
    size_t balls = 0;
    if (!t.done())
    {
        balls = parse_count(t, "ball", 1, kMaxModelNodes);
        for (size_t b = 0; b < balls; ++b)
        {
            const int64_t v = parse_int(t.next("a ball"), "ball " + std::to_string(b));
            if (v < 0 || static_cast<uint64_t>(v) >= nv)
                fail("ball " + std::to_string(b) + " refers to vertex " + std::to_string(v));
        }
    }
    if (!t.done())
        fail("unexpected text after the ball list: '" + std::string(t.peek().substr(0, 40)) + "'");

    // Scale: the φ-power at which every strut is a Zome vector, vZome's own (m = 2) first.
    static constexpr int kPowers[] = {2, 3, 1, 4, 0, 5, -1, 6, -2, 7, -3, 8};
    int chosen = -1000;
    bool moved = false;
    long first_bad = 0;
    for (int m : kPowers)
    {
        try
        {
            const long bad = place_at(m, raw, model, moved);
            if (bad < 0)
            {
                chosen = m;
                break;
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
    if (chosen == -1000)
    {
        const auto& s = model.struts[static_cast<size_t>(first_bad)];
        fail("edge " + std::to_string(first_bad) + " (vertices " + std::to_string(s[0]) + "-" + std::to_string(s[1]) +
             ") is not a Zome strut at any scale");
    }
    check_model(model);
    if (info)
        *info = VefReadInfo{chosen, static_cast<int>(std::clamp<int64_t>(version, 0, 1'000'000)), balls, moved};
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
