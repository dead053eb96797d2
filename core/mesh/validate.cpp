#include "core/mesh/validate.h"

#include <numeric>
#include <sstream>
#include <unordered_map>

namespace zomeify {

const char* to_string(MeshProblem p)
{
    switch (p)
    {
    case MeshProblem::Connectivity:
        return "broken connectivity";
    case MeshProblem::Boundary:
        return "boundary halfedge";
    case MeshProblem::NonManifoldVertex:
        return "non-manifold vertex";
    case MeshProblem::NonZomeEdge:
        return "edge not a Zome vector";
    case MeshProblem::WrongVectorId:
        return "wrong stored slot";
    case MeshProblem::DuplicatePosition:
        return "two nodes at one position";
    case MeshProblem::PositionIndex:
        return "position index out of sync";
    case MeshProblem::SlotConflict:
        return "two struts in one slot";
    case MeshProblem::DoubleEdge:
        return "doubly connected nodes";
    case MeshProblem::FaceSize:
        return "face not a triangle or quad";
    case MeshProblem::LowValence:
        return "valence too low";
    }
    return "unknown";
}

bool ValidationReport::ok() const { return total_problems() == 0; }

size_t ValidationReport::total_problems() const
{
    return std::accumulate(problem_counts.begin(), problem_counts.end(), size_t{0});
}

std::string ValidationReport::message() const
{
    std::ostringstream os;
    if (ok())
    {
        os << "valid: " << n_vertices << " nodes, " << n_edges << " struts, " << n_faces << " faces, "
           << components.size() << (components.size() == 1 ? " component" : " components") << ", genus " << genus;
        return os.str();
    }
    os << "invalid (" << total_problems() << " problems:";
    bool first = true;
    for (size_t i = 0; i < kMeshProblemCount; ++i)
        if (problem_counts[i] != 0)
        {
            os << (first ? " " : ", ") << problem_counts[i] << "x " << to_string(static_cast<MeshProblem>(i));
            first = false;
        }
    os << ")";
    for (const auto& m : messages)
        os << "; " << m;
    return os.str();
}

namespace {

class Validator
{
public:
    Validator(const SurfaceMesh& mesh, const ValidateOptions& options, ValidationReport& report)
        : m_(mesh), opt_(options), r_(report)
    {
    }

    void run_topology()
    {
        r_.n_vertices = m_.n_vertices();
        r_.n_edges = m_.n_edges();
        r_.n_faces = m_.n_faces();
        // Traversals (face cycles, vertex rotations) can loop forever on broken links, so they
        // only run once every single link has been checked.
        check_links();
        if (r_.has(MeshProblem::Connectivity))
            return;
        check_faces();
        check_vertices();
        if (r_.has(MeshProblem::Connectivity))
            return;
        count_components();
        r_.topology_known = true;
    }

    void report(MeshProblem p, const std::string& what)
    {
        ++r_.problem_counts[static_cast<size_t>(p)];
        if (r_.messages.size() < opt_.max_messages)
            r_.messages.push_back(what);
    }

private:
    template <class H>
    static std::string name(H h)
    {
        std::ostringstream os;
        os << h;
        return os.str();
    }

