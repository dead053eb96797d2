#include "core/anneal/energy/local_energy.h"

#include <algorithm>

#include "core/anneal/energy/element_energy.h"
#include "core/mesh/circulators.h"

namespace zomeify {
namespace {

template <class List, class T>
bool contains(const List& list, const T& x) noexcept
{
    return std::find(list.begin(), list.end(), x) != list.end();
}

// The surviving node of the removed region at p, or invalid. Surviving nodes that the change
// touches are endpoints of removed struts or corners of removed faces, so only those are searched.
Vertex find_region_node(const ZomeMesh& mesh, const LocalChange& change, const ZVec& p) noexcept
{
    auto match = [&](Vertex v) { return mesh.position(v) == p && !contains(change.removed_nodes(), v); };
    for (Edge e : change.removed_struts())
    {
        for (int i = 0; i < 2; ++i)
        {
            if (match(mesh.vertex(e, i)))
            {
                return mesh.vertex(e, i);
            }
        }
    }
    for (Face f : change.removed_faces())
    {
        for (Vertex v : face_vertices(mesh, f))
        {
            if (match(v))
            {
                return v;
            }
        }
    }
    return Vertex();
}

// Adds the other ends of the added struts at p to a 1-ring.
void add_new_neighbours(const LocalChange& change, const ZVec& p, LatticeSum& ring, int& k) noexcept
{
    for (const NewStrut& s : change.added_struts())
    {
        if (s.a == p)
        {
            ring += s.b;
            ++k;
        }
        else if (s.b == p)
        {
            ring += s.a;
            ++k;
        }
    }
}

class LocalEnergy
{
public:
    LocalEnergy(const ZomeMesh& mesh, const LocalChange& change, const SurfaceContext& context,
                const EnergyOptions& options, FoldOvers fold_overs) noexcept
        : mesh_(mesh), change_(change), context_(context), options_(options), fold_overs_(fold_overs), normals_(context)
    {
    }

    EnergyDelta run() noexcept
    {
        if (change_.overflowed())
        {
            out_.status = ChangeStatus::Overflow;
            return out_;
        }
        if (fold_overs_ == FoldOvers::Refuse && adds_fold_over())
        {
            out_.status = ChangeStatus::FoldOver;
            out_.adds_fold_over = true;
            return out_;
        }
        removed_samples();
        added_samples();
        fairing();
        return out_;
    }

private:
    // The same test as face_energy's (its barycentre sample is then in the thread's cache).
    bool adds_fold_over() const noexcept
    {
        for (const NewFace& f : change_.added_faces())
            if (face_is_fold_over(f.view(), context_))
                return true;
        return false;
    }

    void removed_samples() noexcept
    {
        EnergySums& d = out_.sums;
        for (Vertex v : change_.removed_nodes())
        {
            d.distance -= node_distance(mesh_.position(v));
            --d.nodes;
        }
        for (Edge e : change_.removed_struts())
        {
            const StrutEnergy s = strut_energy(mesh_.position(mesh_.vertex(e, 0)), mesh_.position(mesh_.vertex(e, 1)),
                                               context_, options_);
            d.distance -= s.distance;
            d.tangential -= s.tangential;
            --d.struts;
        }
        for (Face f : change_.removed_faces())
        {
            const FaceEnergy fe = face_energy(mesh_, f, normals_, options_);
            d.distance -= fe.distance;
            d.normal -= fe.normal;
            d.corners -= fe.corners;
            d.fold_overs -= fe.fold_over ? 1 : 0;
            --d.faces;
        }
    }

    // A node's distance sample, whose normal the corners at that node reuse.
    EnergyFixed node_distance(const ZVec& p) noexcept
    {
        const SurfaceSample s = context_.node_sample(p);
        normals_.remember(p, s.normal);
        return quantize(distance_value(s, options_));
    }

