#include "core/io/zome_json.h"

#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "core/base/errors.h"
#include "core/io/model_check.h"

namespace zomeify {

using nlohmann::json;

namespace {

constexpr const char* kFormat = "zomeify-model";
constexpr int kVersion = 1;

[[noreturn]] void fail(const std::string& what) { throw InvalidInputError("not a valid .zome.json model: " + what); }

const json& member(const json& obj, const char* key)
{
    const auto it = obj.find(key);
    if (it == obj.end())
        fail(std::string("missing \"") + key + "\"");
    return *it;
}

const json& array_member(const json& obj, const char* key, size_t limit)
{
    const json& a = member(obj, key);
    if (!a.is_array())
        fail(std::string("\"") + key + "\" is not an array");
    if (a.size() > limit)
        fail(std::string("\"") + key + "\" has " + std::to_string(a.size()) + " entries (limit " +
             std::to_string(limit) + ")");
    return a;
}

int64_t integer(const json& v, const std::string& where, int64_t lo, int64_t hi)
{
    if (!v.is_number_integer())
        fail(where + " is not an integer");
    const int64_t x =
        v.is_number_unsigned() && v.get<uint64_t>() > static_cast<uint64_t>(hi) ? hi + 1 : v.get<int64_t>();
    if (x < lo || x > hi)
        fail(where + " is out of range");
    return x;
}

double finite_number(const json& v, const std::string& where)
{
    if (!v.is_number())
        fail(where + " is not a number");
    const double x = v.get<double>();
    if (!std::isfinite(x))
        fail(where + " is not finite");
    return x;
}

} // namespace

std::string write_zome_json(const ZomeModel& model)
{
    json nodes = json::array();
    for (const ZVec& p : model.nodes)
        nodes.push_back(p.c);
    json struts = json::array();
    for (const auto& s : model.struts)
        struts.push_back(s);
    json faces = json::array();
    for (const auto& f : model.faces)
        faces.push_back(f);
    json stats = json::parse(model.stats_json.empty() ? std::string("{}") : model.stats_json, nullptr, false);
    if (stats.is_discarded() || !stats.is_object())
        stats = json::object();
    const json doc = {
        {"format", kFormat},
        {"version", kVersion},
        {"nodes", std::move(nodes)},
        {"struts", std::move(struts)},
        {"faces", std::move(faces)},
        {"transform", {{"scale", model.transform.scale}, {"translation", model.transform.translation}}},
        {"stats", std::move(stats)},
    };
    return doc.dump() + "\n";
}

ZomeModel read_zome_json(std::string_view text)
{
    json doc;
    try
    {
        doc = json::parse(text);
    }
    catch (const json::parse_error& e)
    {
        fail("JSON syntax error at byte " + std::to_string(e.byte) + (text.empty() ? " (the file is empty)" : ""));
    }
    catch (const json::out_of_range&)
    {
        // nlohmann throws this while parsing a number beyond double's range, e.g. 1e3000.
        fail("a number is too large");
    }
    if (!doc.is_object())
        fail("the top level is not an object");
    const json& format = member(doc, "format");
    if (!format.is_string() || format.get<std::string>() != kFormat)
        fail("\"format\" is not \"zomeify-model\"");
    const int64_t version = integer(member(doc, "version"), "\"version\"", 0, 1'000'000);
    if (version != kVersion)
        fail("version " + std::to_string(version) + " is not supported (this build reads version 1)");

    ZomeModel model;
    const json& nodes = array_member(doc, "nodes", kMaxModelNodes);
    model.nodes.resize(nodes.size());
    for (size_t i = 0; i < nodes.size(); ++i)
    {
        const json& p = nodes[i];
        const std::string where = "node " + std::to_string(i);
        if (!p.is_array() || p.size() != 6)
            fail(where + " is not 6 integers");
        for (size_t k = 0; k < 6; ++k)
            model.nodes[i].c[k] = static_cast<int32_t>(
                integer(p[k], where, std::numeric_limits<int32_t>::min() / 4, std::numeric_limits<int32_t>::max() / 4));
    }
    const json& struts = array_member(doc, "struts", kMaxModelStruts);
    model.struts.resize(struts.size());
    for (size_t s = 0; s < struts.size(); ++s)
    {
        const json& st = struts[s];
        const std::string where = "strut " + std::to_string(s);
        if (!st.is_array() || st.size() != 2)
            fail(where + " is not a pair of node indices");
        for (size_t k = 0; k < 2; ++k)
            model.struts[s][k] = static_cast<uint32_t>(integer(st[k], where, 0, std::numeric_limits<uint32_t>::max()));
    }
    if (doc.contains("faces"))
    {
        const json& faces = array_member(doc, "faces", kMaxModelFaces);
        model.faces.resize(faces.size());
        for (size_t f = 0; f < faces.size(); ++f)
        {
            const json& face = faces[f];
            const std::string where = "face " + std::to_string(f);
            if (!face.is_array() || face.size() < 3 || face.size() > kMaxFaceSize)
                fail(where + " is not a list of 3 to " + std::to_string(kMaxFaceSize) + " node indices");
            for (const json& v : face)
                model.faces[f].push_back(
                    static_cast<uint32_t>(integer(v, where, 0, std::numeric_limits<uint32_t>::max())));
        }
    }
    if (doc.contains("transform"))
    {
        const json& t = doc["transform"];
        if (!t.is_object())
            fail("\"transform\" is not an object");
        model.transform.scale = finite_number(member(t, "scale"), "transform scale");
        if (!(model.transform.scale > 0))
            fail("transform scale must be positive");
        const json& tr = member(t, "translation");
        if (!tr.is_array() || tr.size() != 3)
            fail("transform translation is not 3 numbers");
        for (size_t k = 0; k < 3; ++k)
            model.transform.translation[k] = finite_number(tr[k], "transform translation");
    }
    if (doc.contains("stats"))
    {
        if (!doc["stats"].is_object())
            fail("\"stats\" is not an object");
        model.stats_json = doc["stats"].dump();
    }
    check_model(model);
    return model;
}

} // namespace zomeify