    void check_links()
    {
        const size_t nh = m_.halfedges_size();
        for (MeshIndex i = 0; i < nh; ++i)
        {
            const Halfedge h(i);
            if (m_.is_deleted(h))
                continue;
            const HalfedgeLinks& l = m_.links(h);
            // Names are built only when a problem is reported: validate runs after every test edit.
            const auto hn = [h] { return "halfedge " + name(h); };
            if (!m_.is_valid(l.to))
            {
                report(MeshProblem::Connectivity, hn() + " points to a missing vertex");
                continue;
            }
            if (!m_.is_valid(l.next) || !m_.is_valid(l.prev))
            {
                report(MeshProblem::Connectivity, hn() + " has a missing next or prev");
                continue;
            }
            if (m_.prev(l.next) != h || m_.next(l.prev) != h)
                report(MeshProblem::Connectivity, hn() + ": next and prev are not inverse");
            if (m_.from_vertex(l.next) != l.to)
                report(MeshProblem::Connectivity, hn() + ": next does not start where it ends");
            if (m_.face(l.next) != l.face)
                report(MeshProblem::Connectivity, hn() + ": next lies in another face");
            if (l.face.is_valid() && !m_.is_valid(l.face))
                report(MeshProblem::Connectivity, hn() + " lies in a missing face");
            if (l.to == m_.from_vertex(h))
                report(MeshProblem::Connectivity, hn() + " is a loop");
        }
        for (MeshIndex i = 0; i < m_.vertices_size(); ++i)
        {
            const Vertex v(i);
            if (m_.is_deleted(v))
                continue;
            const Halfedge h = m_.halfedge(v);
            if (h.is_valid() && (!m_.is_valid(h) || m_.from_vertex(h) != v))
                report(MeshProblem::Connectivity, "vertex " + name(v) + ": outgoing halfedge does not leave it");
        }
        for (MeshIndex i = 0; i < m_.faces_size(); ++i)
        {
            const Face f(i);
            if (m_.is_deleted(f))
                continue;
            const Halfedge h = m_.halfedge(f);
            if (!m_.is_valid(h) || m_.face(h) != f)
                report(MeshProblem::Connectivity, "face " + name(f) + ": its halfedge is not in it");
        }
    }

    void check_faces()
    {
        size_t face_halfedges = 0;
        for (MeshIndex i = 0; i < m_.faces_size(); ++i)
        {
            const Face f(i);
            if (m_.is_deleted(f))
                continue;
            const size_t n = m_.valence(f);
            face_halfedges += n;
            if (opt_.tri_quad_only && n != 3 && n != 4)
                report(MeshProblem::FaceSize, "face " + name(f) + " has " + std::to_string(n) + " corners");
        }
        size_t boundary = 0;
        for (MeshIndex i = 0; i < m_.halfedges_size(); ++i)
        {
            const Halfedge h(i);
            if (!m_.is_deleted(h) && m_.is_boundary(h))
                ++boundary;
        }
        // Every non-boundary halfedge must be reached by exactly one face cycle.
        if (face_halfedges + boundary != m_.n_halfedges())
            report(MeshProblem::Connectivity, "face cycles do not cover the face halfedges exactly once");
        if (opt_.require_closed && boundary != 0)
            report(MeshProblem::Boundary, std::to_string(boundary) + " boundary halfedges in a closed mesh");
    }

    void check_vertices()
    {
        std::vector<MeshIndex> degree(m_.vertices_size(), 0);
        std::vector<MeshIndex> gaps(m_.vertices_size(), 0);
        for (MeshIndex i = 0; i < m_.halfedges_size(); ++i)
        {
            const Halfedge h(i);
            if (m_.is_deleted(h))
                continue;
            const Vertex from = m_.from_vertex(h);
            ++degree[from.idx()];
            if (m_.is_boundary(h))
                ++gaps[from.idx()];
        }
        for (MeshIndex i = 0; i < m_.vertices_size(); ++i)
        {
            const Vertex v(i);
            if (m_.is_deleted(v))
                continue;
            const auto vn = [v] { return "vertex " + name(v); };
            const Halfedge start = m_.halfedge(v);
            if (degree[i] == 0 || !start.is_valid())
            {
                if (degree[i] != 0 || start.is_valid())
                    report(MeshProblem::Connectivity, vn() + ": isolated but has edges");
                else if (opt_.min_valence > 0)
                    report(MeshProblem::LowValence, vn() + " is isolated");
                continue;
            }
            size_t count = 0;
            Halfedge h = start;
            do
            {
                if (m_.from_vertex(h) != v)
                {
                    report(MeshProblem::Connectivity, vn() + ": rotation leaves the vertex");
                    break;
                }
                ++count;
                h = m_.ccw_rotated(h);
            } while (h != start && count <= degree[i]);
            if (count != degree[i])
                report(MeshProblem::NonManifoldVertex,
                       vn() + ": its " + std::to_string(degree[i]) + " edges do not form one rotation cycle");
            else if (gaps[i] > 1)
                report(MeshProblem::NonManifoldVertex,
                       vn() + " touches " + std::to_string(gaps[i]) + " boundary gaps (faces meet at a point)");
            if (gaps[i] > 0 && !m_.is_boundary(start))
                report(MeshProblem::Connectivity, vn() + " is on a boundary but its halfedge is not");
            if (degree[i] < opt_.min_valence)
                report(MeshProblem::LowValence, vn() + " has valence " + std::to_string(degree[i]));
            check_double_edges(v, start);
        }
    }

