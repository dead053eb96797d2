// zomeify link MODEL: prints the share-link fragment of a model.
// zomeify link --decode FRAGMENT -o OUT: writes the model a link holds.
#include <iostream>

#include "core/base/errors.h"
#include "core/cli/args.h"
#include "core/cli/commands.h"
#include "core/cli/model_input.h"
#include "core/cli/output_options.h"
#include "core/io/model_io.h"
#include "core/io/share_link.h"

namespace zomeify::cli {

int cmd_link(const CommandArgs& argv)
{
    const Args args(argv, {"--decode", "-o", kObjUnitsOption}, {kNoFacesFlag});
    if (const auto fragment = args.value("--decode"))
    {
        args.expect_positional(0, "zomeify link --decode FRAGMENT -o OUT");
        const auto outputs = args.values("-o");
        if (outputs.empty())
            throw InvalidInputError("missing -o OUT");
        for (const std::string& out : outputs)
            check_writable_model_name(out);
        const WriteOptions options = write_options(args);
        const ZomeModel model = decode_share_link(*fragment);
        warn_of_clashes(model, "the link");
        for (const std::string& out : outputs)
        {
            write_model_file(out, model, options);
            std::cout << "wrote " << out << " (" << model.nodes.size() << " balls, " << model.struts.size()
                      << " struts)\n";
        }
        return 0;
    }
    args.expect_positional(1, "one model file: zomeify link MODEL");
    if (args.has("-o"))
        throw InvalidInputError("-o goes with --decode");
    std::cout << encode_share_link(read_model_warning_of_clashes(args.positional()[0])) << "\n";
    return 0;
}

} // namespace zomeify::cli
