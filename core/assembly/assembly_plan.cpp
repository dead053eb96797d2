// The planner is a greedy walk over the strut graph: the next ball is the one that closes the most
// struts onto what stands (two or more make a triangle or a braced corner), then the lowest. A ball
// brings every strut to balls already placed, so each strut lands in exactly one step and the build
// is one piece after every step. Building both halves alike, a ball's mirror image joins it in its step:
// the placed set stays symmetric, so the image attaches where the ball does.
#include "core/assembly/assembly_plan.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <numeric>

#include "core/base/errors.h"

namespace zomeify {

namespace {

struct Link
{
    uint32_t ball;
    uint32_t strut;
};

using Adjacency = std::vector<std::vector<Link>>;

Adjacency adjacency(const ZomeModel& model)
{
    if (model.nodes.empty())
        throw InvalidInputError("the model has no balls; there is nothing to build");
    Adjacency adj(model.nodes.size());
    for (uint32_t s = 0; s < model.struts.size(); ++s)
    {
        const auto [a, b] = model.struts[s];
        if (a >= model.nodes.size() || b >= model.nodes.size() || a == b)
            throw InvalidInputError("strut " + std::to_string(s) + " does not join two balls of the model");
        adj[a].push_back({b, s});
        adj[b].push_back({a, s});
    }
    // Neighbours in the order of their exact positions, so that the plan depends on the shape alone,
    // not on how a file or a share link numbers the balls.
    for (auto& links : adj)
        std::sort(links.begin(), links.end(),
                  [&](const Link& x, const Link& y) { return model.nodes[x.ball].c < model.nodes[y.ball].c; });
    return adj;
}

//! Whether ball a comes before ball b among equals: by exact position, never by index.
bool before(const ZomeModel& model, uint32_t a, uint32_t b) { return model.nodes[a].c < model.nodes[b].c; }

uint32_t lowest_ball(const ZomeModel& model, const std::vector<double>& h)
{
    uint32_t best = 0;
    for (uint32_t v = 1; v < h.size(); ++v)
        if (h[v] < h[best] || (h[v] == h[best] && before(model, v, best)))
            best = v;
    return best;
}

//! Cuts a sequence of ball placements into steps and records struts and attachments.
class StepCutter
{
public:
    StepCutter(const Adjacency& adj, const PlanOptions& options)
        : adj_(adj), options_(options), step_of_(adj.size(), -1)
    {
    }

    bool placed(uint32_t v) const { return step_of_[v] >= 0; }
    //! Parts that placing v brings: the ball and its struts to placed balls.
    int cost(uint32_t v) const
    {
        int c = 1;
        for (const Link& l : adj_[v])
            c += placed(l.ball);
        return c;
    }
    int parts_in_step() const { return parts_; }
    bool step_full_for(uint32_t v) const { return step_full_for_parts(cost(v)); }
    //! Whether the open step should close before a placement that brings `parts` parts.
    bool step_full_for_parts(int parts) const
    {
        return parts_ >= options_.min_parts || (parts_ > 0 && parts_ + parts > options_.max_parts);
    }
    //! A ball of the open step with fewer than two struts so far.
    bool is_weak(uint32_t v) const { return step_of_[v] == current() && held_[v] < 2; }
    bool has_weak() const
    {
        if (steps_.empty())
            return false;
        for (uint32_t v : steps_.back().balls)
            if (held_[v] < 2)
                return true;
        return false;
    }

    void close_step() { parts_ = 0; }

    void place(uint32_t v)
    {
        if (parts_ == 0)
            steps_.emplace_back();
        BuildStep& step = steps_.back();
        step_of_[v] = current();
        held_.resize(adj_.size(), 0);
        step.balls.push_back(v);
        parts_ += 1;
        for (const Link& l : adj_[v])
        {
            if (!placed(l.ball) || l.ball == v)
                continue;
            step.struts.push_back(l.strut);
            ++held_[v];
            ++held_[l.ball];
            ++parts_;
            if (step_of_[l.ball] < current())
                step.attach.push_back(l.ball);
        }
    }

