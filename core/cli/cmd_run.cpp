// zomeify run MESH -o OUT [...] (design.md §5): the whole pipeline (run_pipeline: Z0, then the
// annealer) with a one-paragraph summary on stdout, progress on stderr when it is a terminal,
// and the --stats object.
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <unistd.h>

#include "core/assembly/real_size.h"
#include "core/base/errors.h"
#include "core/cli/args.h"
#include "core/cli/commands.h"
#include "core/cli/model_input.h"
#include "core/cli/output_options.h"
#include "core/cli/point_arg.h"
#include "core/cli/run_kits.h"
#include "core/geom/closest_point.h"
#include "core/geom/inside.h"
#include "core/io/model_io.h"
#include "core/io/share_link.h"
#include "core/parts/parts_list.h"
#include "core/pipeline/kit_fit_plan.h"
#include "core/pipeline/pipeline.h"
#include "core/pipeline/run_settings.h"
#include "core/surface/prepare.h"
#include "core/surface/read_mesh.h"
#include "core/zome/real_sizes.h"

namespace zomeify::cli {

namespace {

std::string file_name(const std::string& path)
{
    const size_t slash = path.find_last_of("/\\");
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

// "--operator-weights 1,1,1,1,1,1,1": seven non-negative integers in OperatorKind order.
std::array<uint32_t, 7> operator_weights(const std::string& text)
{
    std::array<uint32_t, 7> w{};
    size_t k = 0, i = 0;
    while (k < w.size())
    {
        size_t j = i;
        uint64_t v = 0;
        while (j < text.size() && j - i < 6 && text[j] >= '0' && text[j] <= '9')
            v = v * 10 + static_cast<uint64_t>(text[j++] - '0');
        const bool last = k + 1 == w.size();
        if (j == i || (last ? j != text.size() : (j >= text.size() || text[j] != ',')))
            throw InvalidInputError("--operator-weights wants 7 integers 0-999999 separated by commas, got '" + text +
                                    "'");
        w[k++] = static_cast<uint32_t>(v);
        i = j + 1;
    }
    uint64_t total = 0;
    for (uint32_t x : w)
        total += x;
    if (total == 0)
        throw InvalidInputError("--operator-weights: at least one weight must be positive");
    return w;
}

// An option of run_settings.h from its flag, within the core's bounds (the page reads the same ones).
double setting(const Args& args, const char* key, double fallback)
{
    const OptionBounds& b = option_bounds(key);
    return b.integer ? static_cast<double>(args.integer(b.flag, static_cast<long long>(fallback),
                                                        static_cast<long long>(b.min), static_cast<long long>(b.max)))
                     : args.number(b.flag, fallback, b.min, b.max);
}

// The longest side of the mesh's bounding box, mesh units.
double longest_side(const TriangleMesh& mesh)
{
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (const Vec3& p : mesh.positions)
        for (int k = 0; k < 3; ++k)
        {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    return std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
}

// The options every front end shares (run_settings.h); "--resolution auto" is the default.
RunSettings run_settings(const Args& args)
{
    RunSettings s;
    if (args.has("--paper-energy"))
        s.energy = paper_energy();
    if (args.value("--resolution") != std::optional<std::string>("auto"))
        s.resolution = static_cast<int>(setting(args, "resolution", s.resolution));
    s.seconds = setting(args, "seconds", s.seconds);
    s.proposals = static_cast<uint64_t>(setting(args, "proposals", static_cast<double>(s.proposals)));
    s.target_nodes = static_cast<long long>(setting(args, "target_nodes", static_cast<double>(s.target_nodes)));
    s.threads = static_cast<int>(setting(args, "threads", s.threads));
    s.seed = static_cast<uint64_t>(setting(args, "seed", static_cast<double>(s.seed)));
    s.initial_only = args.has("--initial-only");
    if (const std::optional<std::string> mirror = args.value("--mirror"))
    {
        if (*mirror != "auto" && *mirror != "off")
            throw InvalidInputError("--mirror wants auto or off, got '" + *mirror + "'");
        s.mirror = *mirror == "auto" ? MirrorMode::Auto : MirrorMode::Off;
    }
    s.energy.w_distance = setting(args, "weights.dist", s.energy.w_distance);
    s.energy.w_orientation = setting(args, "weights.orient", s.energy.w_orientation);
    s.energy.w_fairing = setting(args, "weights.fair", s.energy.w_fairing);
    s.energy.w_complexity = setting(args, "weights.complex", s.energy.w_complexity);
    s.energy.w_surface = setting(args, "weights.surface", s.energy.w_surface);
    s.energy.w_fold = setting(args, "weights.fold", s.energy.w_fold);
    s.check();
    return s;
}

PipelineOptions pipeline_options(const Args& args)
{
    PipelineOptions o = zomeify::pipeline_options(run_settings(args));
    o.b1 = args.number("--b1", 0.0, 0.0, 1e300);
    if (args.has("--b1") && !(o.b1 > 0.0))
        throw InvalidInputError("--b1 must be a positive length in mesh units");
    AnnealOptions& a = o.anneal;
    a.initial_temperature = args.number("--t0", 0.0, 0.0, 1e6);
    if (args.has("--t-min") && args.has("--t-min-ratio"))
        throw InvalidInputError("give either --t-min or --t-min-ratio, not both");
    a.min_temperature = args.number("--t-min", a.min_temperature, 1e-12, 1e6);
    a.t0_spread_factor = args.number("--t0-factor", a.t0_spread_factor, 1e-6, 1e3);
    // An absolute --t-min overrides whatever ratio the options default to.
    a.min_temperature_ratio =
        args.has("--t-min") ? 0.0 : args.number("--t-min-ratio", a.min_temperature_ratio, 0.0, 0.999);
    a.coverage.radius = args.number("--coverage-radius", a.coverage.radius, 0.0, 1e3);
    if (args.has("--operator-weights"))
        a.operator_weights = operator_weights(*args.value("--operator-weights"));
    a.clearance = !args.has("--no-clearance");
    a.refuse_new_fold_overs = !args.has("--allow-fold-overs");
    EnergyOptions& e = a.energy;
    e.surface_cap = args.number("--surface-cap", e.surface_cap, 0.05, 100.0);
    e.surface_spacing = args.number("--surface-spacing", e.surface_spacing, 0.05, 100.0);
    e.surface_zone.f_max = args.number("--surface-zone", e.surface_zone.f_max, 0.0, 1e6);
    return o;
}

// The writers' formats (core/io/model_io), checked before the work so a typo costs nothing.
void check_output_name(const std::string& out)
{
    std::string lower = out;
    for (char& c : lower)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const char* ext : {".zome.json", ".json", ".vef", ".glb", ".obj", ".csv"})
    {
        const std::string e = ext;
        if (lower.size() > e.size() && lower.compare(lower.size() - e.size(), e.size(), e) == 0)
            return;
    }
    throw InvalidInputError("'" + out + "': unknown model format (expected .zome.json, .vef, .glb, .obj or .csv)");
}

// --from MODEL (a model file, or a share link), --near X,Y,Z --radius R.
void continue_options(const Args& args, PipelineOptions& options)
{
    const std::optional<std::string> from = args.value("--from");
    if (!from)
    {
        if (args.has("--near") || args.has("--radius"))
            throw InvalidInputError("--near and --radius fix one spot of a model: give it with --from MODEL");
        return;
    }
    if (args.has("--initial-only") || args.has("--resolution") || args.has("--b1") || args.has("--size-cm") ||
        args.has("--fit-kits"))
        throw InvalidInputError("--from continues a model at its own size: drop --initial-only, --resolution, --b1, "
                                "--size-cm and --fit-kits");
    const bool link = from->find("m=") != std::string::npos && !std::ifstream(*from).good();
    options.from = link ? decode_share_link(*from) : read_model_warning_of_clashes(*from);
    if (args.has("--near") != args.has("--radius"))
        throw InvalidInputError("give --near X,Y,Z and --radius R together");
    if (args.has("--near"))
        options.fix = FixSpot{point_of(*args.value("--near"), "--near"), args.number("--radius", 0.0, 1e-9, 1e300)};
}

// What the summary says of Z0 beyond its counts: cleanup, carving, grids tried, time.
void z0_details(std::ostringstream& s, const PipelineResult& r)
{
    const InitialModelReport& z0 = r.initial.report;
    if (z0.carve.removed > 0)
        s << "; " << z0.carve.removed - z0.carve.restored << " voxels outside the surface carved away";
    if (z0.attempt_used > 0)
        s << "; nudged grid " << z0.attempt_used << " (cell x" << z0.layout.scale_factor << ") used";
    if (z0.attempts > 1)
        s << "; " << z0.attempts << " grids tried";
    if (z0.carve_topology == CarveTopology::Free)
        s << "; carved freely (cells bridging a hole removed) to reach the surface's genus";
    if (z0.centre_sampled)
        s << "; cells taken where their centre is inside the surface (parts too close together for the "
             "touched cells to keep apart) to reach the surface's genus";
    s << std::setprecision(3) << "; " << r.initial_seconds << " s.";
}

std::string summary(const std::string& path, const PipelineResult& r, const std::vector<std::string>& outputs)
{
    const InitialModelReport& z0 = r.initial.report;
    const ZomeModel& m0 = r.initial.model;
    std::ostringstream s;
    s << std::setprecision(4);
    if (r.continued)
        s << "Continued " << file_name(path) << " from a model of " << m0.nodes.size() << " balls and "
          << m0.struts.size() << " struts (genus " << z0.topology.genus << " against the surface's " << r.surface_genus
          << ")"
          << (r.region ? ", changing only the " + std::to_string(nodes_in_region(m0, *r.region)) +
                             " balls near the point given and what joins them"
                       : "")
          << ".";
    else
        s << "Z0 of " << file_name(path) << " at " << r.resolution
          << " cells along the longest side (b1 = " << z0.grid.cell << " mesh units, grid " << z0.grid.dims[0] << "x"
          << z0.grid.dims[1] << "x" << z0.grid.dims[2] << "): " << m0.nodes.size() << " balls, " << m0.struts.size()
          << " B1 struts, " << m0.faces.size() << " quads from " << z0.voxels << " voxels; genus " << z0.topology.genus
          << " against the surface's " << r.surface_genus
          << (z0.topology.genus == r.surface_genus ? " (kept)" : " (NOT kept)") << ". Cleanup removed "
          << z0.repair.removed << " and added " << z0.repair.added << " simple voxels";
    if (!r.continued)
        z0_details(s, r);
    if (r.automatic)
        s << " Resolution chosen automatically: " << r.automatic->message << ".";
    if (r.anneal)
    {
        const AnnealStats& st = r.anneal->stats;
        s << " Annealed " << st.wall_seconds << " s on " << st.threads << (st.threads == 1 ? " thread" : " threads")
          << (st.cancelled ? " (cancelled)" : "") << ": " << st.proposals << " proposals, " << st.commits
          << " commits; E " << std::setprecision(4) << r.anneal->start.total << " -> " << r.model_energy.total << "; "
          << r.model.nodes.size() << " balls, " << r.model.struts.size() << " struts, genus " << r.model_genus << ", "
          << fold_over_summary(r.fold_overs) << "; " << clearance_summary(r.clearance) << "; "
          << fidelity_summary(r.fidelity) << ".";
        if (r.capped)
            s << " " << capacity_capped_text(r.capacity);
        if (r.continued && !r.fix_spot && short_of_target(m0.nodes.size(), r.target_nodes, r.model.nodes.size()))
            s << " It reached " << r.model.nodes.size() << " balls of the " << r.target_nodes
              << " asked: at this size the model cannot " << (r.target_nodes < m0.nodes.size() ? "lose" : "take")
              << " more balls this way (the paper's saturation point).";
        if (r.fix_spot)
            s << " The largest gap within the spot: " << std::setprecision(3) << r.spot_gap_before * kMmPerB0
              << " mm before, " << r.spot_gap_after * kMmPerB0 << " mm after"
              << (r.kept_start ? " (no try made it smaller, so the model is kept as it was)." : ".");
        else if (r.kept_start)
            s << " No model found had a lower energy than the one continued, so it is kept as it was.";
    }
    if (r.mirror)
    {
        s << " " << r.mirror->message;
        if (r.mirror->used && r.anneal)
            s << (r.mirror_mismatch.symmetric()
                      ? " Every change was made with its mirror image: the model maps onto itself."
                      : " The model does NOT map onto itself: " + std::to_string(r.mirror_mismatch.balls) +
                            " balls and " + std::to_string(r.mirror_mismatch.struts) + " struts have no mirror image.");
    }
    s << " Wrote";
    for (const std::string& out : outputs)
        s << " " << out;
    s << ".";
    if (!r.advice.empty())
        s << " Hint: " << r.advice << ".";
    return s.str();
}

} // namespace

int cmd_run(const CommandArgs& argv)
{
    const Args args(argv,
                    {"-o",
                     "--resolution",
                     "--b1",
                     "--target-nodes",
                     "--seconds",
                     "--proposals",
                     "--threads",
                     "--seed",
                     "--stats",
                     "--t0",
                     "--t-min",
                     "--t0-factor",
                     "--t-min-ratio",
                     "--operator-weights",
                     "--coverage-radius",
                     "--w-distance",
                     "--w-orientation",
                     "--w-fairing",
                     "--w-complexity",
                     "--w-surface",
                     "--surface-cap",
                     "--surface-spacing",
                     "--surface-zone",
                     "--w-fold",
                     "--size-cm",
                     "--have",
                     "--from",
                     "--near",
                     "--radius",
                     "--mirror",
                     kObjUnitsOption},
                    {"--initial-only", "--fit-kits", "--within-estimate", "--paper-energy", "--no-clearance",
                     "--allow-fold-overs", "--thicken", kNoFacesFlag});
    args.expect_positional(1, "one mesh file: zomeify run MESH -o OUT");
    const std::vector<std::string> outputs = args.values("-o");
    if (outputs.empty())
        throw InvalidInputError("missing -o OUT");
    if (int(args.has("--resolution")) + int(args.has("--b1")) + int(args.has("--size-cm")) > 1)
        throw InvalidInputError("give one of --resolution, --b1 and --size-cm");
    PipelineOptions options = pipeline_options(args);
    const WriteOptions write = write_options(args);
    for (const std::string& out : outputs)
        check_output_name(out);

    const std::string& path = args.positional()[0];
    const OwnedKits owned = parse_owned_kits(args.value("--have").value_or(""));
    const bool fit = args.has("--fit-kits");
    if (fit && owned.empty())
        throw InvalidInputError("--fit-kits needs --have KITS, the kits you own (e.g. --have creator3)");
    if (fit && args.has("--target-nodes"))
        throw InvalidInputError("give --target-nodes or --fit-kits, not both (--fit-kits chooses the ball count)");
    if (fit && args.has("--initial-only"))
        throw InvalidInputError("--fit-kits needs the annealer: drop --initial-only");
    PrepareOptions prepare;
    prepare.thicken_sheets = args.has("--thicken");
    const PreparedSurface surface = prepare_surface(read_mesh_file(path), prepare);
    if (args.has("--size-cm"))
        options.b1 = b1_for_size_cm(longest_side(surface.mesh), args.number("--size-cm", 0.0, -1e300, 1e300));
    const PartCounts have = kit_contents(owned);
    continue_options(args, options);
    if (!owned.empty() && args.has("--within-estimate"))
        throw InvalidInputError(
            "give --have KITS or --within-estimate, not both (with your kits the run keeps within them)");
    // The kits a person owns bound the run (part_tally.h); or the kits named before it, as the page.
    if (!owned.empty())
        options.anneal.part_limits = part_limits_of(owned);
    options.keep_to_kit_estimate = args.has("--within-estimate");

    PipelineCallbacks callbacks;
    const bool show_progress = isatty(STDERR_FILENO) != 0;
    if (show_progress)
        callbacks.progress = [](const AnnealProgress& p, Annealer&) {
            std::cerr << "\r" << std::fixed << std::setprecision(1) << p.elapsed_seconds << " s  E "
                      << std::setprecision(4) << p.energy.total << "  T " << std::scientific << std::setprecision(2)
                      << p.temperature << std::defaultfloat << "  N " << p.nodes << "  " << p.commits << " commits   "
                      << std::flush;
        };
    // Before annealing (Z0 is known): does a model of the target's size typically fit the kits?
    if (!owned.empty() && !options.initial_only)
        callbacks.initial = [&](const ZomeModel& z0) {
            // The automatic grid comes with its ball target (auto_resolution.h), a size set by the user with Z0's.
            const bool automatic = options.b1 == 0.0 && options.resolution == kAutoResolution;
            const size_t target = options.anneal.target_nodes ? options.anneal.target_nodes
                                  : automatic                 ? target_balls(z0.nodes.size())
                                                              : z0.nodes.size();
            std::cout << estimate_fit_line(target, have) << "\n" << std::flush;
        };

    // --fit-kits: plan a resolution and ball budget, run, check the result's parts, and shrink the
    // budget when it missed (the annealer moves the ball count, so the estimate alone is not enough).
    std::optional<SurfaceProjector> projector;
    std::optional<InsideTest> inside;
    int max_resolution = 0;
    size_t budget = 0;
    if (fit)
    {
        projector.emplace(surface.mesh);
        inside.emplace(*projector);
        max_resolution = fit_max_resolution(args, longest_side(surface.mesh));
        budget = balls_that_fit(have);
    }
    const auto plan_for = [&](size_t balls) {
        return plan_kit_fit(
            surface.mesh, surface.report.genus, [&](const Vec3& p) { return inside->is_inside(p); },
            probe_of(*projector), balls, max_resolution);
    };
    PipelineResult r;
    bool fitted = false;
    for (int attempt = 1;; ++attempt)
    {
        if (fit)
        {
            const KitFitPlan plan = plan_for(budget);
            if (!plan.possible)
                throw InvalidInputError((attempt == 1 ? "" : "after " + std::to_string(attempt - 1) + " tries: ") +
                                        plan.message + " (" + owned_text(owned) + ")");
            std::cout << "Fit my kits (" << owned_text(owned) << "), try " << attempt << " of " << kFitAttempts << ": "
                      << plan.message << ".\n"
                      << std::flush;
            options.b1 = 0.0;
            options.resolution = plan.resolution;
            options.anneal.target_nodes = plan.target_nodes;
        }
        r = run_pipeline(surface.mesh, surface.report.genus, options, callbacks);
        if (show_progress && r.anneal)
            std::cerr << "\n";
        if (!fit)
            break;
        const PartCounts need = part_counts(parts_list(r.model));
        fitted = fits(need, have);
        if (fitted || attempt == kFitAttempts)
            break;
        const size_t next = std::min(shrunk_ball_budget(need, have, r.model.nodes.size()), budget - 1);
        std::cout << "Try " << attempt << " gave " << r.model.nodes.size() << " balls: " << fit_text(need, have)
                  << "; trying again with at most " << next << " balls.\n";
        budget = next;
    }

    const std::string stats = pipeline_stats_json(r);
    r.model.stats_json = pipeline_stats_json(r, -1);
    for (const std::string& out : outputs)
        write_model_file(out, r.model, write);
    if (args.has("--size-cm"))
    {
        const auto size = parts_list(r.model).size_cm;
        std::cout << "Built size " << std::fixed << std::setprecision(1) << size[0] << " x " << size[1] << " x "
                  << size[2] << " cm (asked: longest side " << *args.value("--size-cm") << " cm).\n"
                  << std::defaultfloat;
    }
    if (const auto stats_path = args.value("--stats"))
    {
        std::ofstream f(*stats_path);
        f << stats << "\n";
        if (!f)
            throw IoError("cannot write " + *stats_path);
    }
    std::cout << summary(path, r, outputs) << "\n";
    if (r.kit_estimate)
        std::cout << "Kits named before annealing: " << kits_text(r.kit_estimate->plan.kits)
                  << "; the model's kit plan: " << kits_text(plan_kits(parts_list(r.model)).kits) << ".\n";
    if (!owned.empty() && !options.initial_only)
    {
        const PartsList parts = parts_list(r.model);
        const PartCounts need = part_counts(parts);
        std::cout << "Your kits (" << owned_text(owned) << "): the model (" << parts.balls << " balls, "
                  << parts.strut_count << " struts) " << (fits(need, have) ? "fits them" : fit_text(need, have))
                  << ".\n";
        if (fit && !fitted)
        {
            // The nearest smaller size the estimate expects to fit; not run, so it says so.
            const KitFitPlan next = plan_for(std::min(shrunk_ball_budget(need, have, parts.balls), budget - 1));
            std::cout << "Does not fit after " << kFitAttempts << " tries. "
                      << (next.possible ? "The nearest smaller size expected to fit (not yet run): --resolution " +
                                              std::to_string(next.resolution) + " --target-nodes " +
                                              std::to_string(next.target_nodes) + " (" + next.message + ")."
                                        : "No smaller size is expected to fit: " + next.message + ".")
                      << "\n";
        }
    }
    return 0;
}

} // namespace zomeify::cli
