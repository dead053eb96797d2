#pragma once
//! \file session.h
//! The page's whole state in the worker: the input surface, the current model, and at most one
//! run. Every method turns bad input into a one-line message and leaves the current model as it
//! was. Results go out as JSON text; bulk data (snapshots, exports) through the bindings as typed
//! arrays. No embind here, so the same class can be exercised natively.

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "core/geom/triangle_mesh.h"
#include "core/io/model_io.h"
#include "core/pipeline/kit_estimate.h"
#include "core/surface/prepare.h"
#include "core/zome/model.h"
#include "wasm/run_progress.h"

namespace zomeify::web {

struct LoadedSurface;

class Session
{
public:
    Session();
    ~Session();
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    //! Reads and repairs a mesh file ({ok, kind:"mesh", report} or {ok:false, error}). On success
    //! the surface is replaced; the current model stays until a run replaces it.
    //! `thicken`: an open sheet is given a thickness (PrepareOptions::thicken_sheets) instead of refused.
    std::string load_mesh(const std::string& bytes, const std::string& file_name, bool thicken = false);
    //! Reads a model file (.zome.json, .json, .vef) and makes it the current model.
    std::string load_model(const std::string& bytes, const std::string& file_name);
    //! Opens a share link (whole URL, #m=… or m=…) as the current model.
    std::string open_link(const std::string& link);

    //! Z0 at `resolution` cells without keeping it: {nodes, struts, genus, surface_genus, kept,
    //! advice, size_mm, kits}. Used by the page's live estimate. Without `with_kits` the kit fields
    //! are left out and the quick pass that names them (a second or two in the browser) is skipped:
    //! the page asks so when its line names no kits (the model on screen was made at `resolution`).
    std::string estimate(int resolution, double target = 0, bool with_kits = true);
    //! Z0 for a built longest side of `size_cm` (core/assembly/real_size.h, as `run --size-cm`):
    //! estimate()'s fields plus {size_cm, b1}; a clear error for a size out of range.
    std::string estimate_size(double size_cm, double target = 0);
    //! Whether a typical model of `balls` balls fits the kits in `have` ("creator3, 2x basic", as
    //! `parts --have`): {fits, text, owned, missing{...}, budget} (budget: the balls that fit).
    std::string kit_check(const std::string& have, double balls) const;
    //! "Fit my kits" (core/pipeline/kit_fit_plan.h): {possible, resolution, target_nodes, z0_nodes,
    //! size_cm, genus_kept, ball_budget, message}. With `shrink`, the current model (a run that
    //! missed the kits) lowers the budget as the CLI's next try does. `max_resolution` 0: no bound.
    std::string fit_kits(const std::string& have, int max_resolution, bool shrink);
    //! The resolution a run takes when the user chose none (core/voxel/auto_resolution.h):
    //! {resolution, genus_kept, searched_to, message} plus estimate()'s fields for it.
    std::string auto_resolution();

    //! Starts a run (Z0, then annealing) on its own thread and returns at once; poll() reports.
    //! The threaded build only: the single-threaded build (zomeify_web_st) throws here; it uses run_blocking().
    std::string start(const std::string& options_json);
    //! The same run on the calling thread; `report` is called about every `interval` seconds
    //! and may ask to stop by returning true.
    std::string run_blocking(const std::string& options_json, const std::function<bool(const RunProgress&)>& report,
                             double interval);
    //! Asks a run to stop; it keeps the best model found so far.
    void cancel();
    //! Progress of the current or last run.
    RunProgress progress() const;

    //! The current model (a copy; during a run the latest snapshot, else the finished model).
    ZomeModel model() const;
    //! A counter that changes whenever model() changes.
    uint64_t model_version() const { return model_version_.load(); }
    //! The input surface, if a mesh is loaded.
    const TriangleMesh* surface() const;

    //! The parts list and kit plan of the current model (parts_report_json) or {ok:false,error}.
    //! With `have` (kits owned, `parts --have` syntax) the report adds what is missing.
    std::string parts(const std::string& have = "") const;
    //! The assembly sequence of the current model (core/build plan_json) plus "html", the page to
    //! print (steps_html), `up` as "y", "-z", ...;
    //! or {ok:false,error}. Deterministic from the model, so a shared link gives the sender's steps.
    std::string build_plan(const std::string& up) const;
    //! The current model in the format of `file_name`'s extension (.vef .glb .obj .mtl .zome.json .csv),
    //! with the writers' options (VEF without faces, OBJ in metres).
    //! Throws InvalidInputError for an unknown format or when there is no model.
    std::string export_model(const std::string& file_name, const WriteOptions& options = {}) const;
    //! The share-link fragment m=2.… of the current model, or {ok:false,error}.
    std::string link() const;
    //! {balls, struts, faces, by_kind{...}, genus?, valid, source, stats{}}.
    std::string summary() const;

private:
    void execute_run(const RunOptions& options, RunControl& control);
    void set_model(ZomeModel model, std::string source);
    bool busy() const;
    //! The loaded surface; InvalidInputError when there is none or a run is going.
    const LoadedSurface& idle_surface() const;

    std::unique_ptr<LoadedSurface> surface_;
    std::string surface_name_;

    mutable std::mutex model_mutex_;
    ZomeModel model_;
    std::string model_source_ = "none";
    std::atomic<uint64_t> model_version_{0};

    //! The kits the last estimate named, with the settings they were made for: a run with the
    //! same settings keeps within them without a second quick pass.
    struct NamedKits
    {
        int resolution = 0; //!< kAutoResolution with a size (b1 > 0)
        double b1 = 0.0;
        size_t target = 0; //!< 0: Z0's count
        KitEstimate kits;
    };
    std::optional<NamedKits> named_kits_;

    std::unique_ptr<RunControl> run_;
    std::thread run_thread_;
};

} // namespace zomeify::web
