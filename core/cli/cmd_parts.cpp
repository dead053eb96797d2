// zomeify parts MODEL [--json | --csv]: the parts list of a .zome.json or .vef model.
#include <iostream>

#include "core/base/errors.h"
#include "core/cli/args.h"
#include "core/cli/commands.h"
#include "core/io/model_io.h"
#include "core/parts/parts_list.h"

namespace zomeify::cli {

int cmd_parts(const CommandArgs& argv)
{
    const Args args(argv, {}, {"--json", "--csv"});
    args.expect_positional(1, "one model file: zomeify parts MODEL [--json | --csv]");
    if (args.has("--json") && args.has("--csv"))
        throw InvalidInputError("choose one of --json and --csv");
    const PartsList parts = parts_list(read_model_file(args.positional()[0]));
    if (args.has("--json"))
        std::cout << parts_json(parts);
    else if (args.has("--csv"))
        std::cout << parts_csv(parts);
    else
        std::cout << parts_table(parts);
    return 0;
}

} // namespace zomeify::cli
