#include "core/io/share_link.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <functional>
#include <unordered_map>

#include "core/base/errors.h"
#include "core/io/byte_codec.h"
#include "core/io/model_check.h"
#include "core/io/share_link_faces.h"
#include "core/zome/slots.h"

namespace zomeify {

namespace {

constexpr uint8_t kFlagTransform = 1, kFlagFaces = 2, kFlagFaceExceptions = 4;
constexpr uint8_t kNibbleEscape = 15;

[[noreturn]] void fail(const std::string& what) { throw InvalidInputError("this share link is damaged: " + what); }

struct Neighbour
{
    uint32_t node;
    uint32_t strut;
};

bool is_identity(const ModelTransform& t) { return t == ModelTransform{}; }

// The struts as a traversal from one root per component: nodes in discovery order, and for each
// node the struts it introduces, sorted by vector id.
struct Traversal
{
    std::vector<ZVec> roots;
    std::vector<uint64_t> counts; // per node in discovery order
    std::vector<uint8_t> ids;     // vector id of every strut
    std::vector<uint32_t> new_index;
    std::vector<ZVec> nodes;                     // positions in discovery order
    std::vector<std::array<uint32_t, 2>> struts; // in the new numbering, in link order
};

Traversal traverse(const ZomeModel& m)
{
    const size_t n = m.nodes.size();
    std::vector<std::vector<Neighbour>> adj(n);
    for (uint32_t s = 0; s < m.struts.size(); ++s)
    {
        adj[m.struts[s][0]].push_back({m.struts[s][1], s});
        adj[m.struts[s][1]].push_back({m.struts[s][0], s});
    }
    constexpr uint32_t kNone = UINT32_MAX;
    Traversal t;
    t.new_index.assign(n, kNone);
    std::vector<uint32_t> order;
    order.reserve(n);
    std::vector<bool> strut_done(m.struts.size(), false);
    uint32_t next_root = 0;
    for (size_t k = 0; k < n; ++k)
    {
        if (k == order.size())
        {
            // A new component: its lowest-numbered undiscovered node is the root.
            while (t.new_index[next_root] != kNone)
                ++next_root;
            t.new_index[next_root] = static_cast<uint32_t>(order.size());
            order.push_back(next_root);
            t.roots.push_back(m.nodes[next_root]);
        }
        const uint32_t node = order[k];
        std::vector<std::pair<int, Neighbour>> fresh;
        for (const Neighbour& nbr : adj[node])
            if (!strut_done[nbr.strut])
                fresh.push_back({vector_id_of(m.nodes[nbr.node] - m.nodes[node]), nbr});
        std::sort(fresh.begin(), fresh.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        t.counts.push_back(fresh.size());
        for (const auto& [id, nbr] : fresh)
        {
            t.ids.push_back(static_cast<uint8_t>(id));
            strut_done[nbr.strut] = true;
            if (t.new_index[nbr.node] == kNone)
            {
                t.new_index[nbr.node] = static_cast<uint32_t>(order.size());
                order.push_back(nbr.node);
            }
            t.struts.push_back({static_cast<uint32_t>(k), t.new_index[nbr.node]});
        }
    }
    for (uint32_t old : order)
        t.nodes.push_back(m.nodes[old]);
    return t;
}

// Decodes the strut traversal given the counts and ids (both versions), checking everything.
void rebuild_struts(ZomeModel& m, uint64_t n, uint64_t s, const std::function<ZVec()>& next_root,
                    const std::function<uint64_t(uint64_t)>& count_of, const std::function<uint8_t()>& next_id)
{
    m.nodes.reserve(n);
    m.struts.reserve(s);
    std::unordered_map<ZVec, uint32_t, ZVecHash> index_of;
    index_of.reserve(n);
    try
    {
        for (uint64_t k = 0; k < n; ++k)
        {
            if (k == m.nodes.size())
            {
                const ZVec root = next_root();
                if (!index_of.emplace(root, static_cast<uint32_t>(k)).second)
                    fail("two nodes at one position");
                m.nodes.push_back(root);
            }
            const uint64_t count = count_of(k);
            if (count > kSlotCount)
                fail("node " + std::to_string(k) + " claims " + std::to_string(count) + " struts");
            for (uint64_t i = 0; i < count; ++i)
            {
                const uint8_t id = next_id();
                if (id >= kVectorCount)
                    fail("strut vector " + std::to_string(id) + " is not a Zome vector");
                if (m.struts.size() >= s)
                    fail("more struts than announced");
                const ZVec target = m.nodes[k] + zome_vector(id);
                auto [it, inserted] = index_of.emplace(target, static_cast<uint32_t>(m.nodes.size()));
                if (inserted)
                {
                    if (m.nodes.size() >= n)
                        fail("more nodes than announced");
                    m.nodes.push_back(target);
                }
                m.struts.push_back({static_cast<uint32_t>(k), it->second});
            }
        }
    }
    catch (const OverflowError&)
    {
        fail("positions overflow");
    }
    if (m.nodes.size() != n || m.struts.size() != s)
        fail("the node or strut count does not match the data");
}

ZVec read_root(ByteReader& r)
{
    ZVec root;
    for (int32_t& c : root.c)
    {
        const int64_t v = r.zigzag("a root position");
        if (v < INT32_MIN / 4 || v > INT32_MAX / 4)
            fail("a root position is out of range");
        c = static_cast<int32_t>(v);
    }
    return root;
}

void write_transform(ByteWriter& w, const ModelTransform& t)
{
    w.f64(t.scale);
    for (double x : t.translation)
        w.f64(x);
}

void read_transform(ByteReader& r, ModelTransform& t)
{
    t.scale = r.f64("the transform");
    for (double& x : t.translation)
        x = r.f64("the transform");
    if (!(t.scale > 0) || !std::isfinite(t.scale))
        fail("the scale is not a positive number");
    for (double x : t.translation)
        if (!std::isfinite(x))
            fail("the translation is not finite");
}

// Version 1: counts and ids interleaved, a root where a component starts, explicit faces.
ZomeModel decode_v1(ByteReader& r)
{
    const uint8_t flags = r.u8("the flags");
    if (flags & ~(kFlagTransform | kFlagFaces))
        fail("unknown flags");
    const uint64_t n = r.varint("the node count"), s = r.varint("the strut count");
    // Each node takes at least one byte (its strut count), each strut one byte (its vector).
    if (n > kMaxModelNodes || n > r.left())
        fail("the node count " + std::to_string(n) + " is larger than the link holds");
    if (s > kMaxModelStruts || s > r.left())
        fail("the strut count " + std::to_string(s) + " is larger than the link holds");
    ZomeModel m;
    rebuild_struts(
        m, n, s, [&] { return read_root(r); },
        [&](uint64_t k) {
            const uint64_t count = r.varint("a strut count");
            if (count > r.left())
                fail("node " + std::to_string(k) + " claims " + std::to_string(count) + " struts");
            return count;
        },
        [&] { return r.u8("a strut"); });
    if (flags & kFlagFaces)
        m.faces = read_explicit_faces(r, m.nodes.size(), m.struts);
    if (flags & kFlagTransform)
        read_transform(r, m.transform);
    return m;
}

// Version 2: roots first, strut counts as nibbles (15: the count is 15 + a varint that follows
// the nibbles), vector ids, then faces explicit or as rotation exceptions.
ZomeModel decode_v2(ByteReader& r)
{
    const uint8_t flags = r.u8("the flags");
    if ((flags & ~(kFlagTransform | kFlagFaces | kFlagFaceExceptions)) ||
        ((flags & kFlagFaces) && (flags & kFlagFaceExceptions)))
        fail("unknown flags");
    const uint64_t n = r.varint("the node count"), s = r.varint("the strut count");
    if (n > kMaxModelNodes || n > 2 * r.left())
        fail("the node count " + std::to_string(n) + " is larger than the link holds");
    if (s > kMaxModelStruts || s > r.left())
        fail("the strut count " + std::to_string(s) + " is larger than the link holds");
    const uint64_t components = r.varint("the component count");
    if (components > n || (n > 0 && components == 0) || components * 6 > r.left())
        fail("the component count " + std::to_string(components) + " does not fit");
    std::vector<ZVec> roots;
    for (uint64_t c = 0; c < components; ++c)
        roots.push_back(read_root(r));
    std::vector<uint64_t> counts(n);
    for (uint64_t k = 0; k < n; k += 2)
    {
        const uint8_t b = r.u8("the strut counts");
        counts[k] = b & 15;
        if (k + 1 < n)
            counts[k + 1] = b >> 4;
        else if (b >> 4)
            fail("the strut counts end badly");
    }
    for (uint64_t& c : counts)
        if (c == kNibbleEscape)
        {
            const uint64_t extra = r.varint("a strut count");
            if (extra > kSlotCount)
                fail("a strut count is out of range");
            c += extra;
        }
    size_t next_root = 0;
    ZomeModel m;
    rebuild_struts(
        m, n, s,
        [&] {
            if (next_root >= roots.size())
                fail("more components than announced");
            return roots[next_root++];
        },
        [&](uint64_t k) { return counts[k]; }, [&] { return r.u8("a strut"); });
    if (next_root != roots.size())
        fail("fewer components than announced");
    if (flags & (kFlagFaces | kFlagFaceExceptions))
    {
        // The struts must be a valid model before their geometry orders anything.
        try
        {
            check_model(m);
        }
        catch (const InvalidInputError& e)
        {
            fail(e.what());
        }
        m.faces = (flags & kFlagFaces) ? read_explicit_faces(r, m.nodes.size(), m.struts)
                                       : read_face_exceptions(r, m.nodes, m.struts);
    }
    if (flags & kFlagTransform)
        read_transform(r, m.transform);
    return m;
}

} // namespace

std::string encode_share_link(const ZomeModel& m)
{
    check_model(m);
    const Traversal t = traverse(m);
    ByteWriter faces;
    uint8_t flags = is_identity(m.transform) ? 0 : kFlagTransform;
    if (!m.faces.empty())
    {
        FaceList renumbered;
        for (const auto& f : m.faces)
        {
            std::vector<uint32_t> g;
            for (uint32_t v : f)
                g.push_back(t.new_index[v]);
            renumbered.push_back(std::move(g));
        }
        if (write_face_exceptions(faces, t.nodes, t.struts, renumbered))
            flags |= kFlagFaceExceptions;
        else
        {
            faces = ByteWriter{};
            write_explicit_faces(faces, t.nodes.size(), t.struts, renumbered);
            flags |= kFlagFaces;
        }
    }
    ByteWriter w;
    w.u8(flags);
    w.varint(m.nodes.size());
    w.varint(m.struts.size());
    w.varint(t.roots.size());
    for (const ZVec& root : t.roots)
        for (int32_t c : root.c)
            w.zigzag(c);
    for (size_t k = 0; k < t.counts.size(); k += 2)
    {
        auto nibble = [&](size_t i) {
            return i < t.counts.size() ? std::min<uint64_t>(t.counts[i], kNibbleEscape) : 0;
        };
        w.u8(static_cast<uint8_t>(nibble(k) | nibble(k + 1) << 4));
    }
    for (uint64_t c : t.counts)
        if (c >= kNibbleEscape)
            w.varint(c - kNibbleEscape);
    for (uint8_t id : t.ids)
        w.u8(id);
    for (uint8_t b : faces.bytes())
        w.u8(b);
    if (flags & kFlagTransform)
        write_transform(w, m.transform);
    return "m=" + std::to_string(kShareLinkVersion) + "." + base64url_encode(w.bytes());
}

ZomeModel decode_share_link(std::string_view link)
{
    if (link.size() > kMaxShareLinkChars)
        fail("it is longer than 16 MiB");
    if (const size_t hash = link.rfind('#'); hash != std::string_view::npos)
        link = link.substr(hash + 1);
    // The m= parameter among &-separated ones.
    size_t start = std::string_view::npos;
    for (size_t pos = 0; pos <= link.size();)
    {
        const size_t amp = std::min(link.find('&', pos), link.size());
        if (link.substr(pos, 2) == "m=")
            start = pos + 2;
        pos = amp + 1;
    }
    if (start == std::string_view::npos)
        throw InvalidInputError("this is not a zomeify share link (no m= part)");
    std::string_view body = link.substr(start, std::min(link.find('&', start), link.size()) - start);
    const size_t dot = body.find('.');
    if (dot == std::string_view::npos || dot == 0 || dot > 6)
        fail("no version number");
    int version = 0;
    for (char c : body.substr(0, dot))
    {
        if (c < '0' || c > '9')
            fail("the version is not a number");
        version = version * 10 + (c - '0');
    }
    if (version < 1 || version > kShareLinkVersion)
        throw InvalidInputError("this share link has version " + std::to_string(version) +
                                "; this zomeify reads versions 1 to " + std::to_string(kShareLinkVersion));

    const std::vector<uint8_t> bytes = base64url_decode(body.substr(dot + 1));
    ByteReader r(bytes);
    ZomeModel m = version == 1 ? decode_v1(r) : decode_v2(r);
    if (!r.done())
        fail("unexpected data at the end");
    try
    {
        check_model(m);
    }
    catch (const InvalidInputError& e)
    {
        fail(e.what());
    }
    return m;
}

} // namespace zomeify
