#include "core/io/share_link_faces.h"

#include <algorithm>

#include "core/base/errors.h"
#include "core/io/model_check.h"
#include "core/mesh/recover_faces.h"
#include "core/mesh/strut_rotation.h"

namespace zomeify {

namespace {

constexpr size_t kMixedRadixLimit = 20; // 19! < 2^63

[[noreturn]] void fail(const std::string& what) { throw InvalidInputError("this share link is damaged: " + what); }

// Sorted neighbour lists, the shared reference frame of the explicit face encoding.
std::vector<std::vector<uint32_t>> sorted_neighbours(size_t n, const StrutList& struts)
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

// Faces rotated to start at their smallest corner, then sorted: a canonical face set.
FaceList canonical_faces(FaceList faces)
{
    for (auto& f : faces)
        std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    std::sort(faces.begin(), faces.end());
    return faces;
}

// `r` rotated so that it starts at `first`.
std::vector<uint32_t> starting_at(std::vector<uint32_t> r, uint32_t first)
{
    std::rotate(r.begin(), std::find(r.begin(), r.end(), first), r.end());
    return r;
}

} // namespace

void write_explicit_faces(ByteWriter& w, size_t node_count, const StrutList& struts, const FaceList& faces)
{
    const auto nb = sorted_neighbours(node_count, struts);
    const FaceList sorted = canonical_faces(faces);
    w.varint(sorted.size());
    int64_t previous_first = 0;
    for (const auto& g : sorted)
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

FaceList read_explicit_faces(ByteReader& r, size_t n, const StrutList& struts)
{
    const auto nb = sorted_neighbours(n, struts);
    const uint64_t f = r.varint("the face count");
    if (f > kMaxModelFaces || f * 3 > r.left())
        fail("the face count " + std::to_string(f) + " is larger than the link holds");
    int64_t first = 0;
    FaceList faces(f);
    for (uint64_t i = 0; i < f; ++i)
    {
        const uint64_t k = r.varint("a face") + 3;
        if (k > kMaxFaceSize)
            fail("face " + std::to_string(i) + " has too many corners");
        first += r.zigzag("a face");
        if (first < 0 || static_cast<uint64_t>(first) >= n)
            fail("face " + std::to_string(i) + " starts at a missing node");
        auto& face = faces[i];
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
    return faces;
}

bool write_face_exceptions(ByteWriter& w, const std::vector<ZVec>& nodes, const StrutList& struts,
                           const FaceList& faces)
{
    const std::optional<Rotation> truth = rotation_of_faces(nodes.size(), struts, faces);
    if (!truth || canonical_faces(trace_faces(*truth)) != canonical_faces(faces))
        return false;
    const Rotation guess = guess_rotation(nodes, struts);
    ByteWriter body;
    size_t count = 0, previous = 0;
    for (size_t v = 0; v < nodes.size(); ++v)
    {
        const auto& g = guess[v];
        if (g.empty())
            continue;
        const std::vector<uint32_t> t = starting_at((*truth)[v], g[0]);
        if (t == g)
            continue;
        body.varint(v - previous);
        previous = v + 1;
        ++count;
        // Lehmer code of t[1..] among g[1..]; the last digit is always 0.
        std::vector<uint32_t> left(g.begin() + 1, g.end());
        uint64_t code = 0;
        for (size_t i = 1; i + 1 < t.size(); ++i)
        {
            const auto it = std::find(left.begin(), left.end(), t[i]);
            const auto digit = static_cast<uint64_t>(it - left.begin());
            if (g.size() <= kMixedRadixLimit)
                code = code * left.size() + digit;
            else
                body.varint(digit);
            left.erase(it);
        }
        if (g.size() <= kMixedRadixLimit)
            body.varint(code);
    }
    w.varint(count);
    for (uint8_t b : body.bytes())
        w.u8(b);
    return true;
}

FaceList read_face_exceptions(ByteReader& r, const std::vector<ZVec>& nodes, const StrutList& struts)
{
    Rotation rotation = guess_rotation(nodes, struts);
    const uint64_t count = r.varint("the face exceptions");
    if (count > nodes.size() || count > r.left())
        fail("it claims " + std::to_string(count) + " face exceptions");
    uint64_t at = 0;
    for (uint64_t e = 0; e < count; ++e)
    {
        at += r.varint("a face exception");
        if (at >= nodes.size())
            fail("a face exception names a missing node");
        auto& g = rotation[at];
        if (g.size() < 3)
            fail("a face exception names a node with fewer than 3 struts");
        std::vector<uint32_t> left(g.begin() + 1, g.end()), t{g[0]};
        std::vector<uint64_t> digits(left.size(), 0);
        if (g.size() <= kMixedRadixLimit)
        {
            uint64_t code = r.varint("a face exception");
            for (size_t i = left.size(); i-- > 0;)
            {
                const uint64_t radix = left.size() - i; // digit i chooses among left.size() − i items
                digits[i] = code % radix;
                code /= radix;
            }
            if (code != 0)
                fail("a face exception is out of range");
        }
        else
            for (size_t i = 0; i + 1 < left.size(); ++i)
            {
                digits[i] = r.varint("a face exception");
                if (digits[i] >= left.size() - i)
                    fail("a face exception is out of range");
            }
        for (size_t i = 0; i < digits.size(); ++i)
        {
            t.push_back(left[digits[i]]);
            left.erase(left.begin() + static_cast<std::ptrdiff_t>(digits[i]));
        }
        g = std::move(t);
        ++at;
    }
    FaceList faces = trace_faces(rotation);
    for (const auto& f : faces)
        if (f.size() < 3 || f.size() > kMaxFaceSize)
            fail("the struts and exceptions give a face of " + std::to_string(f.size()) + " corners");
    return faces;
}

} // namespace zomeify
