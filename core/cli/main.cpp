// zomeify: the command-line front end (design.md §5). Bad input → one line on stderr, exit 1.
#include <cstring>
#include <exception>
#include <iostream>
#include <new>

#include "core/base/errors.h"
#include "core/cli/commands.h"

namespace zomeify::cli {

const std::vector<Command>& commands()
{
    static const std::vector<Command> list = {
        {"inspect",
         "inspect MESH [--json] [--thicken]     vertices, faces, closed, manifold, components, genus, bbox, repairs",
         cmd_inspect},
        {"parts", "parts MODEL [--json | --csv] [--have KITS]  parts list and kit plan of a .zome.json or .vef model",
         cmd_parts},
        {"convert",
         "convert MODEL -o OUT [-o OUT2 ...] [--obj-units mm|m] [--no-faces]   to .zome.json, .vef, .glb (metres),\n"
         "          .obj (+.mtl; mm unless --obj-units m) or .csv; --no-faces: VEF without panels",
         cmd_convert},
        {"link", "link MODEL | link --decode FRAGMENT -o OUT   share-link fragment of a model, and back", cmd_link},
        {"steps",
         "steps MODEL [--json] [-o steps.html] [--up AXIS]  assembly sequence: steps of a few parts, from the table up",
         cmd_steps},
        {"score",
         "score MODEL --mesh MESH [--b0 L] [--samples N] [--near X,Y,Z --radius R] [--json] [--thicken]\n"
         "          energy, fold-overs and distance of a model against "
         "a mesh",
         cmd_score},
        {"run",
         "run MESH -o OUT [-o OUT2 ...] [--resolution N | --b1 L | --size-cm CM] [--target-nodes N] [--seconds S | "
         "--proposals N]\n"
         "          [--threads T] [--seed K] [--t0 T | --t0-factor F] [--t-min T | --t-min-ratio R]\n"
         "          [--operator-weights I,A,S,R,F,M,N] [--coverage-radius B0S] [--initial-only] [--stats STATS.json]\n"
         "          [--obj-units mm|m] [--no-faces] [--thicken]   Z0, then annealing; --thicken: an open sheet is\n"
         "          given a thickness instead of being refused\n"
         "          [--have KITS [--fit-kits]]   the run keeps within the kits you own; --fit-kits chooses the\n"
         "          size and ball count so that it does (checked on the result, up to 3 tries)\n"
         "          [--from MODEL [--near X,Y,Z --radius R]]   anneal from a model made for this mesh (a .zome.json\n"
         "          or a share link) instead of Z0; --near: change only the part within R of the point\n"
         "          [--within-estimate]   name the kits before annealing (a short pass) and keep within them,\n"
         "          as the page does",
         cmd_run},
    };
    return list;
}

} // namespace zomeify::cli

namespace {

void usage(std::ostream& os)
{
    os << "usage: zomeify COMMAND ...\n";
    for (const auto& c : zomeify::cli::commands())
        os << "  zomeify " << c.usage << "\n";
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2)
    {
        std::cerr << "zomeify: missing command (try zomeify --help)\n";
        return 2;
    }
    if (!std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h"))
    {
        usage(std::cout);
        return 0;
    }
    const std::vector<std::string> rest(argv + 2, argv + argc);
    for (const auto& c : zomeify::cli::commands())
    {
        if (c.name != std::string(argv[1]))
            continue;
        try
        {
            return c.run(rest);
        }
        catch (const std::bad_alloc&)
        {
            std::cerr << "zomeify: out of memory\n";
        }
        catch (const std::exception& e)
        {
            std::cerr << "zomeify: " << e.what() << "\n";
        }
        return 1;
    }
    std::cerr << "zomeify: unknown command '" << argv[1] << "' (try zomeify --help)\n";
    return 2;
}
