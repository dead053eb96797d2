#include "core/io/share_link.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <unordered_map>

#include "core/base/errors.h"
#include "core/io/byte_codec.h"
#include "core/io/model_check.h"
#include "core/zome/slots.h"

namespace zomeify {

namespace {

constexpr uint8_t kFlagTransform = 1, kFlagFaces = 2;

[[noreturn]] void fail(const std::string& what)
{
    throw InvalidInputError("this share link is damaged: " + what);
}

struct Neighbour
{
    uint32_t node;
    uint32_t strut;
};

bool is_identity(const ModelTransform& t)
{
    return t == ModelTransform{};
}

// Sorted neighbour lists, the shared reference frame of the face encoding.
std::vector<std::vector<uint32_t>> sorted_neighbours(size_t n, const std::vector<std::array<uint32_t, 2>>& struts)
{
    std::vector<std::vector<uint32_t>> nb(n);
    for (const auto& s : struts)
    {
        nb[s[0]].push_back(s[1]);
        nb[s[1]].push_back(s[0]);
    }
    for (auto& list : nb)
        std::sort(list.begin(), list.end());
    return nb;
}

void encode_faces(ByteWriter& w, const ZomeModel& m, const std::vector<uint32_t>& new_index,
                  const std::vector<std::array<uint32_t, 2>>& new_struts)
{
    const auto nb = sorted_neighbours(m.nodes.size(), new_struts);
    // Faces in the new numbering, each rotated to start at its smallest corner, then sorted.
    std::vector<std::vector<uint32_t>> faces;
    for (const auto& f : m.faces)
    {
        std::vector<uint32_t> g;
        for (uint32_t v : f)
            g.push_back(new_index[v]);
        std::rotate(g.begin(), std::min_element(g.begin(), g.end()), g.end());
        faces.push_back(std::move(g));
    }
    std::sort(faces.begin(), faces.end());
    w.varint(faces.size());
    int64_t previous_first = 0;
    for (const auto& g : faces)
    {
        w.varint(g.size() - 3);
        w.zigzag(static_cast<int64_t>(g[0]) - previous_first);
        previous_first = g[0];
        for (size_t c = 1; c < g.size(); ++c)
        {
            const auto& list = nb[g[c - 1]];
            const auto it = std::lower_bound(list.begin(), list.end(), g[c]);
            if (it == list.end() || *it != g[c])
                throw InvalidInputError("a face edge is not a strut; the model cannot be shared as a link");
            w.u8(static_cast<uint8_t>(it - list.begin()));
        }
    }
}

} // namespace

std::string encode_share_link(const ZomeModel& m)
{
    check_model(m);
    const size_t n = m.nodes.size();
    std::vector<std::vector<Neighbour>> adj(n);
    for (uint32_t s = 0; s < m.struts.size(); ++s)
    {
        adj[m.struts[s][0]].push_back({m.struts[s][1], s});
        adj[m.struts[s][1]].push_back({m.struts[s][0], s});
    }
    auto vector_from = [&](uint32_t a, uint32_t b) { return vector_id_of(m.nodes[b] - m.nodes[a]); };

    ByteWriter w;
    const bool faces = !m.faces.empty(), transform = !is_identity(m.transform);
    w.u8(static_cast<uint8_t>((transform ? kFlagTransform : 0) | (faces ? kFlagFaces : 0)));
    w.varint(n);
    w.varint(m.struts.size());

    constexpr uint32_t kNone = UINT32_MAX;
    std::vector<uint32_t> new_index(n, kNone), order;
    std::vector<std::array<uint32_t, 2>> new_struts;
    std::vector<bool> strut_done(m.struts.size(), false);
    order.reserve(n);
    uint32_t next_root = 0;
    for (size_t k = 0; k < n; ++k)
    {
        if (k == order.size())
        {
            // A new component: its lowest-numbered undiscovered node is the root.
            while (new_index[next_root] != kNone)
                ++next_root;
            new_index[next_root] = static_cast<uint32_t>(order.size());
            order.push_back(next_root);
            for (int32_t c : m.nodes[next_root].c)
                w.zigzag(c);
        }
        const uint32_t node = order[k];
        std::vector<std::pair<int, Neighbour>> fresh;
        for (const Neighbour& nbr : adj[node])
            if (!strut_done[nbr.strut])
                fresh.push_back({vector_from(node, nbr.node), nbr});
        std::sort(fresh.begin(), fresh.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        w.varint(fresh.size());
        for (const auto& [id, nbr] : fresh)
        {
            w.u8(static_cast<uint8_t>(id));
            strut_done[nbr.strut] = true;
            if (new_index[nbr.node] == kNone)
            {
                new_index[nbr.node] = static_cast<uint32_t>(order.size());
                order.push_back(nbr.node);
            }
            new_struts.push_back({static_cast<uint32_t>(k), new_index[nbr.node]});
        }
    }
    if (faces)
        encode_faces(w, m, new_index, new_struts);
    if (transform)
    {
        w.f64(m.transform.scale);
        for (double t : m.transform.translation)
            w.f64(t);
    }
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
    if (version != kShareLinkVersion)
        throw InvalidInputError("this share link has version " + std::to_string(version) +
                                "; this zomeify reads version " + std::to_string(kShareLinkVersion));

    const std::vector<uint8_t> bytes = base64url_decode(body.substr(dot + 1));
    ByteReader r(bytes);
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
                ZVec root;
                for (int32_t& c : root.c)
                {
                    const int64_t v = r.zigzag("a root position");
                    if (v < INT32_MIN / 4 || v > INT32_MAX / 4)
                        fail("a root position is out of range");
                    c = static_cast<int32_t>(v);
                }
                if (!index_of.emplace(root, static_cast<uint32_t>(k)).second)
                    fail("two nodes at one position");
                m.nodes.push_back(root);
            }
            const uint64_t count = r.varint("a strut count");
            if (count > kSlotCount || count > r.left())
                fail("node " + std::to_string(k) + " claims " + std::to_string(count) + " struts");
            for (uint64_t i = 0; i < count; ++i)
            {
                const uint8_t id = r.u8("a strut");
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

    if (flags & kFlagFaces)
    {
        const auto nb = sorted_neighbours(m.nodes.size(), m.struts);
        const uint64_t f = r.varint("the face count");
        if (f > kMaxModelFaces || f * 3 > r.left())
            fail("the face count " + std::to_string(f) + " is larger than the link holds");
        int64_t first = 0;
        m.faces.resize(f);
        for (uint64_t i = 0; i < f; ++i)
        {
            const uint64_t k = r.varint("a face") + 3;
            if (k > kMaxFaceSize)
                fail("face " + std::to_string(i) + " has too many corners");
            first += r.zigzag("a face");
            if (first < 0 || static_cast<uint64_t>(first) >= n)
                fail("face " + std::to_string(i) + " starts at a missing node");
            auto& face = m.faces[i];
            face.push_back(static_cast<uint32_t>(first));
            for (uint64_t c = 1; c < k; ++c)
            {
                const uint8_t j = r.u8("a face");
                const auto& list = nb[face.back()];
                if (j >= list.size())
                    fail("face " + std::to_string(i) + " follows a missing strut");
                face.push_back(list[j]);
            }
            // The corners follow struts; the closing edge must be one too, or the model could not be
            // shared again (the encoder refuses faces whose edges are not struts).
            const auto& last = nb[face.back()];
            if (!std::binary_search(last.begin(), last.end(), face.front()))
                fail("face " + std::to_string(i) + " does not close along a strut");
        }
    }
    if (flags & kFlagTransform)
    {
        m.transform.scale = r.f64("the transform");
        for (double& t : m.transform.translation)
            t = r.f64("the transform");
        if (!(m.transform.scale > 0) || !std::isfinite(m.transform.scale))
            fail("the scale is not a positive number");
        for (double t : m.transform.translation)
            if (!std::isfinite(t))
                fail("the translation is not finite");
    }
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
