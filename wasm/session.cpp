#include "wasm/session.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/assembly/assembly_plan.h"
#include "core/assembly/plan_report.h"
#include "core/assembly/real_size.h"
#include "core/assembly/steps_html.h"
#include "core/base/errors.h"
#include "core/base/stopwatch.h"
#include "core/geom/closest_point.h"
#include "core/geom/inside.h"
#include "core/io/model_io.h"
#include "core/io/obj_export.h"
#include "core/io/share_link.h"
#include "core/mesh/model_convert.h"
#include "core/mesh/validate.h"
#include "core/parts/kit_fit.h"
#include "core/parts/kits.h"
#include "core/parts/mirror_halves.h"
#include "core/parts/parts_list.h"
#include "core/parts/parts_report.h"
#include "core/pipeline/kit_fit_plan.h"
#include "core/pipeline/pipeline.h"
#include "core/pipeline/z0_choice.h"
#include "core/surface/read_mesh.h"
#include "core/surface/report_text.h"
#include "core/voxel/advisor.h"
#include "core/voxel/auto_resolution.h"
#include "core/voxel/carve.h"
#include "core/voxel/initial_model.h"
#include "core/voxel/voxel_grid.h"
#include "core/zome/real_sizes.h"
#include "core/zome/slots.h"

namespace zomeify::web {

//! The prepared input surface and the queries built on it (immutable once loaded).
struct LoadedSurface
{
    TriangleMesh mesh;
    SurfaceReport report;
    double area = 0.0; //!< mesh units² (surface_capacity)
    std::unique_ptr<SurfaceProjector> projector;
    std::unique_ptr<InsideTest> inside;

