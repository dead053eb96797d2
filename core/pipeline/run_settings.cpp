#include "core/pipeline/run_settings.h"

#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "core/base/errors.h"
#include "core/voxel/advisor.h"

namespace zomeify {

namespace {

// The weights' JSON names, in the order of run_option_bounds().
struct WeightField
{
    const char* name;
    double EnergyOptions::*field;
};
constexpr WeightField kWeights[] = {{"dist", &EnergyOptions::w_distance},   {"orient", &EnergyOptions::w_orientation},
                                    {"fair", &EnergyOptions::w_fairing},    {"complex", &EnergyOptions::w_complexity},
                                    {"surface", &EnergyOptions::w_surface}, {"fold", &EnergyOptions::w_fold}};

std::string number_text(double x)
{
    std::string s = std::to_string(x);
    s.erase(s.find_last_not_of('0') + 1);
    if (!s.empty() && s.back() == '.')
        s.pop_back();
    return s;
}

// Every option's value, in the order of run_option_bounds() (resolution first).
std::vector<double> values(const RunSettings& s)
{
    std::vector<double> v = {static_cast<double>(s.resolution), s.seconds,
                             static_cast<double>(s.proposals),  static_cast<double>(s.target_nodes),
                             static_cast<double>(s.threads),    static_cast<double>(s.seed)};
    for (const WeightField& w : kWeights)
        v.push_back(s.energy.*w.field);
    v.push_back(s.size_cm);
    return v;
}

void check_value(const OptionBounds& b, double x)
{
    const bool in = std::isfinite(x) && x >= b.min && x <= b.max && (!b.integer || x == std::floor(x));
    if (!in)
        throw InvalidInputError(std::string("option '") + b.key + "' (" + b.flag + ") must be " +
                                (b.integer ? "a whole number " : "a number ") + "from " + number_text(b.min) + " to " +
                                number_text(b.max) + ", got " + number_text(x));
}

} // namespace

const std::vector<TimePreset>& time_presets()
{
    static const std::vector<TimePreset> presets = {{"quick", 5.0}, {"standard", 30.0}, {"thorough", 120.0}};
    return presets;
}

const std::vector<OptionBounds>& run_option_bounds()
{
    static const std::vector<OptionBounds> bounds = {
        {"resolution", "--resolution", kAutoResolution, kMaxResolution, true},
        {"seconds", "--seconds", 0, 7 * 24 * 3600.0, false},
        {"proposals", "--proposals", 0, 1e12, true},
        {"target_nodes", "--target-nodes", 0, 10'000'000, true},
        {"threads", "--threads", 0, 64, true},
        {"seed", "--seed", 0, 9007199254740991.0, true},
        {"weights.dist", "--w-distance", 0, 1e6, false},
        {"weights.orient", "--w-orientation", 0, 1e6, false},
        {"weights.fair", "--w-fairing", 0, 1e6, false},
        {"weights.complex", "--w-complexity", 0, 1e6, false},
        {"weights.surface", "--w-surface", 0, 1e6, false},
        {"weights.fold", "--w-fold", 0, 1e6, false},
        // 0 = off; real_size.h's own bounds (about 25 cm to 19 m) are checked once the mesh is known.
        {"size_cm", "--size-cm", 0, 1900, false},
    };
    return bounds;
}

const OptionBounds& option_bounds(const std::string& key)
{
    for (const OptionBounds& b : run_option_bounds())
        if (key == b.key)
            return b;
    throw std::out_of_range("no run option '" + key + "'");
}

void RunSettings::check() const
{
    const std::vector<double> v = values(*this);
    const std::vector<OptionBounds>& bounds = run_option_bounds();
    for (size_t i = 0; i < bounds.size(); ++i)
        check_value(bounds[i], v[i]);
    // 1 cell cannot hold a shape; 0 means automatic.
    if (resolution != kAutoResolution && resolution < kMinResolution)
        throw InvalidInputError("option 'resolution' (--resolution) must be automatic (0) or from " +
                                std::to_string(kMinResolution) + " to " + std::to_string(kMaxResolution) + ", got " +
                                std::to_string(resolution));
    // A proposal budget replaces the time budget; without one the run needs some time.
    if (proposals == 0 && !(seconds > 0.0))
        throw InvalidInputError("option 'seconds' (--seconds) must be positive unless a proposal budget is given");
    if (radius != 0.0 && !(continue_model && radius > 0.0 && std::isfinite(radius) && std::isfinite(near[0]) &&
                           std::isfinite(near[1]) && std::isfinite(near[2])))
        throw InvalidInputError("fixing one spot needs the model to continue, a point and a positive radius");
    if (target_nodes != 0 && target_nodes < 4)
        throw InvalidInputError("option 'target_nodes' (--target-nodes) must be 0 (Z0's count) or at least 4, got " +
                                std::to_string(target_nodes));
}

RunSettings run_settings_from_json(const std::string& json)
{
    const nlohmann::json j = nlohmann::json::parse(json, nullptr, false);
    if (j.is_discarded() || !j.is_object())
        throw InvalidInputError("run options must be a JSON object");
    const auto number = [](const nlohmann::json& o, const char* key, double fallback) {
        if (!o.contains(key))
            return fallback;
        if (!o.at(key).is_number())
            throw InvalidInputError(std::string("run option '") + key + "' must be a number");
        const double x = o.at(key).get<double>();
        // Checked here so a huge value never reaches an integer cast.
        for (const OptionBounds& b : run_option_bounds())
            if (std::string(b.key) == key || std::string(b.key) == std::string("weights.") + key)
                check_value(b, x);
        return x;
    };
    RunSettings s;
    s.resolution = static_cast<int>(number(j, "resolution", s.resolution));
    s.seconds = number(j, "seconds", s.seconds);
    s.proposals = static_cast<uint64_t>(number(j, "proposals", static_cast<double>(s.proposals)));
    s.target_nodes = static_cast<long long>(number(j, "target_nodes", static_cast<double>(s.target_nodes)));
    s.threads = static_cast<int>(number(j, "threads", s.threads));
    s.seed = static_cast<uint64_t>(number(j, "seed", static_cast<double>(s.seed)));
    s.size_cm = number(j, "size_cm", s.size_cm);
    if (j.contains("initial_only"))
    {
        if (!j.at("initial_only").is_boolean())
            throw InvalidInputError("run option 'initial_only' must be true or false");
        s.initial_only = j.at("initial_only").get<bool>();
    }
    if (j.contains("continue"))
    {
        if (!j.at("continue").is_boolean())
            throw InvalidInputError("run option 'continue' must be true or false");
        s.continue_model = j.at("continue").get<bool>();
    }
    if (j.contains("mirror"))
    {
        const nlohmann::json& m = j.at("mirror");
        if (!m.is_string() || (m.get<std::string>() != "auto" && m.get<std::string>() != "off"))
            throw InvalidInputError("run option 'mirror' must be \"auto\" or \"off\"");
        s.mirror = m.get<std::string>() == "auto" ? MirrorMode::Auto : MirrorMode::Off;
    }
    if (j.contains("near"))
    {
        const nlohmann::json& p = j.at("near");
        if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() || !p[2].is_number())
            throw InvalidInputError("run option 'near' must be a point [x, y, z]");
        for (size_t k = 0; k < 3; ++k)
            s.near[k] = p[k].get<double>();
        if (!j.contains("radius") || !j.at("radius").is_number())
            throw InvalidInputError("run option 'near' needs a 'radius'");
        s.radius = j.at("radius").get<double>();
        if (!(s.radius > 0.0))
            throw InvalidInputError("run option 'radius' must be positive");
    }
    if (j.contains("weights"))
    {
        const nlohmann::json& w = j.at("weights");
        if (!w.is_object())
            throw InvalidInputError("run option 'weights' must be an object");
        for (const WeightField& f : kWeights)
            s.energy.*f.field = number(w, f.name, s.energy.*f.field);
    }
    s.check();
    return s;
}