    void added_samples() noexcept
    {
        EnergySums& d = out_.sums;
        for (const ZVec& p : change_.added_nodes())
        {
            d.distance += node_distance(p);
            ++d.nodes;
        }
        for (const NewStrut& s : change_.added_struts())
        {
            const StrutEnergy se = strut_energy(s.a, s.b, context_, options_);
            d.distance += se.distance;
            d.tangential += se.tangential;
            ++d.struts;
        }
        for (const NewFace& f : change_.added_faces())
        {
            const FaceEnergy fe = face_energy(f.view(), normals_, options_);
            out_.adds_fold_over = out_.adds_fold_over || fe.fold_over;
            d.fold_overs += fe.fold_over ? 1 : 0;
            d.distance += fe.distance;
            d.normal += fe.normal;
            d.corners += fe.corners;
            ++d.faces;
        }
    }

    // A node's fairing changes exactly when a strut at it appears or disappears (a moved neighbour
    // is a removed and re-added node, so its struts are too). Existing such nodes lose their old
    // value; survivors and added nodes gain the value of their new 1-ring.
    void fairing() noexcept
    {
        for (Vertex v : change_.removed_nodes())
        {
            touch(v);
            // A removed node takes all its struts along; a kept one would leave a survivor's
            // 1-ring pointing at a node that no longer exists.
            for (Halfedge h : outgoing_halfedges(mesh_, v))
            {
                if (!contains(change_.removed_struts(), ZomeMesh::edge(h)))
                {
                    out_.status = ChangeStatus::KeptStrutToRemovedNode;
                }
            }
        }
        for (Edge e : change_.removed_struts())
        {
            touch(mesh_.vertex(e, 0));
            touch(mesh_.vertex(e, 1));
        }
        for (const NewStrut& s : change_.added_struts())
        {
            touch_position(s.a);
            touch_position(s.b);
        }
        if (touched_.overflowed())
        {
            out_.status = ChangeStatus::Overflow;
        }
        if (!out_.ok())
        {
            return;
        }
        EnergyAccumulator& fair = out_.sums.fairing;
        for (Vertex v : touched_)
        {
            fair -= fairing_energy(mesh_, v);
            if (!contains(change_.removed_nodes(), v))
            {
                fair += surviving_fairing(v);
            }
        }
        for (const ZVec& p : change_.added_nodes())
        {
            LatticeSum ring;
            int k = 0;
            add_new_neighbours(change_, p, ring, k);
            fair += fairing_energy(p, ring, k);
        }
    }

    void touch(Vertex v) noexcept
    {
        if (!contains(touched_, v))
        {
            touched_.push_back(v);
        }
    }

    // An added strut's end is an added node (handled with the added nodes) or a surviving node.
    void touch_position(const ZVec& p) noexcept
    {
        if (contains(change_.added_nodes(), p))
        {
            return;
        }
        const Vertex v = find_region_node(mesh_, change_, p);
        if (!v.is_valid())
        {
            out_.status = ChangeStatus::UnknownNode;
            return;
        }
        touch(v);
    }

    EnergyFixed surviving_fairing(Vertex v) noexcept
    {
        LatticeSum ring;
        int k = 0;
        for (Halfedge h : outgoing_halfedges(mesh_, v))
        {
            if (contains(change_.removed_struts(), ZomeMesh::edge(h)))
            {
                continue;
            }
            ring += mesh_.position(mesh_.to_vertex(h));
            ++k;
        }
        add_new_neighbours(change_, mesh_.position(v), ring, k);
        return fairing_energy(mesh_.position(v), ring, k);
    }

    const ZomeMesh& mesh_;
    const LocalChange& change_;
    const SurfaceContext& context_;
    const EnergyOptions& options_;
    const FoldOvers fold_overs_;
    NodeNormals normals_;
    EnergyDelta out_;
    // Existing nodes whose fairing value changes (removed ones included).
    FixedList<Vertex, 4 * LocalChange::kMaxStruts + LocalChange::kMaxNodes> touched_;
};

} // namespace

EnergyDelta simulate_change(const ZomeMesh& mesh, const LocalChange& change, const SurfaceContext& context,
                            const EnergyOptions& options, FoldOvers fold_overs) noexcept
{
    return LocalEnergy(mesh, change, context, options, fold_overs).run();
}

} // namespace zomeify
