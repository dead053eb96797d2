// Fuzz target: the VEF reader. What it accepts must survive a write/read round trip unchanged.
#include <string_view>

#include "core/base/errors.h"
#include "core/io/vef.h"
#include "tests/fuzz/fuzz_target.h"

ZOME_FUZZ_TARGET(vef)
{
    using namespace zomeify;
    ZomeModel model;
    try
    {
        model = read_vef(std::string_view(reinterpret_cast<const char*>(data), size));
    }
    catch (const InvalidInputError&)
    {
        return 0;
    }
    catch (const OverflowError&)
    {
        return 0;
    }
    // The writer uses vZome's scale, which the reader prefers, so the exact model comes back.
    const ZomeModel again = read_vef(write_vef(model));
    ZOME_FUZZ_CHECK(again.nodes == model.nodes, "VEF round trip keeps the nodes");
    ZOME_FUZZ_CHECK(again.struts == model.struts, "VEF round trip keeps the struts");
    ZOME_FUZZ_CHECK(again.faces.size() == model.faces.size(), "VEF round trip keeps the faces");
    return 0;
}
