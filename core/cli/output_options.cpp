#include "core/cli/output_options.h"

namespace zomeify::cli {

WriteOptions write_options(const Args& args)
{
    WriteOptions o;
    if (const auto units = args.value(kObjUnitsOption))
        o.obj_units = parse_obj_units(*units);
    o.vef_faces = !args.has(kNoFacesFlag);
    return o;
}

} // namespace zomeify::cli
