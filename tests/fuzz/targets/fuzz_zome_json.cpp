// Fuzz target: the .zome.json reader. What it accepts must survive a write/read round trip.
#include <string_view>

#include "core/base/errors.h"
#include "core/io/zome_json.h"
#include "tests/fuzz/fuzz_target.h"

ZOME_FUZZ_TARGET(zome_json)
{
    using namespace zomeify;
    ZomeModel model;
    try
    {
        model = read_zome_json(std::string_view(reinterpret_cast<const char*>(data), size));
    }
    catch (const InvalidInputError&)
    {
        return 0;
    }
    catch (const OverflowError&)
    {
        return 0;
    }
    const ZomeModel again = read_zome_json(write_zome_json(model));
    ZOME_FUZZ_CHECK(again.nodes == model.nodes, "zome.json round trip keeps the nodes");
    ZOME_FUZZ_CHECK(again.struts == model.struts, "zome.json round trip keeps the struts");
    ZOME_FUZZ_CHECK(again.faces == model.faces, "zome.json round trip keeps the faces");
    return 0;
}
