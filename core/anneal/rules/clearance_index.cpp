#include "core/anneal/rules/clearance_index.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/geom/clearance.h"
#include "core/mesh/circulators.h"
#include "core/mesh/element_ranges.h"
#include "core/zome/clearance_rules.h"

namespace zomeify {
namespace {

// Grid cells (b0): about a strut long.
constexpr double kCell = 1.0;

Vec3 to_vec3(const ZVec& p)
{
    const auto c = p.to_double();
    return {c[0], c[1], c[2]};
}

// The rule of core/geom/clearance.h on a panel's canonical triangles.
bool pierces(const Vec3& a, const Vec3& b, const FaceShape& shape)
{
    return strut_face_clash(a, b, std::span<const std::array<Vec3, 3>>(shape.triangles.data(), shape.count));
}

// Whether two boxes come within `gap` of each other (a cheap test before an exact one; the slack
// keeps touching pairs in).
bool boxes_within(const Box3& a, const Box3& b, double gap)
{
    const double g = gap + 1e-9;
    return (a.min.array() <= b.max.array() + g).all() && (b.min.array() <= a.max.array() + g).all();
}

void mark_all(std::vector<uint32_t>& marks, uint32_t index, uint32_t mark)
{
    if (index >= marks.size())
        marks.resize(std::max<size_t>(index + 1, 2 * marks.size()), 0);
    marks[index] = mark;
}

} // namespace

const char* clash_name(ClashKind kind) noexcept
{
    switch (kind)
    {
    case ClashKind::None:
        return "none";
    case ClashKind::BallBall:
        return "ball–ball";
    case ClashKind::BallStrut:
        return "ball–strut";
    case ClashKind::StrutStrut:
        return "strut–strut";
    case ClashKind::StrutFace:
        return "strut through face";
    }
    return "?";
}

bool ClearanceIndex::Panel::has_corner(const ZVec& p) const noexcept
{
    for (int i = 0; i < size; ++i)
        if (corners[static_cast<size_t>(i)] == p)
            return true;
    return false;
}

ClearanceIndex::Ball ClearanceIndex::make_ball(const ZVec& p)
{
    Ball b{to_vec3(p), p, {}};
    b.box.extend(b.p);
    return b;
}

ClearanceIndex::Strut ClearanceIndex::make_strut(const ZVec& a, const ZVec& b)
{
    Strut s{to_vec3(a), to_vec3(b), a, b, {}};
    s.box.extend(s.a);
    s.box.extend(s.b);
    return s;
}

ClearanceIndex::Panel ClearanceIndex::make_panel(std::span<const ZVec> corners)
{
    Panel p;
    p.shape = face_shape(corners);
    p.size = static_cast<int>(std::min<size_t>(corners.size(), 4));
    std::copy_n(corners.begin(), p.size, p.corners.begin());
    p.box = p.shape.box;
    return p;
}

ClearanceIndex::ClearanceIndex(const Box3& domain)
    : balls_(domain, kCell), struts_(domain, kCell), panels_(domain, kCell)
{
}

void ClearanceIndex::reset(const ZomeMesh& mesh)
{
    balls_.clear();
    struts_.clear();
    panels_.clear();
    for (Vertex v : vertices(mesh))
        balls_.insert(v.idx(), make_ball(mesh.position(v)));
    for (Edge e : edges(mesh))
        struts_.insert(e.idx(), make_strut(mesh.position(mesh.vertex(e, 0)), mesh.position(mesh.vertex(e, 1))));
    for (Face f : faces(mesh))
    {
        std::array<ZVec, 4> corners;
        size_t n = 0;
        for (Vertex v : face_vertices(mesh, f))
            if (n < corners.size())
                corners[n++] = mesh.position(v);
        panels_.insert(f.idx(), make_panel(std::span<const ZVec>(corners.data(), n)));
    }
}

void ClearanceIndex::reset(const ZomeModel& model)
{
    balls_.clear();
    struts_.clear();
    panels_.clear();
    const size_t n = model.nodes.size();
    for (size_t i = 0; i < n; ++i)
        balls_.insert(static_cast<uint32_t>(i), make_ball(model.nodes[i]));
    for (size_t i = 0; i < model.struts.size(); ++i)
    {
        const auto& s = model.struts[i];
        if (s[0] < n && s[1] < n)
            struts_.insert(static_cast<uint32_t>(i), make_strut(model.nodes[s[0]], model.nodes[s[1]]));
    }
    for (size_t i = 0; i < model.faces.size(); ++i)
    {
        const auto& f = model.faces[i];
        if (f.size() != 3 && f.size() != 4)
            continue;
        std::array<ZVec, 4> corners;
        bool ok = true;
        for (size_t k = 0; k < f.size(); ++k)
        {
            ok = ok && f[k] < n;
            corners[k] = ok ? model.nodes[f[k]] : ZVec{};
        }
        if (ok)
            panels_.insert(static_cast<uint32_t>(i), make_panel(std::span<const ZVec>(corners.data(), f.size())));
    }
}

ClashKind ClearanceIndex::check_ball(const Ball& ball, Scratch& sc) const
{
    ClashKind found = ClashKind::None;
    balls_.for_each_near(dilated(ball.box, kMinBallBall), sc.visits, [&](uint32_t i, const Ball& other) {
        if (found == ClashKind::None && !sc.removed(sc.removed_balls, i) && balls_clash(other.p, ball.p))
            found = ClashKind::BallBall;
    });
    for (const Ball& other : sc.balls)
        if (&other != &ball && balls_clash(other.p, ball.p))
            return ClashKind::BallBall;
    if (found != ClashKind::None)
        return found;
    // A new ball holds none of the struts that stay (its own are all new).
    struts_.for_each_near(dilated(ball.box, kMinBallStrut), sc.visits, [&](uint32_t i, const Strut& s) {
        if (found == ClashKind::None && s.box.distance_squared(ball.p) < kMinBallStrutSquared &&
            !sc.removed(sc.removed_struts, i) && !s.holds(ball.at) && ball_strut_clash(ball.p, s.a, s.b))
            found = ClashKind::BallStrut;
    });
    return found;
}

ClashKind ClearanceIndex::check_strut(const Strut& strut, size_t index, Scratch& sc) const
{
    ClashKind found = ClashKind::None;
    const auto near_ball = [&](const Ball& b) {
        return !strut.holds(b.at) && strut.box.distance_squared(b.p) < kMinBallStrutSquared &&
               ball_strut_clash(b.p, strut.a, strut.b);
    };
    balls_.for_each_near(dilated(strut.box, kMinBallStrut), sc.visits, [&](uint32_t i, const Ball& b) {
        if (found == ClashKind::None && !sc.removed(sc.removed_balls, i) && near_ball(b))
            found = ClashKind::BallStrut;
    });
    for (const Ball& b : sc.balls)
        if (near_ball(b))
            return ClashKind::BallStrut;
    if (found != ClashKind::None)
        return found;

    const auto too_close = [&](const Strut& o) {
        return !strut.shares_ball(o) && boxes_within(strut.box, o.box, kMinStrutStrut) &&
               struts_clash(strut.a, strut.b, o.a, o.b);
    };
    struts_.for_each_near(dilated(strut.box, kMinStrutStrut), sc.visits, [&](uint32_t i, const Strut& o) {
        if (found == ClashKind::None && !sc.removed(sc.removed_struts, i) && too_close(o))
            found = ClashKind::StrutStrut;
    });
    for (size_t j = index + 1; j < sc.struts.size(); ++j)
        if (too_close(sc.struts[j]))
            return ClashKind::StrutStrut;
    if (found != ClashKind::None)
        return found;

    const auto through = [&](const Panel& p) {
        return boxes_within(strut.box, p.box, 0.0) && !p.has_corner(strut.from) && !p.has_corner(strut.to) &&
               pierces(strut.a, strut.b, p.shape);
    };
    panels_.for_each_near(strut.box, sc.visits, [&](uint32_t i, const Panel& p) {
        if (found == ClashKind::None && !sc.removed(sc.removed_panels, i) && through(p))
            found = ClashKind::StrutFace;
    });
    for (const Panel& p : sc.panels)
        if (through(p))
            return ClashKind::StrutFace;
    return found;
}

ClashKind ClearanceIndex::check_panel(const Panel& panel, Scratch& sc) const
{
    // New struts against new panels were checked with the struts.
    ClashKind found = ClashKind::None;
    struts_.for_each_near(panel.box, sc.visits, [&](uint32_t i, const Strut& s) {
        if (found == ClashKind::None && boxes_within(panel.box, s.box, 0.0) && !sc.removed(sc.removed_struts, i) &&
            !panel.has_corner(s.from) && !panel.has_corner(s.to) && pierces(s.a, s.b, panel.shape))
            found = ClashKind::StrutFace;
    });
    return found;
}

ClashKind ClearanceIndex::check(const LocalChange& change) const { return check(change, *own_); }

ClashKind ClearanceIndex::check(const LocalChange& change, Scratch& sc) const
{
    if (++sc.mark == 0) // wrapped: old marks could match again
    {
        for (auto* marks : {&sc.removed_balls, &sc.removed_struts, &sc.removed_panels})
            std::fill(marks->begin(), marks->end(), 0U);
        sc.mark = 1;
    }
    for (Vertex v : change.removed_nodes())
        mark_all(sc.removed_balls, v.idx(), sc.mark);
    for (Edge e : change.removed_struts())
        mark_all(sc.removed_struts, e.idx(), sc.mark);
    for (Face f : change.removed_faces())
        mark_all(sc.removed_panels, f.idx(), sc.mark);
    sc.balls.clear();
    sc.struts.clear();
    sc.panels.clear();
    for (const ZVec& p : change.added_nodes())
        sc.balls.push_back(make_ball(p));
    for (const NewStrut& st : change.added_struts())
        sc.struts.push_back(make_strut(st.a, st.b));
    for (const NewFace& f : change.added_faces())
        sc.panels.push_back(make_panel(f.view()));

    for (const Ball& b : sc.balls)
        if (const ClashKind k = check_ball(b, sc); k != ClashKind::None)
            return k;
    for (size_t i = 0; i < sc.struts.size(); ++i)
        if (const ClashKind k = check_strut(sc.struts[i], i, sc); k != ClashKind::None)
            return k;
    for (const Panel& p : sc.panels)
        if (const ClashKind k = check_panel(p, sc); k != ClashKind::None)
            return k;
    return ClashKind::None;
}

ClearanceReport ClearanceIndex::audit() const
{
    // Clearances are looked for this far (b0); the rules' minimums are well inside it.
    constexpr double kReach = 1.0;
    constexpr size_t kExamples = 8;
    ClearanceReport r;
    r.ball_ball = r.ball_strut = r.strut_strut = kReach;
    const auto found = [&](ClashKind kind, const Vec3& a, const Vec3& b, double distance) {
        ++r.clashes[static_cast<size_t>(kind)];
        if (r.examples.size() < kExamples)
            r.examples.push_back({kind, 0.5 * (a + b), distance});
    };
    GridVisits visits;
    for (uint32_t i = 0; i < balls_.capacity(); ++i)
    {
        if (!balls_.contains(i))
            continue;
        const Ball& ball = balls_[i];
        balls_.for_each_near(dilated(ball.box, kReach), visits, [&](uint32_t j, const Ball& other) {
            if (j <= i)
                return;
            const double d = (other.p - ball.p).norm();
            r.ball_ball = std::min(r.ball_ball, d);
            if (balls_clash(ball.p, other.p))
                found(ClashKind::BallBall, ball.p, other.p, d);
        });
        struts_.for_each_near(dilated(ball.box, kReach), visits, [&](uint32_t, const Strut& s) {
            if (s.holds(ball.at))
                return;
            const double d = std::sqrt(point_segment_distance_squared(ball.p, s.a, s.b));
            r.ball_strut = std::min(r.ball_strut, d);
            if (ball_strut_clash(ball.p, s.a, s.b))
                found(ClashKind::BallStrut, ball.p, 0.5 * (s.a + s.b), d);
        });
    }
    for (uint32_t i = 0; i < struts_.capacity(); ++i)
    {
        if (!struts_.contains(i))
            continue;
        const Strut& strut = struts_[i];
        struts_.for_each_near(dilated(strut.box, kReach), visits, [&](uint32_t j, const Strut& o) {
            if (j <= i || strut.shares_ball(o))
                return;
            const double d = std::sqrt(segment_segment_distance_squared(strut.a, strut.b, o.a, o.b));
            r.strut_strut = std::min(r.strut_strut, d);
            if (struts_clash(strut.a, strut.b, o.a, o.b))
                found(ClashKind::StrutStrut, 0.5 * (strut.a + strut.b), 0.5 * (o.a + o.b), d);
        });
        panels_.for_each_near(strut.box, visits, [&](uint32_t, const Panel& p) {
            if (!p.has_corner(strut.from) && !p.has_corner(strut.to) && pierces(strut.a, strut.b, p.shape))
                found(ClashKind::StrutFace, 0.5 * (strut.a + strut.b), p.box.center(), 0.0);
        });
    }
    return r;
}

ClearanceReport clearance_report(const ZomeMesh& mesh)
{
    Box3 box;
    for (Vertex v : vertices(mesh))
        box.extend(to_vec3(mesh.position(v)));
    ClearanceIndex index(dilated(box, 1.0));
    index.reset(mesh);
    return index.audit();
}

ClearanceReport clearance_report(const ZomeModel& model)
{
    Box3 box;
    for (const ZVec& p : model.nodes)
        box.extend(to_vec3(p));
    ClearanceIndex index(dilated(box, 1.0));
    index.reset(model);
    return index.audit();
}

std::string clearance_summary(const ClearanceReport& report)
{
    const auto mm = [](double b0) {
        char text[32];
        std::snprintf(text, sizeof text, "%.1f mm", b0 * kMmPerB0);
        return std::string(text);
    };
    if (report.total() == 0)
    {
        // The tightest spot: the part gap (surface to surface) that is smallest.
        const double balls = report.ball_ball - kBallDiameterB0;
        const double ball_strut = report.ball_strut - 0.5 * (kBallDiameterB0 + kStrutThicknessB0);
        const double struts = report.strut_strut - kStrutThicknessB0;
        const double gap = std::min({balls, ball_strut, struts});
        const char* what = gap == balls ? "two balls" : gap == struts ? "two struts" : "a ball and a strut";
        return "no clashes: the closest parts are " + std::string(what) + " " + mm(gap) + " apart";
    }
    static constexpr const char* kWhat[kClashKinds] = {"", "pairs of balls too close", "balls touching a strut",
                                                       "pairs of struts too close", "struts through a face"};
    std::string out = std::to_string(report.total()) + (report.total() == 1 ? " clash:" : " clashes:");
    const char* sep = " ";
    for (int k = 1; k < kClashKinds; ++k)
        if (report.clashes[static_cast<size_t>(k)] > 0)
        {
            out += sep + std::to_string(report.clashes[static_cast<size_t>(k)]) + " " + kWhat[k];
            sep = ", ";
        }
    return out;
}

void ClearanceIndex::forget(const LocalChange& change)
{
    for (Vertex v : change.removed_nodes())
        balls_.erase(v.idx());
    for (Edge e : change.removed_struts())
        struts_.erase(e.idx());
    for (Face f : change.removed_faces())
        panels_.erase(f.idx());
}

void ClearanceIndex::learn(const ZomeMesh& mesh, const LocalChange& change, std::span<const Face> added_faces)
{
    for (const ZVec& p : change.added_nodes())
    {
        const Vertex v = mesh.find_vertex(p);
        if (v.is_valid())
            balls_.insert(v.idx(), make_ball(p));
    }
    for (const NewStrut& s : change.added_struts())
    {
        const Vertex a = mesh.find_vertex(s.a), b = mesh.find_vertex(s.b);
        const Halfedge h = a.is_valid() && b.is_valid() ? mesh.find_halfedge(a, b) : Halfedge();
        if (h.is_valid())
            struts_.insert(ZomeMesh::edge(h).idx(), make_strut(s.a, s.b));
    }
    const auto& faces = change.added_faces();
    for (size_t k = 0; k < faces.size() && k < added_faces.size(); ++k)
        panels_.insert(added_faces[k].idx(), make_panel(faces[k].view()));
}

} // namespace zomeify
