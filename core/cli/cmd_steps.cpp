// zomeify steps MODEL [--json] [-o steps.html] [--up AXIS]: the assembly sequence of a model
// (core/build): one line a step, or one JSON object, and optionally a page to print.
#include <filesystem>
#include <iostream>

#include "core/assembly/assembly_plan.h"
#include "core/assembly/plan_report.h"
#include "core/assembly/steps_html.h"
#include "core/base/errors.h"
#include "core/cli/args.h"
#include "core/cli/commands.h"
#include "core/cli/model_input.h"
#include "core/io/file_bytes.h"

namespace zomeify::cli {

int cmd_steps(const CommandArgs& argv)
{
    const Args args(argv, {"-o", "--up"}, {"--json"});
    args.expect_positional(1, "one model file: zomeify steps MODEL [--json] [-o steps.html] [--up AXIS]");
    PlanOptions options;
    options.up = parse_up_axis(args.value("--up").value_or("y"));
    for (const std::string& out : args.values("-o"))
        if (std::filesystem::path(out).extension() != ".html")
            throw InvalidInputError("steps writes .html pages with -o, not '" + out + "'");
    const std::string& path = args.positional()[0];
    const ZomeModel model = read_model_warning_of_clashes(path);
    options.mirror = building_mirror(model, options.up); // a symmetric model: both halves alike
    const BuildPlan plan = plan_assembly(model, options);
    const PlanFigures naive = plan_breadth_first(model, options).figures;
    for (const std::string& out : args.values("-o"))
        write_file_bytes(out, steps_html(model, plan, std::filesystem::path(path).filename().string()));
    std::cout << (args.has("--json") ? plan_json(model, plan, naive) : plan_text(model, plan, naive));
    return 0;
}

} // namespace zomeify::cli
