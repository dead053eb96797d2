// zomeify parts MODEL [--json | --csv] [--have KITS]: the parts list of a .zome.json or .vef
// model, with the kit plan (and, with --have, the loose parts missing from the kits you own).
#include <iostream>

#include "core/base/errors.h"
#include "core/cli/args.h"
#include "core/cli/commands.h"
#include "core/cli/model_input.h"
#include "core/io/model_io.h"
#include "core/parts/parts_report.h"

namespace zomeify::cli {

int cmd_parts(const CommandArgs& argv)
{
    const Args args(argv, {"--have"}, {"--json", "--csv"});
    args.expect_positional(1, "one model file: zomeify parts MODEL [--json | --csv] [--have KITS]");
    if (args.has("--json") && args.has("--csv"))
        throw InvalidInputError("choose one of --json and --csv");
    const OwnedKits owned = parse_owned_kits(args.value("--have").value_or(""));
    const PartsList parts = parts_list(read_model_warning_of_clashes(args.positional()[0]));
    if (args.has("--json"))
        std::cout << parts_report_json(parts, owned);
    else if (args.has("--csv"))
        std::cout << parts_csv(parts);
    else
        std::cout << parts_report_text(parts, owned);
    return 0;
}

} // namespace zomeify::cli
