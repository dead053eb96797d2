// REMNODE(n) (paper §3.2): n and its struts go; the hole (n's link, k nodes) is filled with
// triangles and quads whose new struts are chords between link nodes. The fill is a random ear
// cutting: starting at a random link position, the first ear (three consecutive nodes, chord
// a–c; or four, chord a–d) whose chord is a valid new strut (a Zome vector, both slots free, the
// two nodes not joined yet) is cut off as a face, until three or four nodes remain, which become
// the last face (a remaining quad is split by a valid diagonal with probability 1/2). Whether
// triangle or quad ears are tried first is random per proposal. A link that no such cutting
// fills is refused (NoCandidate); complete_fill() then checks valence and slots once more.
#include <algorithm>

#include "core/anneal/operators/exact_steps.h"
#include "core/anneal/operators/operators.h"
#include "core/anneal/operators/region.h"

namespace zomeify::detail {
namespace {

// The chords chosen so far, by the slots they take at their ends.
struct Chord
{
    uint8_t a, b;
    int slot_a, slot_b;
};
using Chords = FixedList<Chord, kMaxLink>;

bool slot_taken_by_chord(const Chords& chords, size_t node, int slot) noexcept
{
    return std::any_of(chords.begin(), chords.end(), [&](const Chord& c) {
        return (c.a == node && c.slot_a == slot) || (c.b == node && c.slot_b == slot);
    });
}

// Whether a new strut between link nodes a and b is possible; records it in `chords` if so.
bool try_chord(const ZomeMesh& mesh, const LocalChange& change, const Fill& fill, size_t a, size_t b,
               Chords& chords) noexcept
{
    const int id = vector_between(fill.nodes()[a].pos, fill.nodes()[b].pos);
    if (id < 0)
        return false;
    const int slot_a = vector_slot(id), slot_b = opposite_slot(slot_a);
    if (slot_taken_by_chord(chords, a, slot_a) || slot_taken_by_chord(chords, b, slot_b) ||
        keeps_strut_in_slot(mesh, fill.nodes()[a].v, slot_a, change) ||
        keeps_strut_in_slot(mesh, fill.nodes()[b].v, slot_b, change))
        return false;
    return chords.push_back({static_cast<uint8_t>(a), static_cast<uint8_t>(b), slot_a, slot_b});
}

} // namespace

Rejection propose_rem_node(const ZomeMesh& mesh, Vertex seed, Rng& rng, Claims& claims, Fill& fill,
                           LocalChange& change) noexcept
{
    if (const Rejection r = load_node_region(mesh, seed, claims, fill, change); r != Rejection::None)
        return r;
    FixedList<uint8_t, kMaxLink> polygon;
    for (size_t i = 0; i < fill.link_size(); ++i)
        polygon.push_back(static_cast<uint8_t>(i));
    Chords chords;
    const bool triangles_first = rng.below(2) == 0;
    while (polygon.size() > 4)
    {
        const size_t m = polygon.size();
        const size_t start = rng.below(m);
        bool cut = false;
        for (size_t t = 0; t < 2 * m && !cut; ++t)
        {
            const size_t i = (start + t % m) % m;
            const size_t ear = (t < m) == triangles_first ? 3 : 4; // corners of the ear
            if (m - ear + 2 < 3)
                continue; // the rest would be no face
            const uint8_t a = polygon[i], d = polygon[(i + ear - 1) % m];
            if (!try_chord(mesh, change, fill, a, d, chords))
                continue;
            if (ear == 3)
                fill.add_triangle(a, polygon[(i + 1) % m], d);
            else
                fill.add_quad(a, polygon[(i + 1) % m], polygon[(i + 2) % m], d);
            // Drop the ear's inner corners from the polygon.
            FixedList<uint8_t, kMaxLink> rest;
            for (size_t j = 0; j < m; ++j)
            {
                const size_t offset = (j + m - i) % m;
                if (offset == 0 || offset >= ear - 1)
                    rest.push_back(polygon[j]);
            }
            polygon = rest;
            cut = true;
        }
        if (!cut)
            return Rejection::NoCandidate;
    }
    if (polygon.size() == 4 && rng.below(2) == 0)
    {
        const size_t i = rng.below(2);
        if (try_chord(mesh, change, fill, polygon[i], polygon[i + 2], chords))
        {
            fill.add_triangle(polygon[i], polygon[i + 1], polygon[i + 2]);
            fill.add_triangle(polygon[i + 2], polygon[(i + 3) % 4], polygon[i]);
            return complete_fill(mesh, fill, claims, change);
        }
    }
    if (polygon.size() == 4)
        fill.add_quad(polygon[0], polygon[1], polygon[2], polygon[3]);
    else
        fill.add_triangle(polygon[0], polygon[1], polygon[2]);
    return complete_fill(mesh, fill, claims, change);
}

} // namespace zomeify::detail
