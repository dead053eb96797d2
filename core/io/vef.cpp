#include "core/io/vef.h"

#include <algorithm>
#include <charconv>
#include <limits>
#include <sstream>

#include "core/base/errors.h"
#include "core/io/file_bytes.h"
#include "core/io/model_check.h"
#include "core/zome/slots.h"

namespace zomeify {

namespace {

[[noreturn]] void fail(const std::string& what)
{
    throw InvalidInputError("not a valid VEF file: " + what);
}

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
        fail(std::string(what) + " count " + std::to_string(n) + " is larger than the file holds (is the file truncated?)");
    return static_cast<size_t>(n);
}

// "(a,b)" = a·φ + b, or a plain integer b. Integer coefficients only.
QPhi parse_golden(std::string_view s, const std::string& what)
{
    if (s.size() >= 2 && s.front() == '(' && s.back() == ')')
    {
        const std::string_view inner = s.substr(1, s.size() - 2);
        const size_t comma = inner.find(',');
        if (comma == std::string_view::npos || inner.find(',', comma + 1) != std::string_view::npos)
            fail(what + ": '" + std::string(s.substr(0, 40)) + "' is not a golden number (a,b)");
        const std::string_view a = inner.substr(0, comma), b = inner.substr(comma + 1);
        if (a.find('/') != std::string_view::npos || b.find('/') != std::string_view::npos)
            fail(what + ": fractional coordinates are not supported");
        return QPhi{parse_int(b, what), parse_int(a, what)};
    }
    return QPhi{parse_int(s, what), 0};
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
    if (t.peek() == "field")
    {
        t.next("field");
        const std::string_view field = t.next("field name");
        if (field != "golden")
            fail("field '" + std::string(field) + "' is not supported (Zometool models use 'golden')");
    }

    // Raw exact coordinates (Z[φ]) first; the scale is decided once the struts are known.
    const size_t nv = parse_count(t, "vertex", 4, kMaxModelNodes);
    std::vector<std::array<QPhi, 3>> raw(nv);
    for (size_t i = 0; i < nv; ++i)
    {
        const std::string where = "vertex " + std::to_string(i);
        parse_golden(t.next("a vertex"), where); // W, unused
        for (int k = 0; k < 3; ++k)
            raw[i][static_cast<size_t>(k)] = parse_golden(t.next("a vertex"), where);
    }
    ZomeModel model;
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

    // Scale: twice our coordinate = raw · φ^(−m) for a file drawn at 2φ^m raw units per b0.
    auto scaled = [&](int m) {
        const QPhi f = phi_power(-m);
        std::vector<ZVec> nodes(nv);
        for (size_t i = 0; i < nv; ++i)
            nodes[i] = ZVec::from_twice(raw[i][0] * f, raw[i][1] * f, raw[i][2] * f);
        return nodes;
    };
    auto bad_strut = [&](const std::vector<ZVec>& nodes) -> long {
        for (size_t e = 0; e < ne; ++e)
            if (vector_id_of(nodes[model.struts[e][1]] - nodes[model.struts[e][0]]) < 0)
                return static_cast<long>(e);
        return -1;
    };
    static constexpr int kPowers[] = {2, 3, 1, 4, 0, 5, -1, 6, -2, 7, -3, 8};
    long first_bad = -1;
    int chosen = -1000;
    try
    {
        for (int m : kPowers)
        {
            std::vector<ZVec> nodes = scaled(m);
            const long bad = bad_strut(nodes);
            if (bad < 0)
            {
                model.nodes = std::move(nodes);
                chosen = m;
                break;
            }
            if (m == 2)
                first_bad = bad;
        }
    }
    catch (const OverflowError&)
    {
        fail("coordinates are too large");
    }
    if (chosen == -1000)
    {
        const auto& s = model.struts[static_cast<size_t>(first_bad)];
        fail("edge " + std::to_string(first_bad) + " (vertices " + std::to_string(s[0]) + "-" + std::to_string(s[1]) +
             ") is not a Zome strut at any scale");
    }
    check_model(model);
    if (info)
        *info = VefReadInfo{chosen, static_cast<int>(std::clamp<int64_t>(version, 0, 1'000'000)), balls};
    return model;
}

ZomeModel read_vef_file(const std::string& path, VefReadInfo* info)
{
    return read_vef(read_file_bytes(path), info);
}

std::string write_vef(const ZomeModel& model)
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
    out << "\n" << model.faces.size() << "\n";
    for (const auto& f : model.faces)
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
