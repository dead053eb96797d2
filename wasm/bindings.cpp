// embind facade of Session for the page's worker (web/src/worker/core_worker.js). Text results are
// JSON strings; bulk data leaves as typed arrays copied out of the wasm heap (so they can be
// transferred to the page, and are never views of a SharedArrayBuffer).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include "core/io/obj_export.h"
#include "core/zome/slots.h"
#include "wasm/run_options.h"
#include "wasm/session.h"

using emscripten::val;

namespace zomeify::web {

namespace {

template <class T>
val typed_copy(const char* type, const std::vector<T>& data)
{
    return val::global(type).new_(emscripten::typed_memory_view(data.size(), data.data()));
}

val error_object(const std::string& message)
{
    val out = val::object();
    out.set("ok", false);
    out.set("error", message);
    return out;
}

class WebSession
{
public:
    std::string load_mesh(const std::string& bytes, const std::string& name, bool thicken)
    {
        return s_.load_mesh(bytes, name, thicken);
    }
    std::string load_model(const std::string& bytes, const std::string& name) { return s_.load_model(bytes, name); }
    std::string open_link(const std::string& link) { return s_.open_link(link); }
    std::string estimate(int resolution, double target, bool with_kits)
    {
        return s_.estimate(resolution, target, with_kits);
    }
    std::string estimate_size(double size_cm, double target) { return s_.estimate_size(size_cm, target); }
    std::string kit_check(const std::string& have, double balls) const { return s_.kit_check(have, balls); }
    std::string fit_kits(const std::string& have, int max_resolution, bool shrink)
    {
        return s_.fit_kits(have, max_resolution, shrink);
    }
    std::string auto_resolution() { return s_.auto_resolution(); }
    std::string start(const std::string& options) { return s_.start(options); }
    std::string run_blocking(const std::string& options, val callback, double interval)
    {
        return s_.run_blocking(
            options, [&](const RunProgress& p) { return callback(p.json()).as<bool>(); }, interval);
    }
    void cancel() { s_.cancel(); }
    std::string progress() const { return s_.progress().json(); }
    double model_version() const { return static_cast<double>(s_.model_version()); }
    std::string parts(const std::string& have) const { return s_.parts(have); }
    std::string build_plan(const std::string& up) const { return s_.build_plan(up); }
    std::string link() const { return s_.link(); }
    std::string summary() const { return s_.summary(); }

    //! {ok, bytes: Uint8Array} or {ok:false, error}.
    val export_model(const std::string& name) const { return export_model_with(name, true, "mm"); }
    //! The same with the writers' options: faces in a VEF, OBJ units ("mm" or "m").
    val export_model_with(const std::string& name, bool vef_faces, const std::string& obj_units) const
    {
        try
        {
            const std::string bytes = s_.export_model(name, WriteOptions{parse_obj_units(obj_units), vef_faces});
            val out = val::object();
            out.set("ok", true);
            out.set("bytes", val::global("Uint8Array")
                                 .new_(emscripten::typed_memory_view(bytes.size(),
                                                                     reinterpret_cast<const uint8_t*>(bytes.data()))));
            return out;
        }
        catch (const std::exception& e)
        {
            return error_object(e.what());
        }
    }

    //! The current model for the viewer: positions in Zome units (b0 = 1), strut node pairs,
    //! strut kinds (0..8 = B0..R2, 255 if not a Zome vector), faces as a triangle fan list, the
    //! transform to mesh units, and the version counter.
    val snapshot() const
    {
        const double version = model_version();
        const ZomeModel m = s_.model();
        std::vector<float> positions;
        positions.reserve(3 * m.nodes.size());
        for (const ZVec& p : m.nodes)
            for (int k = 0; k < 3; ++k)
                positions.push_back(static_cast<float>(p.coord(k)));
        std::vector<uint32_t> struts;
        std::vector<uint8_t> kinds;
        struts.reserve(2 * m.struts.size());
        kinds.reserve(m.struts.size());
        for (const auto& s : m.struts)
        {
            struts.push_back(s[0]);
            struts.push_back(s[1]);
            const int id = vector_id_of(m.nodes[s[1]] - m.nodes[s[0]]);
            kinds.push_back(id < 0 ? uint8_t{255} : static_cast<uint8_t>(vector_kind(id)));
        }
        std::vector<uint32_t> triangles;
        for (const auto& f : m.faces)
            for (size_t i = 1; i + 1 < f.size(); ++i)
                triangles.insert(triangles.end(), {f[0], f[i], f[i + 1]});
        val out = val::object();
        out.set("version", version);
        out.set("positions", typed_copy("Float32Array", positions));
        out.set("struts", typed_copy("Uint32Array", struts));
        out.set("kinds", typed_copy("Uint8Array", kinds));
        out.set("triangles", typed_copy("Uint32Array", triangles));
        out.set("scale", m.transform.scale);
        val t = val::array();
        for (double x : m.transform.translation)
            t.call<void>("push", x);
        out.set("translation", t);
        return out;
    }

    //! The input surface in mesh units, or null.
    val surface() const
    {
        const TriangleMesh* mesh = s_.surface();
        if (!mesh)
            return val::null();
        std::vector<float> positions;
        positions.reserve(3 * mesh->positions.size());
        for (const Vec3& p : mesh->positions)
            for (int k = 0; k < 3; ++k)
                positions.push_back(static_cast<float>(p[k]));
        std::vector<uint32_t> triangles;
        triangles.reserve(3 * mesh->triangles.size());
        for (const auto& t : mesh->triangles)
            triangles.insert(triangles.end(), t.begin(), t.end());
        val out = val::object();
        out.set("positions", typed_copy("Float32Array", positions));
        out.set("triangles", typed_copy("Uint32Array", triangles));
        return out;
    }

private:
    Session s_;
};

int max_threads() { return max_run_threads(); }

bool threaded_build()
{
#if defined(__EMSCRIPTEN_PTHREADS__)
    return true;
#else
    return false;
#endif
}

} // namespace

EMSCRIPTEN_BINDINGS(zomeify_web)
{
    emscripten::class_<WebSession>("Session")
        .constructor<>()
        .function("loadMesh", &WebSession::load_mesh)
        .function("loadModel", &WebSession::load_model)
        .function("openLink", &WebSession::open_link)
        .function("estimate", &WebSession::estimate)
        .function("estimateSize", &WebSession::estimate_size)
        .function("kitCheck", &WebSession::kit_check)
        .function("fitKits", &WebSession::fit_kits)
        .function("autoResolution", &WebSession::auto_resolution)
        .function("start", &WebSession::start)
        .function("runBlocking", &WebSession::run_blocking)
        .function("cancel", &WebSession::cancel)
        .function("progress", &WebSession::progress)
        .function("modelVersion", &WebSession::model_version)
        .function("snapshot", &WebSession::snapshot)
        .function("surface", &WebSession::surface)
        .function("parts", &WebSession::parts)
        .function("buildPlan", &WebSession::build_plan)
        .function("exportModel", &WebSession::export_model)
        .function("exportModelWith", &WebSession::export_model_with)
        .function("link", &WebSession::link)
        .function("summary", &WebSession::summary);
    emscripten::function("maxThreads", &max_threads);
    emscripten::function("runSettingsSchema", &run_settings_schema_json);
    emscripten::function("threadedBuild", &threaded_build);
}

} // namespace zomeify::web