    InsidePredicate is_inside() const
    {
        return [this](const Vec3& p) { return inside->is_inside(p); };
    }
};

namespace {

std::string error_json(const std::string& message) { return nlohmann::json{{"ok", false}, {"error", message}}.dump(); }

std::string extension_of(const std::string& name)
{
    const size_t dot = name.find_last_of('.');
    std::string ext = dot == std::string::npos ? "" : name.substr(dot);
    for (char& c : ext)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

bool is_model_file_name(const std::string& name)
{
    const std::string ext = extension_of(name);
    return ext == ".json" || ext == ".vef";
}

//! Runs `body`, turning every exception into {ok:false, error} (bad input must never escape).
template <class F>
std::string guarded(F&& body)
{
    try
    {
        return body();
    }
    catch (const std::bad_alloc&)
    {
        return error_json("out of memory: the input is too large for the browser");
    }
    catch (const std::exception& e)
    {
        return error_json(e.what());
    }
}

// The kits for a run from Z0 (kit_estimate.h): "kit_plan" the kits named, which the run keeps
// within, and "kit_plan_low" the plan of the quick pass's own mix ("typically").
nlohmann::json kits_estimate(const KitEstimate& kits)
{
    size_t count = 0;
    for (const auto& [kit, n] : kits.plan.kits)
        count += n;
    const KitPlan low = plan_kits(kits.quick);
    return {{"kits", count},
            {"kit_plan", kits_text(kits.plan.kits)},
            {"kit_plan_parts", kits.plan.parts_bought},
            {"kit_plan_low", kits_text(low.kits)},
            {"kit_plan_low_parts", low.parts_bought},
            {"kit_seconds", kits.seconds}};
}

std::string owned_text(const OwnedKits& owned)
{
    std::string s;
    for (const auto& [kit, n] : owned)
        s += (s.empty() ? "" : " + ") + std::to_string(n) + " x " + std::string(kit->name);
    return s;
}

// The longest side of the mesh's bounding box, the length --size-cm scales.
double longest_side(const TriangleMesh& mesh)
{
    const auto [lo, hi] = bounding_box(mesh);
    return (hi - lo).maxCoeff();
}

} // namespace

Session::Session() = default;

Session::~Session()
{
    cancel();
    if (run_thread_.joinable())
        run_thread_.join();
}

bool Session::busy() const { return run_ && !run_->get().finished(); }

std::string Session::load_mesh(const std::string& bytes, const std::string& file_name, bool thicken)
{
    return guarded([&] {
        if (busy())
            throw InvalidInputError("a run is in progress; cancel it first");
        if (is_model_file_name(file_name))
            return load_model(bytes, file_name);
        if (!is_mesh_file_name(file_name))
            throw InvalidInputError(file_name + ": unknown file type (use .obj .stl .ply .off .gltf .glb, or a "
                                                ".zome.json / .vef model)");
        if (bytes.empty())
            throw InvalidInputError(file_name + ": the file is empty");
        const std::span<const uint8_t> data(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
        PolygonSoup soup = read_mesh_buffer(data, file_name);
        PrepareOptions prepare;
        prepare.thicken_sheets = thicken;
        PreparedSurface prepared = prepare_surface(soup, prepare);
        auto loaded = std::make_unique<LoadedSurface>();
        loaded->mesh = prepared.mesh;
        loaded->report = prepared.report;
        loaded->area = surface_area(prepared.mesh);
        loaded->projector = std::make_unique<SurfaceProjector>(prepared.mesh);
        loaded->inside = std::make_unique<InsideTest>(*loaded->projector);
        surface_ = std::move(loaded);
        named_kits_.reset(); // they were for the last shape
        surface_name_ = file_name;
        nlohmann::json out;
        out["ok"] = true;
        out["kind"] = "mesh";
        out["report"] = nlohmann::json::parse(surface_report_json(surface_->report, file_name));
        return out.dump();
    });
}

std::string Session::load_model(const std::string& bytes, const std::string& file_name)
{
    return guarded([&] {
        if (busy())
            throw InvalidInputError("a run is in progress; cancel it first");
        if (bytes.empty())
            throw InvalidInputError(file_name + ": the file is empty");
        std::vector<std::string> notes;
        ZomeModel m = read_model_buffer(bytes, file_name, &notes);
        parts_list(m); // rejects struts that are not Zome vectors before the model is shown
        set_model(std::move(m), "file");
        return nlohmann::json{{"ok", true}, {"kind", "model"}, {"notes", notes}}.dump();
    });
}

std::string Session::open_link(const std::string& link)
{
    return guarded([&] {
        if (busy())
            throw InvalidInputError("a run is in progress; cancel it first");
        ZomeModel m = decode_share_link(link);
        set_model(std::move(m), "link");
        return nlohmann::json{{"ok", true}, {"kind", "model"}}.dump();
    });
}

namespace {

// Z0 of the loaded surface at `resolution`, and what the page shows of it: counts, genus against
// the surface's, and the finished model's size and the kits for a run towards `target` balls (0:
// Z0's count), which are kept for the run that follows (Session::named_kits_).
std::tuple<InitialModel, nlohmann::json, KitEstimate>
z0_estimate(const LoadedSurface& s, int resolution, double b1 = 0.0, size_t target = 0, bool with_kits = true)
{
    // Z0 as a run builds it (z0_choice.h), so the estimate's ball count is the run's starting model.
    InitialModel z0 =
        build_initial_model(s.mesh, s.is_inside(), run_z0_options(*s.projector, s.report.genus, resolution, b1));
    nlohmann::json out;
    out["ok"] = true;
    out["resolution"] = resolution;
    out["nodes"] = z0.model.nodes.size();
    out["struts"] = z0.model.struts.size();
    out["valid"] = z0.report.valid;
    out["genus"] = z0.report.topology.genus;
    out["surface_genus"] = s.report.genus;
    out["kept"] = z0.report.valid && z0.report.topology.genus == s.report.genus;
    out["seconds"] = z0.report.seconds;
    out["z0_seconds"] = z0.report.seconds;              // kept when `seconds` is the automatic search's time
    out["size_mm"] = z0_built_size_cm(z0.model) * 10.0; // the finished model's size at real scale
    if (!with_kits)
        return {std::move(z0), std::move(out), KitEstimate{}};
    KitEstimate kits = estimate_kits(*s.projector, z0, target);
    out.update(kits_estimate(kits));
    return {std::move(z0), std::move(out), std::move(kits)};
}

// A ball target from the page: 0 (none: Z0's count) or a whole number in the run's bounds.
size_t target_of(double target)
{
    if (!(target >= 0.0 && target <= 1e6) || target != std::floor(target))
        throw InvalidInputError("the ball target must be a whole number between 0 and 1,000,000");
    return static_cast<size_t>(target);
}

} // namespace

const LoadedSurface& Session::idle_surface() const
{
    if (!surface_)
        throw InvalidInputError("no mesh loaded");
    if (busy())
        throw InvalidInputError("a run is in progress");
    return *surface_;
}

std::string Session::estimate(int resolution, double target, bool with_kits)
{
    return guarded([&] {
        const LoadedSurface& s = idle_surface();
        if (resolution < kMinResolution || resolution > kMaxResolution)
            throw InvalidInputError("resolution must be between " + std::to_string(kMinResolution) + " and " +
                                    std::to_string(kMaxResolution) + " cells");
        const size_t balls = target_of(target);
        auto [z0, out, kits] = z0_estimate(s, resolution, 0.0, balls, with_kits);
        if (with_kits)
            named_kits_ = NamedKits{resolution, 0.0, balls, std::move(kits)};
        const GenusAdvice advice =
            z0.report.valid ? genus_advice(s.mesh, s.report.genus, s.is_inside(), resolution, z0.report.topology.genus,
                                           run_z0_options(*s.projector, s.report.genus, resolution, 0.0))
                            : GenusAdvice{};
        out["advice"] = advice.message;
        out["advice_resolution"] = advice.resolution;
        return out.dump();
    });
}

std::string Session::estimate_size(double size_cm, double target)
{
    return guarded([&] {
        const LoadedSurface& s = idle_surface();
        const double longest = longest_side(s.mesh);
        // The CLI's formula (real_size.h), so the page's size gives the model `run --size-cm` gives.
        const double b1 = b1_for_size_cm(longest, size_cm);
        const size_t balls = target_of(target);
        auto [z0, out, kits] = z0_estimate(s, static_cast<int>(std::lround(longest / b1)), b1, balls);
        named_kits_ = NamedKits{kAutoResolution, b1, balls, std::move(kits)};
        out["size_cm"] = size_cm;
        out["b1"] = b1;
        out["advice"] = "";
        out["advice_resolution"] = 0;
        return out.dump();
    });
}

std::string Session::kit_check(const std::string& have, double balls) const
{
    return guarded([&] {
        const OwnedKits owned = parse_owned_kits(have);
        if (owned.empty())
            throw InvalidInputError("no kits chosen");
        if (!(balls >= 0 && balls <= 1e7))
            throw InvalidInputError("the ball count must be between 0 and 10,000,000");
        const PartCounts kits = kit_contents(owned);
        const PartCounts need = part_counts(typical_parts(static_cast<size_t>(balls)));
        PartCounts missing{};
        for (size_t k = 0; k < need.size(); ++k)
            missing[k] = need[k] > kits[k] ? need[k] - kits[k] : 0;
        nlohmann::json out{{"ok", true},
                           {"fits", fits(need, kits)},
                           {"text", fit_text(need, kits)},
                           {"owned", owned_text(owned)},
                           {"missing", part_counts_json(missing)},
                           {"budget", balls_that_fit(kits)}};
        return out.dump();
    });
}

std::string Session::fit_kits(const std::string& have, int max_resolution, bool shrink)
{
    return guarded([&] {
        const LoadedSurface& s = idle_surface();
        const OwnedKits owned = parse_owned_kits(have);
        if (owned.empty())
            throw InvalidInputError("choose the kits you own first");
        const PartCounts kits = kit_contents(owned);
        size_t budget = balls_that_fit(kits);
        const ZomeModel m = model();
        if (shrink && !m.nodes.empty())
        {
            // The model on screen missed these kits: as the CLI's next try, fewer balls by the
            // scarcest part's shortfall.
            const PartCounts need = part_counts(parts_list(m));
            if (!fits(need, kits))
                budget = std::min(budget, shrunk_ball_budget(need, kits, m.nodes.size()));
        }
        const KitFitPlan plan = plan_kit_fit(s.mesh, s.report.genus, s.is_inside(), probe_of(*s.projector), budget,
                                             max_resolution > 0 ? max_resolution : kMaxResolution);
        return nlohmann::json{{"ok", true},
                              {"possible", plan.possible},
                              {"resolution", plan.resolution},
                              {"target_nodes", plan.target_nodes},
                              {"z0_nodes", plan.z0_nodes},
                              {"size_cm", plan.size_cm},
                              {"genus_kept", plan.genus_kept},
                              {"ball_budget", plan.ball_budget},
                              {"owned", owned_text(owned)},
                              {"message", plan.message}}
            .dump();
    });
}

std::string Session::auto_resolution()
{
    return guarded([&] {
        const LoadedSurface& s = idle_surface();
        // The CLI's choice (z0_choice.h): the same grid, ball target and sentence as `zomeify run`.
        const AutoResolution a = automatic_resolution(*s.projector, s.report.genus, s.is_inside());
        // The bill of the model the annealer aims at.
        auto [z0, out, kits] = z0_estimate(s, a.resolution, 0.0, a.target_nodes);
        named_kits_ = NamedKits{a.resolution, 0.0, a.target_nodes, std::move(kits)};
        out.update(nlohmann::json::parse(auto_resolution_json(a)));
        out["kept"] = a.genus_kept;
        out["seconds"] = a.seconds;
        // Whether a run at this size would be made mirror-symmetric (`run --mirror auto`), and why.
        const auto [lo, hi] = bounding_box(s.mesh);
        const double cell = (hi - lo).maxCoeff() / std::max(1, a.resolution);
        out["mirror"] = nlohmann::json::parse(mirror_choice_json(choose_mirror(*s.projector, cell / kPhi)));
        return out.dump();
    });
}

void Session::set_model(ZomeModel model, std::string source)
{
    std::lock_guard lock(model_mutex_);
    model_ = std::move(model);
    model_source_ = std::move(source);
    model_version_.fetch_add(1);
}

ZomeModel Session::model() const
{
    std::lock_guard lock(model_mutex_);
    return model_;
}

const TriangleMesh* Session::surface() const { return surface_ ? &surface_->mesh : nullptr; }

void Session::execute_run(const RunOptions& options, RunControl& control)
{
    Stopwatch clock;
    try
    {
        const LoadedSurface& s = *surface_;
        PipelineOptions po = pipeline_options(options);
        // The page already holds the core's answer on holes for this resolution (estimate, or the
        // automatic choice) and says it once; the run does not search again for a second hint.
        po.advise = false;
        if (options.size_cm > 0.0)
            po.b1 = b1_for_size_cm(longest_side(s.mesh), options.size_cm); // as `run --size-cm`
        if (options.continue_model)
        {
            // Improve, Fewer balls, More detail, Fix here: from the model on screen (it must have
            // been made for this shape: run_pipeline refuses it otherwise), at its own size.
            po.from = model();
            // A symmetric model stays symmetric; any other is continued as it is, without a word on it.
            const std::optional<ModelMirror> own = model_mirror(*po.from);
            po.mirror = own && own->mismatch.symmetric() ? MirrorMode::Auto : MirrorMode::Off;
            if (options.radius > 0.0)
                po.fix = FixSpot{Vec3(options.near[0], options.near[1], options.near[2]), options.radius};
        }
        // A run from Z0 keeps within the kits its estimate named: those of the estimate on screen
        // when it was made for these settings, else the same quick pass again (same kits).
        po.keep_to_kit_estimate = !options.continue_model;
        std::optional<KitEstimate> named;
        if (po.keep_to_kit_estimate && named_kits_ &&
            named_kits_->resolution == (po.b1 > 0.0 ? kAutoResolution : po.resolution) && named_kits_->b1 == po.b1 &&
            named_kits_->target == po.anneal.target_nodes)
        {
            named = named_kits_->kits;
            po.anneal.part_limits = named->limits;
        }
        AnnealOptions& a = po.anneal;
        // 0 = automatic: every thread this build can start.
        a.threads = options.threads == 0 ? max_run_threads() : std::clamp(options.threads, 1, max_run_threads());
        a.progress_interval = 0.1;
        control.update([&](RunProgress& p) {
            p.state = RunState::Initial;
            p.budget_seconds = options.proposals > 0 ? 0.0 : options.seconds;
            p.threads = a.threads;
            p.annealer = !options.initial_only;
        });

        double last_snapshot = -1.0;
        double last_fidelity = -1.0;
        PipelineCallbacks callbacks;
        callbacks.cancel = &control.cancel_flag();
        callbacks.initial = [&](const ZomeModel& z0) {
            set_model(z0, "run");
            control.update([&](RunProgress& p) {
                p.state = options.initial_only ? RunState::Initial : RunState::Annealing;
                p.nodes = z0.nodes.size();
                p.struts = z0.struts.size();
                p.seconds = clock.seconds();
            });
        };
        callbacks.progress = [&](const AnnealProgress& ap, Annealer& annealer) {
            // The model goes out a few times a second (the page draws at least two per second);
            // a snapshot costs a copy of the mesh under the commit lock, so not on every report.
            // Not on the final report: the engine makes it under its commit lock, which
            // snapshot() takes too; the final model comes from run_pipeline's result anyway.
            const double now = clock.seconds();
            std::optional<Fidelity> fidelity;
            if (!ap.finished && (last_snapshot < 0.0 || now - last_snapshot >= 0.2))
            {
                last_snapshot = now;
                ZomeModel snapshot = annealer.snapshot();
                // How close the model is so far, every 2 s: 4,000 points a side keep it to a few ms
                // of this thread's time (about 1% of the run).
                if (now - last_fidelity >= 2.0)
                {
                    last_fidelity = now;
                    FidelityOptions quick;
                    quick.samples_per_side = 4000;
                    try
                    {
                        fidelity = measure_fidelity(snapshot, *s.projector, quick);
                    }
                    catch (const InvalidInputError&)
                    {
                        // A model without faces has no distance yet; the figure waits for the next one.
                    }
                }
                set_model(std::move(snapshot), "run");
            }
            control.update([&](RunProgress& p) {
                p.state = RunState::Annealing;
                p.seconds = now;
                p.fraction = ap.fraction;
                p.temperature = ap.temperature;
                p.energy = ap.energy.total;
                p.best_energy = ap.best_energy;
                p.proposals = ap.proposals;
                p.commits = ap.commits;
                p.nodes = ap.nodes;
                p.struts = ap.struts;
                if (fidelity)
                {
                    p.gap_mm = fidelity->hausdorff * kMmPerB0;
                    p.rms_mm = fidelity->rms_symmetric * kMmPerB0;
                }
            });
        };

        PipelineResult result = run_pipeline(s.mesh, s.report.genus, po, callbacks);
        if (named && !po.initial_only)
            result.kit_estimate = std::move(named);
        // The same statistics the CLI writes (its .zome.json carries them too).
        result.model.stats_json = pipeline_stats_json(result, -1);
        const size_t nodes = result.model.nodes.size(), struts = result.model.struts.size();
        set_model(std::move(result.model), "run");
        control.update([&](RunProgress& p) {
            p.seconds = clock.seconds();
            p.nodes = nodes;
            p.struts = struts;
            if (result.anneal)
            {
                p.energy = result.model_energy.total;
                p.commits = result.anneal->stats.commits;
                p.proposals = result.anneal->stats.proposals;
            }
            if (!control.cancel_requested())
                p.fraction = 1.0; // a cancelled run shows how far it got
            p.valid = result.model_valid;
            p.genus = result.model_genus;
            p.surface_genus = result.surface_genus;
            if (result.model_valid)
            {
                p.gap_mm = result.fidelity.hausdorff * kMmPerB0;
                p.rms_mm = result.fidelity.rms_symmetric * kMmPerB0;
            }
            p.note = result.advice;
            if (result.automatic && !result.automatic->genus_kept)
                p.note = result.automatic->message;
            if (!result.model_valid)
                p.note += (p.note.empty() ? "" : " ") + std::string("Model check: ") + result.validation;
            p.state = control.cancel_requested() ? RunState::Cancelled : RunState::Done;
        });
    }
    catch (const std::exception& e)
    {
        const std::string what = e.what();
        control.update([&](RunProgress& p) {
            p.seconds = clock.seconds();
            p.error = what;
            p.state = RunState::Failed;
        });
    }
}

std::string Session::start(const std::string& options_json)
{
    return guarded([&] {
        if (!surface_)
            throw InvalidInputError(
                "load a mesh first (this model came from a file or link; drop its mesh to run again)");
        if (busy())
            throw InvalidInputError("a run is in progress");
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
        // The single-threaded page build (zomeify_web_st) runs through run_blocking(): core_worker.js
        // calls start() only when threadedBuild() is true.
        (void)options_json;
        throw InvalidInputError("start() needs the threaded build; this build runs with runBlocking()");
#else
        const RunOptions options = parse_run_options(options_json);
        if (run_thread_.joinable())
            run_thread_.join();
        run_ = std::make_unique<RunControl>();
        // The worker's own thread must return to its event loop: it receives Cancel, and
        // pthread_create from another thread is completed there.
        run_->update([](RunProgress& p) { p.state = RunState::Initial; });
        run_thread_ = std::thread([this, options] { execute_run(options, *run_); });
#endif
        return nlohmann::json{{"ok", true}}.dump();
    });
}

std::string Session::run_blocking(const std::string& options_json,
                                  const std::function<bool(const RunProgress&)>& report, double interval)
{
    return guarded([&] {
        if (!surface_)
            throw InvalidInputError("load a mesh first");
        if (busy())
            throw InvalidInputError("a run is in progress");
        const RunOptions options = parse_run_options(options_json);
        if (run_thread_.joinable())
            run_thread_.join();
        run_ = std::make_unique<RunControl>();
        run_->set_reporter(report, interval);
        execute_run(options, *run_);
        report(run_->get());
        return nlohmann::json{{"ok", true}}.dump();
    });
}

void Session::cancel()
{
    if (run_)
        run_->request_cancel();
}

RunProgress Session::progress() const { return run_ ? run_->get() : RunProgress{}; }

std::string Session::parts(const std::string& have) const
{
    return guarded([&] {
        const OwnedKits owned = parse_owned_kits(have); // a bad kit name fails before the model is read
        const ZomeModel m = model();
        if (m.nodes.empty())
            throw InvalidInputError("no model yet");
        nlohmann::json doc = nlohmann::json::parse(parts_report_json(parts_list(m), owned));
        if (const std::optional<MirrorHalves> halves = mirror_halves(m)) // the parts by half (mirror_halves.h)
            doc["mirror"] = mirror_halves_json(*halves);
        return doc.dump();
    });
}

std::string Session::build_plan(const std::string& up) const
{
    return guarded([&] {
        const ZomeModel m = model();
        if (m.nodes.empty())
            throw InvalidInputError("no model yet");
        PlanOptions options;
        options.up = parse_up_axis(up);
        options.mirror = building_mirror(m, options.up); // a symmetric model: both halves alike
        const BuildPlan plan = plan_assembly(m, options);
        nlohmann::json out = nlohmann::json::parse(plan_json(m, plan, plan_breadth_first(m, options).figures));
        out["html"] = steps_html(m, plan, surface_name_.empty() ? "model" : surface_name_);
        return out.dump();
    });
}

std::string Session::export_model(const std::string& file_name, const WriteOptions& options) const
{
    const ZomeModel m = model();
    if (m.nodes.empty())
        throw InvalidInputError("no model yet");
    const std::string ext = extension_of(file_name);
    if (ext == ".obj" || ext == ".mtl")
    {
        const size_t dot = file_name.find_last_of('.');
        const ObjExport obj = write_obj(m, file_name.substr(0, dot) + ".mtl", options.obj_units);
        return ext == ".obj" ? obj.obj : obj.mtl;
    }
    return write_model_buffer(m, file_name, options);
}

std::string Session::link() const
{
    return guarded([&] {
        const ZomeModel m = model();
        if (m.nodes.empty())
            throw InvalidInputError("no model yet");
        return nlohmann::json{{"ok", true}, {"link", encode_share_link(m)}}.dump();
    });
}

std::string Session::summary() const
{
    return guarded([&] {
        ZomeModel m;
        std::string source;
        {
            std::lock_guard lock(model_mutex_);
            m = model_;
            source = model_source_;
        }
        nlohmann::json out;
        out["ok"] = true;
        out["source"] = source;
        out["balls"] = m.nodes.size();
        out["struts"] = m.struts.size();
        out["faces"] = m.faces.size();
        nlohmann::json by_kind = nlohmann::json::object();
        for (const auto& s : m.struts)
        {
            const int id = vector_id_of(m.nodes[s[1]] - m.nodes[s[0]]);
            if (id >= 0)
                by_kind[std::string(kind_info(vector_kind(id)).name)] =
                    by_kind.value(std::string(kind_info(vector_kind(id)).name), 0) + 1;
        }
        out["by_kind"] = by_kind;
        if (!m.faces.empty())
        {
            const ValidationReport check = validate(from_model(m));
            out["valid"] = check.ok();
            out["genus"] = check.genus;
            out["validation"] = check.message();
        }
        else
        {
            out["valid"] = nullptr;
        }
        if (!m.nodes.empty())
        {
            // Any model, a loaded one without faces too: can its parts be built side by side?
            const ClearanceReport clearance = clearance_report(m);
            out["clashes"] = clearance.total();
            out["clearance"] = clearance_summary(clearance);
        }
        out["stats"] = nlohmann::json::parse(m.stats_json, nullptr, false);
        if (out["stats"].is_discarded())
            out["stats"] = nlohmann::json::object();
        out["surface"] = surface_ ? surface_name_ : "";
        // How many balls the loaded shape holds well at this model's size (More detail, issue 40),
        // and the core's sentence when the model has them already.
        const double b0 = kind_info(StrutKind::B0).length * m.transform.scale;
        if (const size_t capacity = surface_ && !m.nodes.empty() ? surface_capacity(surface_->area, b0) : 0)
        {
            out["capacity"] = capacity;
            if (at_capacity(m.nodes.size(), capacity))
                out["capacity_full"] = capacity_full_text(m.nodes.size(), capacity);
        }
        return out.dump();
    });
}

} // namespace zomeify::web
