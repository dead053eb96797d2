#include "core/assembly/plan_report.h"

#include <cstdio>
#include <sstream>

#include "core/base/errors.h"
#include "core/zome/real_sizes.h"

namespace zomeify {

namespace {

std::string number(double x)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", x);
    return buf;
}

void figures_json(std::ostream& os, const PlanFigures& f)
{
    os << "{\"steps\":" << f.steps << ",\"max_overhang_b0\":" << number(f.max_overhang_b0)
       << ",\"max_overhang_mm\":" << number(f.max_overhang_b0 * kMmPerB0)
       << ",\"two_strut_share\":" << number(f.two_strut_share) << ",\"max_dangling\":" << f.max_dangling << "}";
}

} // namespace

std::string up_axis_name(UpAxis up) { return std::string(up.sign < 0 ? "-" : "") + char('x' + up.axis); }

std::vector<StrutKind> strut_kinds(const ZomeModel& model)
{
    std::vector<StrutKind> kinds;
    kinds.reserve(model.struts.size());
    for (size_t s = 0; s < model.struts.size(); ++s)
    {
        const auto [a, b] = model.struts[s];
        const int id = vector_id_of(model.nodes.at(b) - model.nodes.at(a));
        if (id < 0)
            throw InvalidInputError("strut " + std::to_string(s) + " is not a Zome strut");
        kinds.push_back(vector_kind(id));
    }
    return kinds;
}

std::array<size_t, kStrutKindCount> step_strut_counts(const std::vector<StrutKind>& kinds, const BuildStep& step)
{
    std::array<size_t, kStrutKindCount> counts{};
    for (uint32_t s : step.struts)
        ++counts[static_cast<size_t>(kinds.at(s))];
    return counts;
}

std::string halves_alike_text(const BuildPlan& plan)
{
    if (!plan.mirror)
        return {};
    return std::string("Both halves are built alike: each step adds its parts with their mirror images about the "
                       "plane across the ") +
           "xyz"[plan.mirror->axis] + " axis.";
}

std::string plan_json(const ZomeModel& model, const BuildPlan& plan, const PlanFigures& naive)
{
    const std::vector<StrutKind> kinds = strut_kinds(model);
    std::ostringstream os;
    os << "{\"up\":\"" << up_axis_name(plan.up) << "\",";
    if (plan.mirror)
        os << "\"mirror\":{\"axis\":\""
           << "xyz"[plan.mirror->axis] << "\",\"coordinate_b0\":" << number(plan.mirror->coordinate()) << "},";
    os << "\"nodes\":[";
    for (size_t i = 0; i < model.nodes.size(); ++i)
    {
        os << (i ? ",[" : "[");
        for (int k = 0; k < 6; ++k)
            os << (k ? "," : "") << model.nodes[i].c[k];
        os << "]";
    }
    os << "],\"steps\":[";
    for (size_t s = 0; s < plan.steps.size(); ++s)
    {
        const BuildStep& st = plan.steps[s];
        os << (s ? ",\n" : "\n") << "{\"balls\":[";
        for (size_t i = 0; i < st.balls.size(); ++i)
            os << (i ? "," : "") << st.balls[i];
        os << "],\"struts\":[";
        for (size_t i = 0; i < st.struts.size(); ++i)
        {
            const auto [a, b] = model.struts[st.struts[i]];
            os << (i ? ",[" : "[") << a << "," << b << "]";
        }
        os << "],\"attach\":[";
        for (size_t i = 0; i < st.attach.size(); ++i)
            os << (i ? "," : "") << st.attach[i];
        os << "],\"parts\":{\"" << kBallPartCode << "\":" << st.balls.size();
        const auto counts = step_strut_counts(kinds, st);
        for (int k = 0; k < kStrutKindCount; ++k)
            if (counts[k])
                os << ",\"" << kind_info(static_cast<StrutKind>(k)).part_code << "\":" << counts[k];
        os << "}}";
    }
    os << "],\n\"figures\":";
    figures_json(os, plan.figures);
    os << ",\"naive\":";
    figures_json(os, naive);
    os << "}\n";
    return os.str();
}

std::string plan_text(const ZomeModel& model, const BuildPlan& plan, const PlanFigures& naive)
{
    const std::vector<StrutKind> kinds = strut_kinds(model);
    std::ostringstream os;
    os << "Build plan, " << up_axis_name(plan.up) << " up: " << model.nodes.size() << " balls and "
       << model.struts.size() << " struts in " << plan.steps.size() << " steps.\n";
    if (plan.mirror)
        os << halves_alike_text(plan) << "\n";
    for (size_t s = 0; s < plan.steps.size(); ++s)
    {
        const BuildStep& st = plan.steps[s];
        os << "step " << s + 1 << ": " << st.balls.size() << (st.balls.size() == 1 ? " ball, " : " balls, ")
           << st.struts.size() << (st.struts.size() == 1 ? " strut" : " struts");
        const auto counts = step_strut_counts(kinds, st);
        const char* sep = " (";
        for (int k = 0; k < kStrutKindCount; ++k)
            if (counts[k])
            {
                os << sep << kind_info(static_cast<StrutKind>(k)).name << " x" << counts[k];
                sep = ", ";
            }
        os << (st.struts.empty() ? "" : ")");
        if (s == 0)
            os << " on the table";
        else
        {
            os << " on ball" << (st.attach.size() == 1 ? " " : "s ");
            for (size_t i = 0; i < st.attach.size(); ++i)
                os << (i ? ", " : "") << st.attach[i];
        }
        os << "\n";
    }
    const double mm = kMmPerB0;
    os << "Largest overhang " << number(plan.figures.max_overhang_b0 * mm)
       << " mm; steps ending with every new ball on two struts: " << number(100 * plan.figures.two_strut_share)
       << "%; most balls on one strut at once: " << plan.figures.max_dangling
       << " (breadth-first order: " << naive.steps << " steps, " << number(naive.max_overhang_b0 * mm) << " mm, "
       << number(100 * naive.two_strut_share) << "%, " << naive.max_dangling << ").\n";
    return os.str();
}

} // namespace zomeify