    void check_double_edges(Vertex v, Halfedge start)
    {
        for (Halfedge a = start;;)
        {
            const Vertex va = m_.to_vertex(a);
            for (Halfedge b = m_.ccw_rotated(a); b != start; b = m_.ccw_rotated(b))
                if (m_.to_vertex(b) == va && va.idx() > v.idx())
                    report(MeshProblem::DoubleEdge,
                           "vertex " + name(v) + " and " + name(va) + " are joined by two edges");
            a = m_.ccw_rotated(a);
            if (a == start)
                break;
        }
    }

    MeshIndex find(std::vector<MeshIndex>& parent, MeshIndex x)
    {
        while (parent[x] != x)
        {
            parent[x] = parent[parent[x]];
            x = parent[x];
        }
        return x;
    }

    void count_components()
    {
        const size_t nv = m_.vertices_size();
        std::vector<MeshIndex> parent(nv);
        std::iota(parent.begin(), parent.end(), MeshIndex{0});
        for (MeshIndex i = 0; i < m_.edges_size(); ++i)
        {
            const Edge e(i);
            if (m_.is_deleted(e))
                continue;
            const MeshIndex a = find(parent, m_.vertex(e, 0).idx());
            const MeshIndex b = find(parent, m_.vertex(e, 1).idx());
            if (a != b)
                parent[a] = b;
        }
        std::vector<MeshIndex> comp_of_root(nv, kInvalidMeshIndex);
        std::vector<MeshComponent>& comps = r_.components;
        const auto comp = [&](Vertex v) -> MeshComponent& {
            const MeshIndex root = find(parent, v.idx());
            if (comp_of_root[root] == kInvalidMeshIndex)
            {
                comp_of_root[root] = static_cast<MeshIndex>(comps.size());
                comps.emplace_back();
            }
            return comps[comp_of_root[root]];
        };
        for (MeshIndex i = 0; i < nv; ++i)
        {
            const Vertex v(i);
            if (!m_.is_deleted(v) && !m_.is_isolated(v))
                ++comp(v).vertices;
        }
        for (MeshIndex i = 0; i < m_.edges_size(); ++i)
            if (!m_.is_deleted(Edge(i)))
                ++comp(m_.vertex(Edge(i), 0)).edges;
        for (MeshIndex i = 0; i < m_.faces_size(); ++i)
            if (!m_.is_deleted(Face(i)))
                ++comp(m_.to_vertex(m_.halfedge(Face(i)))).faces;
        // Boundary loops: walk each boundary cycle once, marking its halfedges.
        std::vector<uint8_t> seen(m_.halfedges_size(), 0);
        for (MeshIndex i = 0; i < m_.halfedges_size(); ++i)
        {
            const Halfedge h(i);
            if (m_.is_deleted(h) || !m_.is_boundary(h) || seen[i])
                continue;
            Halfedge x = h;
            do
            {
                seen[x.idx()] = 1;
                x = m_.next(x);
            } while (x != h);
            ++comp(m_.to_vertex(h)).boundary_loops;
        }
        r_.genus = 0;
        r_.euler_characteristic = 0;
        r_.boundary_loops = 0;
        for (MeshComponent& c : comps)
        {
            c.euler_characteristic =
                static_cast<long>(c.vertices) - static_cast<long>(c.edges) + static_cast<long>(c.faces);
            c.genus = static_cast<int>((2 - c.euler_characteristic - static_cast<long>(c.boundary_loops)) / 2);
            r_.genus += c.genus;
            r_.euler_characteristic += c.euler_characteristic;
            r_.boundary_loops += c.boundary_loops;
        }
    }