    std::vector<BuildStep> finish()
    {
        for (BuildStep& s : steps_)
        {
            std::sort(s.attach.begin(), s.attach.end());
            s.attach.erase(std::unique(s.attach.begin(), s.attach.end()), s.attach.end());
        }
        return std::move(steps_);
    }

private:
    int current() const { return static_cast<int>(steps_.size()) - 1; }

    const Adjacency& adj_;
    const PlanOptions& options_;
    std::vector<int> step_of_;
    std::vector<int> held_;
    std::vector<BuildStep> steps_;
    int parts_ = 0;
};

void require_one_piece(const ZomeModel& model, size_t reached)
{
    if (reached != model.nodes.size())
        throw InvalidInputError("the model is not one piece (" + std::to_string(model.nodes.size() - reached) +
                                " balls are not joined to the lowest ball); a build plan needs one connected model");
}

//! The first balls of a plan that builds both halves alike: the start, a shortest path of struts
//! to its image, then the images of the path's balls: a symmetric set, each ball joined to one before
//! it (a ball on the plane is a path of one). Empty when the image cannot be reached.
std::vector<uint32_t> symmetric_seed(const Adjacency& adj, const std::vector<uint32_t>& image, uint32_t start)
{
    std::vector<int64_t> previous(adj.size(), -1);
    previous[start] = start;
    std::deque<uint32_t> queue{start};
    while (!queue.empty() && previous[image[start]] < 0)
    {
        const uint32_t v = queue.front();
        queue.pop_front();
        for (const Link& l : adj[v])
            if (previous[l.ball] < 0)
            {
                previous[l.ball] = v;
                queue.push_back(l.ball);
            }
    }
    if (previous[image[start]] < 0)
        return {};
    std::vector<uint32_t> path{image[start]};
    while (path.back() != start)
        path.push_back(static_cast<uint32_t>(previous[path.back()]));
    std::reverse(path.begin(), path.end());
    std::vector<uint32_t> seed = path;
    for (size_t i = 1; i + 1 < path.size(); ++i)
        seed.push_back(image[path[i]]); // joined to the image of the ball before it, already in the seed
    return seed;
}

//! Each ball's mirror image under options.mirror (identity without one); throws for a plane the
//! planner cannot pair on.
std::vector<uint32_t> pairing(const ZomeModel& model, const PlanOptions& options)
{
    std::vector<uint32_t> image(model.nodes.size());
    std::iota(image.begin(), image.end(), 0u);
    if (!options.mirror)
        return image;
    if (options.mirror->axis == options.up.axis)
        throw InvalidInputError("the halves cannot be built alike about a plane across the up axis");
    const std::optional<std::vector<uint32_t>> mapped = mirror_ball_images(model, *options.mirror);
    if (!mapped || !mirror_mismatch(model, *options.mirror).symmetric())
        throw InvalidInputError("the model does not map onto itself about that plane; its halves differ");
    return *mapped;
}

BuildPlan finish_plan(const ZomeModel& model, const PlanOptions& options, std::vector<BuildStep> steps)
{
    BuildPlan plan;
    plan.up = options.up;
    plan.mirror = options.mirror;
    plan.steps = std::move(steps);
    plan.figures = plan_figures(model, plan.steps, options.up);
    return plan;
}

} // namespace

UpAxis parse_up_axis(const std::string& text)
{
    std::string t = text;
    UpAxis up;
    if (!t.empty() && (t[0] == '+' || t[0] == '-'))
    {
        up.sign = t[0] == '-' ? -1 : 1;
        t.erase(0, 1);
    }
    if (t != "x" && t != "y" && t != "z")
        throw InvalidInputError("up axis must be x, y or z with an optional sign (e.g. -z), not '" + text + "'");
    up.axis = t[0] - 'x';
    return up;
}

std::vector<double> ball_heights(const ZomeModel& model, UpAxis up)
{
    std::vector<double> h(model.nodes.size());
    for (size_t i = 0; i < h.size(); ++i)
        h[i] = up.sign * model.nodes[i].coord(up.axis);
    return h;
}

std::optional<LatticeMirror> building_mirror(const ZomeModel& model, UpAxis up)
{
    const std::optional<ModelMirror> own = model_mirror(model);
    if (!own)
        return std::nullopt;
    std::vector<int> axes{own->mirror.axis};
    for (int axis = 0; axis < 3; ++axis)
        if (axis != own->mirror.axis)
            axes.push_back(axis);
    for (int axis : axes)
        if (axis != up.axis)
            if (const LatticeMirror plane = middle_plane(model, axis); mirror_mismatch(model, plane).symmetric())
                return plane;
    return std::nullopt;
}

namespace {

//! The greedy walk from the balls of `seed` (placed first, as one step), each next ball with its image.
std::vector<BuildStep> walk(const ZomeModel& model, const Adjacency& adj, const std::vector<uint32_t>& image,
                            const std::vector<double>& h, const PlanOptions& sizes, const std::vector<uint32_t>& seed)
{
    StepCutter cut(adj, sizes);
    std::vector<int> held(adj.size(), 0); // struts from each unplaced ball to placed balls
    size_t placed = 0;
    auto place = [&](uint32_t v) {
        cut.place(v);
        ++placed;
        for (const Link& l : adj[v])
            ++held[l.ball];
    };
    for (uint32_t v : seed)
        if (!cut.placed(v))
            place(v);
    // Parts that placing v (and its image, which the placed set's symmetry lets attach too) bring.
    auto parts_of = [&](uint32_t v) {
        int parts = cut.cost(v);
        if (image[v] != v)
        {
            parts += cut.cost(image[v]);
            for (const Link& l : adj[v])
                parts += l.ball == image[v]; // the strut across the plane comes with the image
        }
        return parts;
    };
    while (placed < adj.size())
    {
        // Score: one bracing strut is worth two b0 of height; a lone strut (a ball that dangles)
        // costs three more; a strut that braces a dangling ball of this step is worth two.
        double best_score = std::numeric_limits<double>::infinity();
        uint32_t best = 0;
        bool best_braces = false;
        for (uint32_t v = 0; v < adj.size(); ++v)
        {
            if (cut.placed(v) || held[v] == 0)
                continue;
            bool braces = false;
            for (const Link& l : adj[v])
                braces = braces || cut.is_weak(l.ball);
            const int k = std::min(held[v], 4);
            const double score = h[v] - 2.0 * k + (k < 2 ? 3.0 : 0.0) - (braces ? 2.0 : 0.0);
            // Equal heights give equal scores exactly (same coordinates, same arithmetic).
            if (score < best_score || (score == best_score && before(model, v, best)))
            {
                best_score = score;
                best = v;
                best_braces = braces;
            }
        }
        if (best_score == std::numeric_limits<double>::infinity())
            break;
        // Keep a step open past its size while its last ball dangles and the next one braces it.
        const int parts = parts_of(best);
        const bool keep_open = best_braces && cut.parts_in_step() + parts <= sizes.max_parts;
        if (cut.step_full_for_parts(parts) && !keep_open)
            cut.close_step();
        place(best);
        if (!cut.placed(image[best]))
            place(image[best]);
    }
    require_one_piece(model, placed);
    return cut.finish();
}

//! The lowest ball on the mirror plane or joined to its image (one ball or one strut across the
//! middle); adj.size() when there is none.
uint32_t lowest_middle_ball(const ZomeModel& model, const Adjacency& adj, const std::vector<uint32_t>& image,
                            const std::vector<double>& h)
{
    uint32_t middle = static_cast<uint32_t>(adj.size());
    for (uint32_t v = 0; v < adj.size(); ++v)
    {
        bool across = image[v] == v;
        for (const Link& l : adj[v])
            across = across || l.ball == image[v];
        if (across && (middle == adj.size() || h[v] < h[middle] || (h[v] == h[middle] && before(model, v, middle))))
            middle = v;
    }
    return middle;
}

} // namespace

BuildPlan plan_assembly(const ZomeModel& model, const PlanOptions& options)
{
    const Adjacency adj = adjacency(model);
    const std::vector<uint32_t> image = pairing(model, options);
    const std::vector<double> h = ball_heights(model, options.up);
    const uint32_t lowest = lowest_ball(model, h);
    if (!options.mirror)
        return finish_plan(model, options, walk(model, adj, image, h, options, {lowest}));
    // Building both halves alike, a step is the same few parts on each side: twice the parts. The
    // seed is a symmetric piece: from the middle (a ball on the plane or a strut across it) or from the
    // lowest ball with a path to its image (a chain that may dangle); the plan with the smaller
    // overhang is kept, the middle's on a tie.
    PlanOptions sizes = options;
    sizes.min_parts *= 2;
    sizes.max_parts *= 2;
    std::vector<uint32_t> seed = symmetric_seed(adj, image, lowest);
    if (seed.empty())
        seed = {lowest}; // the image is in another piece: require_one_piece says so
    BuildPlan plan = finish_plan(model, options, walk(model, adj, image, h, sizes, seed));
    if (const uint32_t middle = lowest_middle_ball(model, adj, image, h); middle < adj.size() && middle != lowest)
    {
        BuildPlan from_middle =
            finish_plan(model, options, walk(model, adj, image, h, sizes, symmetric_seed(adj, image, middle)));
        if (from_middle.figures.max_overhang_b0 <= plan.figures.max_overhang_b0)
            plan = std::move(from_middle);
    }
    return plan;
}

BuildPlan plan_breadth_first(const ZomeModel& model, const PlanOptions& options)
{
    const Adjacency adj = adjacency(model);
    StepCutter cut(adj, options);
    std::vector<char> seen(adj.size(), 0);
    const uint32_t start = lowest_ball(model, ball_heights(model, options.up));
    std::deque<uint32_t> queue{start};
    seen[start] = 1;
    size_t placed = 0;
    while (!queue.empty())
    {
        const uint32_t v = queue.front();
        queue.pop_front();
        if (cut.step_full_for(v))
            cut.close_step();
        cut.place(v);
        ++placed;
        for (const Link& l : adj[v])
            if (!seen[l.ball])
            {
                seen[l.ball] = 1;
                queue.push_back(l.ball);
            }
    }
    require_one_piece(model, placed);
    return finish_plan(model, options, cut.finish());
}

PlanFigures plan_figures(const ZomeModel& model, const std::vector<BuildStep>& steps, UpAxis up)
{
    const std::vector<double> h = ball_heights(model, up);
    std::vector<int> step_of(model.nodes.size(), -1);
    for (size_t s = 0; s < steps.size(); ++s)
        for (uint32_t v : steps[s].balls)
            step_of[v] = static_cast<int>(s);
    std::vector<int> held(model.nodes.size(), 0);
    PlanFigures f;
    f.steps = steps.size();
    size_t braced_steps = 0;
    for (size_t s = 0; s < steps.size(); ++s)
    {
        for (uint32_t si : steps[s].struts)
            for (uint32_t v : model.struts[si])
                ++held[v];
        bool braced = true;
        for (uint32_t v : steps[s].balls)
            braced = braced && held[v] >= 2;
        // Dangling balls: a strut joined one of them since, so count over all balls built so far.
        size_t dangling = 0;
        for (size_t v = 0; v < held.size(); ++v)
            dangling += step_of[v] >= 0 && step_of[v] <= static_cast<int>(s) && held[v] == 1;
        f.max_dangling = std::max(f.max_dangling, dangling);
        braced_steps += braced;
    }
    // Overhang: a ball's support is the highest lower ball a strut joins it to by the end of its step.
    std::vector<double> support(model.nodes.size(), -std::numeric_limits<double>::infinity());
    for (const auto& st : model.struts)
    {
        const uint32_t a = st[0], b = st[1];
        if (h[a] < h[b] - 1e-9 && step_of[a] <= step_of[b])
            support[b] = std::max(support[b], h[a]);
        if (h[b] < h[a] - 1e-9 && step_of[b] <= step_of[a])
            support[a] = std::max(support[a], h[b]);
    }
    for (size_t v = 0; v < support.size(); ++v)
        if (std::isfinite(support[v]))
            f.max_overhang_b0 = std::max(f.max_overhang_b0, h[v] - support[v]);
    f.two_strut_share = steps.empty() ? 0.0 : double(braced_steps) / double(steps.size());
    return f;
}

std::string check_plan(const ZomeModel& model, const BuildPlan& plan)
{
    const size_t n = model.nodes.size();
    std::vector<int> step_of(n, -1), strut_step(model.struts.size(), -1);
    std::vector<uint32_t> parent(n);
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](uint32_t v) {
        while (parent[v] != v)
            v = parent[v] = parent[parent[v]];
        return v;
    };
    size_t built = 0;
    for (size_t s = 0; s < plan.steps.size(); ++s)
    {
        const BuildStep& step = plan.steps[s];
        if (step.balls.empty() && step.struts.empty())
            return "step " + std::to_string(s + 1) + " is empty";
        for (uint32_t v : step.balls)
        {
            if (v >= n || step_of[v] >= 0)
                return "ball " + std::to_string(v) + " is out of range or in two steps";
            step_of[v] = static_cast<int>(s);
            ++built;
        }
        for (uint32_t si : step.struts)
        {
            if (si >= model.struts.size() || strut_step[si] >= 0)
                return "strut " + std::to_string(si) + " is out of range or in two steps";
            strut_step[si] = static_cast<int>(s);
            const auto [a, b] = model.struts[si];
            if (step_of[a] < 0 || step_of[b] < 0)
                return "strut " + std::to_string(si) + " in step " + std::to_string(s + 1) +
                       " has a ball not yet built";
            parent[find(a)] = find(b);
        }
        // One piece after every step: every built ball joined to the first one.
        const uint32_t root = find(plan.steps[0].balls.at(0));
        for (uint32_t v = 0; v < n; ++v)
            if (step_of[v] >= 0 && find(v) != root)
                return "after step " + std::to_string(s + 1) + " ball " + std::to_string(v) +
                       " is not joined to the rest";
    }
    if (built != n)
        return std::to_string(n - built) + " balls are in no step";
    if (plan.mirror)
    {
        const std::optional<std::vector<uint32_t>> image = mirror_ball_images(model, *plan.mirror);
        if (!image)
            return "the model does not map onto itself about the plan's plane";
        for (size_t s = 0; s < plan.steps.size(); ++s)
            for (uint32_t v : plan.steps[s].balls)
                if (step_of[(*image)[v]] != static_cast<int>(s))
                    return "ball " + std::to_string(v) + " of step " + std::to_string(s + 1) +
                           " is not built with its mirror image";
        std::map<std::pair<uint32_t, uint32_t>, size_t> strut_index;
        for (size_t si = 0; si < model.struts.size(); ++si)
            strut_index[std::minmax(model.struts[si][0], model.struts[si][1])] = si;
        for (size_t si = 0; si < model.struts.size(); ++si)
        {
            const auto it = strut_index.find(std::minmax((*image)[model.struts[si][0]], (*image)[model.struts[si][1]]));
            if (it == strut_index.end() || strut_step[it->second] != strut_step[si])
                return "strut " + std::to_string(si) + " is not built with its mirror image";
        }
    }
    for (size_t si = 0; si < strut_step.size(); ++si)
        if (strut_step[si] < 0)
            return "strut " + std::to_string(si) + " is in no step";
    return {};
}

} // namespace zomeify
