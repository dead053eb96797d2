// zomeify parts MODEL [--json | --csv] [--have KITS]: the parts list of a .zome.json or .vef
// model, with the kit plan (and, with --have, the loose parts missing from the kits you own); a
// mirror-symmetric model also gets its parts by half and middle (parts/mirror_halves.h).
#include <iostream>

#include "core/base/errors.h"
#include "core/cli/args.h"
#include "core/cli/commands.h"
#include "core/cli/model_input.h"
#include "core/io/model_io.h"
#include "core/parts/mirror_halves.h"
#include "core/parts/parts_report.h"

namespace zomeify::cli {

int cmd_parts(const CommandArgs& argv)
{
    const Args args(argv, {"--have"}, {"--json", "--csv"});
    args.expect_positional(1, "one model file: zomeify parts MODEL [--json | --csv] [--have KITS]");
    if (args.has("--json") && args.has("--csv"))
        throw InvalidInputError("choose one of --json and --csv");
    const OwnedKits owned = parse_owned_kits(args.value("--have").value_or(""));
    const ZomeModel model = read_model_warning_of_clashes(args.positional()[0]);
    const PartsList parts = parts_list(model);
    const std::optional<MirrorHalves> halves = mirror_halves(model);
    if (args.has("--json"))
    {
        nlohmann::json doc = nlohmann::json::parse(parts_report_json(parts, owned));
        if (halves)
            doc["mirror"] = mirror_halves_json(*halves);
        std::cout << doc.dump(2) << "\n";
    }
    else if (args.has("--csv"))
        std::cout << parts_csv(parts);
    else
        std::cout << parts_report_text(parts, owned) << (halves ? mirror_halves_text(*halves) : "");
    return 0;
}

} // namespace zomeify::cli
