// Fuzz target: share link decoding (versions 1 and 2). A decoded model must encode again, and that
// link must decode to a model of the same size (nodes are renumbered by the traversal, so only
// counts are compared), whose link is the same again (decoding gives the canonical numbering, and
// faces come back as the same rotation exceptions or the same explicit list).
#include <string>
#include <string_view>

#include "core/base/errors.h"
#include "core/io/share_link.h"
#include "tests/fuzz/fuzz_target.h"

ZOME_FUZZ_TARGET(share_link)
{
    using namespace zomeify;
    ZomeModel model;
    try
    {
        model = decode_share_link(std::string_view(reinterpret_cast<const char*>(data), size));
    }
    catch (const InvalidInputError&)
    {
        return 0;
    }
    const ZomeModel again = decode_share_link(encode_share_link(model));
    ZOME_FUZZ_CHECK(again.nodes.size() == model.nodes.size(), "share link round trip keeps the node count");
    ZOME_FUZZ_CHECK(again.struts.size() == model.struts.size(), "share link round trip keeps the strut count");
    ZOME_FUZZ_CHECK(again.faces.size() == model.faces.size(), "share link round trip keeps the face count");
    const std::string link = encode_share_link(again);
    ZOME_FUZZ_CHECK(encode_share_link(decode_share_link(link)) == link, "a re-shared link is a fixed point");
    return 0;
}
