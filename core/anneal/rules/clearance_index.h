#pragma once
//! \file clearance_index.h
//! Physical validity as an operator rule (design.md §3.8, clearance_rules.h): the annealer refuses
//! every commit that would leave two balls too close, a ball too close to a strut it does not
//! hold, two struts sharing no ball too close (a bow-tie quad among them), or a strut passing
//! through a face it shares no ball with. Only the change's new elements can create a clash, so
//! they are checked against the elements near them, found through grids of the model's balls,
//! struts and faces that the commits keep up to date. A model that starts with clashes keeps them
//! until some change removes them.
//!
//! Not thread-safe: the annealer calls it inside the commit section.

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/anneal/element_grid.h"
#include "core/anneal/energy/face_shape.h"
#include "core/anneal/energy/local_change.h"
#include "core/anneal/fixed_list.h"
#include "core/mesh/zome_mesh.h"
#include "core/zome/model.h"

namespace zomeify {

//! What a change would break.
enum class ClashKind : uint8_t
{
    None,
    BallBall,   //!< two balls closer than kMinBallBall
    BallStrut,  //!< a ball closer than kMinBallStrut to a strut it does not hold
    StrutStrut, //!< two struts sharing no ball closer than kMinStrutStrut
    StrutFace,  //!< a strut through a face it shares no ball with
};
inline constexpr int kClashKinds = 5;
const char* clash_name(ClashKind kind) noexcept;

//! One clash found in a model: its kind and where (b0 units, the model's own coordinates).
struct Clash
{
    ClashKind kind = ClashKind::None;
    Vec3 where = Vec3::Zero(); //!< midway between the two parts
    double distance = 0.0;     //!< between them (b0; 0 for a strut through a face)
};

//! Every clash of a whole model, and the smallest clearance of each kind (b0): ball centres, ball
//! centre to a strut it does not hold, struts sharing no ball. A clearance is only looked for up to
//! about 1 b0; none found nearer reads as that limit.
struct ClearanceReport
{
    std::array<size_t, kClashKinds> clashes{}; //!< per ClashKind (index 0 unused)
    double ball_ball = 0.0, ball_strut = 0.0, strut_strut = 0.0;
    std::vector<Clash> examples; //!< the first few, for messages
    size_t total() const noexcept
    {
        size_t n = 0;
        for (size_t c : clashes)
            n += c;
        return n;
    }
};

class ClearanceIndex
{
public:
    //! Grids covering `domain` (b0 units; elements outside it still count, in the border cells).
    explicit ClearanceIndex(const Box3& domain);

    //! Indexes every element of `mesh` (also after a compaction renumbered them).
    void reset(const ZomeMesh& mesh);
    //! Indexes a model as it is (balls, struts, and faces if it has them), valid or not.
    void reset(const ZomeModel& model);
    //! One thread's scratch for check() (the change's new elements, marks of its removed ones).
    struct Scratch;
    //! The first clash that applying `change` would create, or None. Only reads the grids, so any
    //! number of threads may check at once, each with its own scratch, while none forgets or learns.
    ClashKind check(const LocalChange& change, Scratch& scratch) const;
    //! The same with the index's own scratch (one thread).
    ClashKind check(const LocalChange& change) const;
    //! Keeps the grids in step with an applied change: call forget() with the mesh before
    //! apply_proposal, and learn() after it with the new faces' handles (change.added_faces() order).
    void forget(const LocalChange& change);
    void learn(const ZomeMesh& mesh, const LocalChange& change, std::span<const Face> added_faces);

    //! Every clash among the indexed elements (each pair once), and the smallest clearances.
    ClearanceReport audit() const;

    struct Ball
    {
        Vec3 p;
        ZVec at;
        Box3 box;
    };
    struct Strut
    {
        Vec3 a, b;
        ZVec from, to;
        Box3 box;
        bool holds(const ZVec& p) const noexcept { return p == from || p == to; }
        bool shares_ball(const Strut& o) const noexcept { return holds(o.from) || holds(o.to); }
    };
    struct Panel
    {
        FaceShape shape;
        std::array<ZVec, 4> corners{};
        int size = 0;
        Box3 box;
        bool has_corner(const ZVec& p) const noexcept;
    };
    struct Scratch
    {
        FixedList<Ball, LocalChange::kMaxNodes> balls;
        FixedList<Strut, LocalChange::kMaxStruts> struts;
        FixedList<Panel, LocalChange::kMaxFaces> panels;
        std::vector<uint32_t> removed_balls, removed_struts, removed_panels;
        uint32_t mark = 0;
        GridVisits visits;
        bool removed(const std::vector<uint32_t>& marks, uint32_t index) const noexcept
        {
            return index < marks.size() && marks[index] == mark;
        }
    };

private:
    static Ball make_ball(const ZVec& p);
    static Strut make_strut(const ZVec& a, const ZVec& b);
    static Panel make_panel(std::span<const ZVec> corners);

    ClashKind check_ball(const Ball& ball, Scratch& s) const;
    ClashKind check_strut(const Strut& strut, size_t index, Scratch& s) const;
    ClashKind check_panel(const Panel& panel, Scratch& s) const;

    ElementGrid<Ball> balls_;
    ElementGrid<Strut> struts_;
    ElementGrid<Panel> panels_;
    mutable std::unique_ptr<Scratch> own_ = std::make_unique<Scratch>();
};

//! The clearance report of a whole model (a model without faces is checked for ball and strut
//! clearances only).
ClearanceReport clearance_report(const ZomeMesh& mesh);
ClearanceReport clearance_report(const ZomeModel& model);

//! One line for users, in millimetres at real size: "no clashes; the closest parts are two struts
//! 4.1 mm apart" or "3 clashes: 2 pairs of balls too close, 1 strut through a face".
std::string clearance_summary(const ClearanceReport& report);

} // namespace zomeify
