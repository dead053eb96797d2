// zomeify convert MODEL -o OUT [-o OUT2 ...] [--obj-units mm|m] [--no-faces]: between model
// formats, chosen by extension.
#include <iostream>

#include "core/base/errors.h"
#include "core/cli/args.h"
#include "core/cli/commands.h"
#include "core/cli/model_input.h"
#include "core/cli/output_options.h"
#include "core/io/model_io.h"

namespace zomeify::cli {

int cmd_convert(const CommandArgs& argv)
{
    const Args args(argv, {"-o", kObjUnitsOption}, {kNoFacesFlag});
    args.expect_positional(1, "one model file: zomeify convert MODEL -o OUT");
    const std::vector<std::string> outputs = args.values("-o");
    if (outputs.empty())
        throw InvalidInputError("missing -o OUT");
    for (const std::string& out : outputs)
        check_writable_model_name(out);
    const WriteOptions options = write_options(args);
    const ZomeModel model = read_model_warning_of_clashes(args.positional()[0]);
    for (const std::string& out : outputs)
    {
        write_model_file(out, model, options);
        std::cout << "wrote " << out << " (" << model.nodes.size() << " balls, " << model.struts.size() << " struts)\n";
    }
    return 0;
}

} // namespace zomeify::cli
