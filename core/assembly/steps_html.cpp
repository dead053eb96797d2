#include "core/assembly/steps_html.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/assembly/plan_report.h"
#include "core/zome/real_sizes.h"

namespace zomeify {

namespace {

constexpr double kPanel = 300.0; // SVG side, px
constexpr double kMargin = 12.0;

std::string escape(const std::string& s)
{
    std::string out;
    for (char c : s)
    {
        switch (c)
        {
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '&':
            out += "&amp;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

std::string fixed(double x)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", x);
    return buf;
}

const char* strut_colour(StrutKind k)
{
    switch (kind_color(k))
    {
    case Color::Blue:
        return "#1c5fd6";
    case Color::Yellow:
        return "#e0a800";
    default:
        return "#d3212d";
    }
}

//! Screen positions: upright, turned a little about the up axis and seen slightly from above, so
//! that no strut of the lattice directions lies exactly along the line of sight.
std::vector<std::array<double, 2>> project(const ZomeModel& model, UpAxis up)
{
    const int a1 = (up.axis + 1) % 3, a2 = (up.axis + 2) % 3;
    const double turn = 0.47, tilt = 0.33;
    std::vector<std::array<double, 2>> p(model.nodes.size());
    for (size_t i = 0; i < p.size(); ++i)
    {
        const double x = model.nodes[i].coord(a1) * up.sign, z = model.nodes[i].coord(a2);
        const double y = up.sign * model.nodes[i].coord(up.axis);
        const double sx = x * std::cos(turn) + z * std::sin(turn);
        const double depth = -x * std::sin(turn) + z * std::cos(turn);
        p[i] = {sx, y * std::cos(tilt) - depth * std::sin(tilt)};
    }
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (const auto& q : p)
        for (int k = 0; k < 2; ++k)
        {
            lo[k] = std::min(lo[k], q[k]);
            hi[k] = std::max(hi[k], q[k]);
        }
    const double span = std::max({hi[0] - lo[0], hi[1] - lo[1], 1e-9});
    const double s = (kPanel - 2 * kMargin) / span;
    for (auto& q : p)
        q = {kMargin + (q[0] - lo[0]) * s + 0.5 * (span - (hi[0] - lo[0])) * s,
             kPanel - kMargin - (q[1] - lo[1]) * s - 0.5 * (span - (hi[1] - lo[1])) * s};
    return p;
}

void line(std::ostream& os, const std::array<double, 2>& a, const std::array<double, 2>& b, const char* colour,
          double width)
{
    os << "<line x1=\"" << fixed(a[0]) << "\" y1=\"" << fixed(a[1]) << "\" x2=\"" << fixed(b[0]) << "\" y2=\""
       << fixed(b[1]) << "\" stroke=\"" << colour << "\" stroke-width=\"" << width << "\"/>";
}

void step_svg(std::ostream& os, const ZomeModel& model, const std::vector<StrutKind>& kinds,
              const std::vector<std::array<double, 2>>& p, const std::vector<int>& strut_step,
              const std::vector<int>& ball_step, int s, const std::vector<uint32_t>& attach)
{
    os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kPanel << "\" height=\"" << kPanel
       << "\" viewBox=\"0 0 " << kPanel << " " << kPanel << "\">";
    // Painter's order: the parts still to come, what stands (one path each, to keep the page
    // small), then this step's struts on top, each in its colour.
    std::string later, built;
    for (size_t i = 0; i < model.struts.size(); ++i)
    {
        const auto [a, b] = model.struts[i];
        if (strut_step[i] == s)
            continue;
        std::string& d = strut_step[i] > s ? later : built;
        d.append("M").append(fixed(p[a][0])).append(" ").append(fixed(p[a][1]));
        d.append("L").append(fixed(p[b][0])).append(" ").append(fixed(p[b][1]));
    }
    os << "<path d=\"" << later << "\" stroke=\"#e6e6e6\" stroke-width=\"1\" fill=\"none\"/>";
    os << "<path d=\"" << built << "\" stroke=\"#8a8a8a\" stroke-width=\"1.5\" fill=\"none\"/>";
    for (size_t i = 0; i < model.struts.size(); ++i)
        if (strut_step[i] == s)
            line(os, p[model.struts[i][0]], p[model.struts[i][1]], strut_colour(kinds[i]), 4);
    for (size_t v = 0; v < model.nodes.size(); ++v)
        if (ball_step[v] == s)
            os << "<circle cx=\"" << fixed(p[v][0]) << "\" cy=\"" << fixed(p[v][1])
               << "\" r=\"5\" fill=\"#ffffff\" stroke=\"#000000\" stroke-width=\"2\"/>";
    for (uint32_t v : attach)
        os << "<circle cx=\"" << fixed(p[v][0]) << "\" cy=\"" << fixed(p[v][1])
           << "\" r=\"4\" fill=\"#8a8a8a\" stroke=\"#000000\"/>";
    os << "</svg>";
}

} // namespace

std::string steps_html(const ZomeModel& model, const BuildPlan& plan, const std::string& title)
{
    const std::vector<StrutKind> kinds = strut_kinds(model);
    const auto p = project(model, plan.up);
    std::vector<int> strut_step(model.struts.size(), -1), ball_step(model.nodes.size(), -1);
    for (size_t s = 0; s < plan.steps.size(); ++s)
    {
        for (uint32_t i : plan.steps[s].struts)
            strut_step[i] = static_cast<int>(s);
        for (uint32_t v : plan.steps[s].balls)
            ball_step[v] = static_cast<int>(s);
    }
    std::ostringstream os;
    os << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
       << "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'; "
          "img-src data:\">"
       << "<title>Build steps: " << escape(title) << "</title><style>"
       << "body{font-family:sans-serif;margin:1em;color:#111}"
       << ".step{display:inline-block;vertical-align:top;width:320px;margin:0 1em 1em "
          "0;break-inside:avoid;page-break-inside:avoid}"
       << ".step h2{font-size:1.1em;margin:.2em 0}.step ul{margin:.2em 0;padding-left:1.2em}"
       << "svg{border:1px solid #ccc;background:#fff}</style></head><body>\n";
    os << "<h1>Build steps: " << escape(title) << "</h1>\n<p>" << model.nodes.size() << " balls and "
       << model.struts.size() << " struts in " << plan.steps.size() << " steps, " << up_axis_name(plan.up)
       << " up. Each picture shows what stands in grey, this step's struts in their colours and its new balls"
       << " as white circles; grey dots are the balls they attach to.";
    if (plan.mirror)
        os << ' ' << halves_alike_text(plan);
    os << "</p>\n";
    for (size_t s = 0; s < plan.steps.size(); ++s)
    {
        const BuildStep& st = plan.steps[s];
        os << "<section class=\"step\" id=\"step-" << s + 1 << "\"><h2>Step " << s + 1 << " of " << plan.steps.size()
           << "</h2>";
        step_svg(os, model, kinds, p, strut_step, ball_step, static_cast<int>(s), st.attach);
        os << "<ul><li>" << st.balls.size() << " &times; ball " << kBallPartCode << "</li>";
        const auto counts = step_strut_counts(kinds, st);
        for (int k = 0; k < kStrutKindCount; ++k)
            if (counts[k])
            {
                const StrutKindInfo& info = kind_info(static_cast<StrutKind>(k));
                os << "<li>" << counts[k] << " &times; " << info.name << " " << info.color << " " << info.part_code
                   << "</li>";
            }
        os << "</ul><p>"
           << (s == 0 ? std::string("Start on the table.")
                      : "Attach to " + std::to_string(st.attach.size()) + (st.attach.size() == 1 ? " ball" : " balls") +
                            " already built.")
           << "</p></section>\n";
    }
    os << "</body></html>\n";
    return os.str();
}

} // namespace zomeify