    const SurfaceMesh& m_;
    const ValidateOptions& opt_;
    ValidationReport& r_;
};

void check_zome(const ZomeMesh& m, Validator& val)
{
    for (MeshIndex i = 0; i < m.edges_size(); ++i)
    {
        const Edge e(i);
        if (m.is_deleted(e))
            continue;
        const Halfedge h = SurfaceMesh::halfedge(e, 0);
        const int id = vector_id_of(m.vector(h));
        const auto en = [&] {
            std::ostringstream os;
            os << "edge " << e << " (" << m.from_vertex(h) << "->" << m.to_vertex(h) << ")";
            return os.str();
        };
        if (id < 0)
        {
            val.report(
                MeshProblem::NonZomeEdge, en() + " has vector " + [&] {
                    std::ostringstream os;
                    os << m.vector(h);
                    return os.str();
                }() + ", not a Zome vector");
            if (m.vector_id(h) != kNoZomeVector || m.vector_id(SurfaceMesh::opposite(h)) != kNoZomeVector)
                val.report(MeshProblem::WrongVectorId, en() + " stores a Zome vector id for a non-Zome vector");
            continue;
        }
        const int opposite_id = vector_id(opposite_slot(vector_slot(id)), vector_size(id));
        if (m.vector_id(h) != id || m.vector_id(SurfaceMesh::opposite(h)) != opposite_id)
            val.report(MeshProblem::WrongVectorId, en() + " stores vector ids " + std::to_string(m.vector_id(h)) + "/" +
                                                       std::to_string(m.vector_id(SurfaceMesh::opposite(h))) +
                                                       ", expected " + std::to_string(id) + "/" +
                                                       std::to_string(opposite_id));
    }

    std::unordered_map<ZVec, Vertex, ZVecHash> seen;
    seen.reserve(m.n_vertices());
    for (MeshIndex i = 0; i < m.vertices_size(); ++i)
    {
        const Vertex v(i);
        if (m.is_deleted(v))
            continue;
        const auto vn = [v] {
            std::ostringstream os;
            os << "vertex " << v;
            return os.str();
        };
        const auto [it, inserted] = seen.emplace(m.position(v), v);
        if (!inserted)
        {
            std::ostringstream os;
            os << vn() << " sits at " << m.position(v) << " like " << it->second;
            val.report(MeshProblem::DuplicatePosition, os.str());
        }
        else if (m.find_vertex(m.position(v)) != v)
            val.report(MeshProblem::PositionIndex, vn() + " is not found at its position");
        // Slots of one node: at most 62 distinct, so a bit mask makes this O(valence).
        const Halfedge start = m.halfedge(v);
        if (!start.is_valid())
            continue;
        uint64_t used = 0;
        size_t guard = 0;
        Halfedge h = start;
        do
        {
            const int s = m.slot(h);
            if (s >= 0)
            {
                if (used & (uint64_t{1} << s))
                    val.report(MeshProblem::SlotConflict, vn() + " has two struts in slot " + std::to_string(s));
                used |= uint64_t{1} << s;
            }
            h = m.ccw_rotated(h);
        } while (h != start && ++guard < m.halfedges_size());
    }
    m.position_index().for_each([&](const ZVec& p, Vertex v) {
        if (!m.is_valid(v) || m.position(v) != p)
        {
            std::ostringstream os;
            os << "the position index maps " << p << " to " << v << ", which is not there";
            val.report(MeshProblem::PositionIndex, os.str());
        }
    });
    if (m.position_index_size() != m.n_vertices())
        val.report(MeshProblem::PositionIndex, "the position index has " + std::to_string(m.position_index_size()) +
                                                   " entries for " + std::to_string(m.n_vertices()) + " nodes");
}

} // namespace

ValidationReport validate(const SurfaceMesh& mesh, const ValidateOptions& options)
{
    ValidationReport report;
    Validator val(mesh, options, report);
    val.run_topology();
    return report;
}

ValidationReport validate(const ZomeMesh& mesh, const ValidateOptions& options)
{
    ValidationReport report;
    Validator val(mesh, options, report);
    val.run_topology();
    // The per-vertex slot walk needs sound rotation cycles.
    if (options.check_zome && report.topology_known)
        check_zome(mesh, val);
    return report;
}

} // namespace zomeify