std::string run_settings_json(const RunSettings& s)
{
    nlohmann::json weights = nlohmann::json::object();
    for (const WeightField& f : kWeights)
        weights[f.name] = s.energy.*f.field;
    const nlohmann::json j = {{"resolution", s.resolution},
                              {"seconds", s.seconds},
                              {"proposals", s.proposals},
                              {"target_nodes", s.target_nodes},
                              {"threads", s.threads},
                              {"seed", s.seed},
                              {"initial_only", s.initial_only},
                              {"size_cm", s.size_cm},
                              {"weights", weights},
                              {"mirror", s.mirror == MirrorMode::Auto ? "auto" : "off"}};
    return j.dump();
}

std::string run_settings_schema_json()
{
    nlohmann::json bounds = nlohmann::json::object();
    for (const OptionBounds& b : run_option_bounds())
    {
        // The page's resolution slider has no "automatic" position: its lower end is a real grid.
        const double min = std::string(b.key) == "resolution" ? kMinResolution : b.min;
        bounds[b.key] = {{"min", min}, {"max", b.max}, {"integer", b.integer}, {"flag", b.flag}};
    }
    nlohmann::json presets = nlohmann::json::object();
    for (const TimePreset& p : time_presets())
        presets[p.name] = p.seconds;
    const nlohmann::json j = {{"defaults", nlohmann::json::parse(run_settings_json())},
                              {"bounds", bounds},
                              {"presets", presets},
                              {"advice_max_resolution", kAdviceMaxResolution}};
    return j.dump();
}

PipelineOptions pipeline_options(const RunSettings& s)
{
    s.check();
    PipelineOptions o;
    o.resolution = s.resolution;
    o.initial_only = s.initial_only;
    o.mirror = s.mirror;
    AnnealOptions& a = o.anneal;
    a.seconds = s.seconds;
    a.max_proposals = s.proposals;
    a.threads = s.threads;
    a.seed = s.seed;
    a.target_nodes = static_cast<size_t>(s.target_nodes);
    a.energy = s.energy;
    return o;
}

} // namespace zomeify
