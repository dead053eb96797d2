#include "core/io/share_link.h"
#include "core/zome/slots.h"

#include <cctype>
#include <random>

#include <gtest/gtest.h>

#include "core/base/errors.h"
#include "core/geom/closest_point.h"
#include "core/io/byte_codec.h"
#include "core/io/file_bytes.h"
#include "core/io/model_io.h"
#include "core/io/vef.h"
#include "core/mesh/recover_faces.h"
#include "core/score/fit_translation.h"
#include "core/surface/prepare.h"
#include "tests/support/model_compare.h"
#include "tests/support/paths.h"

using namespace zomeify;

namespace {

ZomeModel bunny() { return read_vef_file(test::shared_path("data/vef/bunny.vef")); }

ZomeModel icosahedron() { return read_model_file(test::test_data_path("samples/icosahedron.zome.json")); }

std::string link_error(const std::string& link)
{
    try
    {
        decode_share_link(link);
    }
    catch (const InvalidInputError& e)
    {
        const std::string msg = e.what();
        EXPECT_EQ(msg.find('\n'), std::string::npos);
        return msg;
    }
    ADD_FAILURE() << "no error for link " << link.substr(0, 80);
    return {};
}

std::string body(const ZomeModel& m)
{
    return encode_share_link(m).substr(4); // after "m=2."
}

// A version 1 link (the icosahedron with its faces) as zomeify wrote them before version 2.
std::string v1_icosahedron_body()
{
    std::string link = read_file_bytes(test::test_data_path("../fuzz/seeds/share_link/icosahedron.link"));
    while (!link.empty() && std::isspace(static_cast<unsigned char>(link.back())))
        link.pop_back();
    return link.substr(4);
}

} // namespace

TEST(ShareLink, BunnyRoundTripAndLength)
{
    ZOME_REQUIRE_SHARED();
    const ZomeModel b = bunny();
    const std::string link = encode_share_link(b);
    EXPECT_LE(link.size(), 1900u) << "the paper's bunny (968 struts) must fit in 1,900 characters";
    EXPECT_EQ(link.substr(0, 4), "m=2.");
    const ZomeModel back = decode_share_link(link);
    EXPECT_EQ(test::canonical(back), test::canonical(b));
    // Decoding yields the canonical numbering: a second trip is bit-identical.
    EXPECT_EQ(encode_share_link(back), link);
    EXPECT_EQ(decode_share_link(encode_share_link(back)), back);
}

TEST(ShareLink, FacesTransformAndComponentsSurvive)
{
    ZomeModel m = icosahedron();
    m.transform.scale = 0.125;
    m.transform.translation = {1.5, -2.0, 1.0 / 3.0};
    // A second component: a lone B2 strut far away, and an isolated ball.
    const ZVec far{{0, 40, 0, 0, 0, 0}};
    m.nodes.push_back(far);
    m.nodes.push_back(far + zome_vector(vector_id(5, 2)));
    m.nodes.push_back(ZVec{{0, 0, 0, 60, 0, 0}});
    m.struts.push_back({12, 13});
    const ZomeModel back = decode_share_link("https://example.org/zomeify/#x=1&" + encode_share_link(m) + "&y=2");
    EXPECT_EQ(test::canonical(back), test::canonical(m));
    EXPECT_EQ(back.faces.size(), 20u);
}

TEST(ShareLink, ModelLinkModelThroughTheCliFormats)
{
    ZOME_REQUIRE_SHARED();
    const ZomeModel b = bunny();
    const std::string path = test::temp_path("from_link.zome.json");
    write_model_file(path, decode_share_link(encode_share_link(b)));
    EXPECT_EQ(test::canonical(read_model_file(path)), test::canonical(b));
}

TEST(ShareLink, HostileLinksGiveClearErrors)
{
    EXPECT_NE(link_error("").find("no m="), std::string::npos);
    EXPECT_NE(link_error("#q=1.AAAA").find("no m="), std::string::npos);
    EXPECT_NE(link_error("m=3.AAAA").find("version 3"), std::string::npos);
    EXPECT_NE(link_error("m=0.AAAA").find("version 0"), std::string::npos);
    EXPECT_NE(link_error("m=x.AAAA").find("version"), std::string::npos);
    EXPECT_NE(link_error("m=1.AA*A").find("unexpected character"), std::string::npos);
    EXPECT_NE(link_error("m=1.").find("ends early"), std::string::npos);

    // Huge counts in a valid header.
    ByteWriter w;
    w.u8(0);
    w.varint(uint64_t{1} << 40);
    w.varint(3);
    EXPECT_NE(link_error("m=1." + base64url_encode(w.bytes())).find("node count"), std::string::npos);

    // A strut vector id that is no Zome vector.
    ByteWriter v;
    v.u8(0);
    v.varint(2);
    v.varint(1);
    for (int i = 0; i < 6; ++i)
        v.zigzag(0);
    v.varint(1);
    v.u8(200);
    v.varint(0);
    EXPECT_NE(link_error("m=1." + base64url_encode(v.bytes())).find("not a Zome vector"), std::string::npos);

    // A face that follows a strut its node does not have (version 1's explicit faces).
    std::vector<uint8_t> bytes = base64url_decode(v1_icosahedron_body());
    bytes.back() = 60; // last face corner: neighbour index 60 of at most 5
    EXPECT_NE(link_error("m=1." + base64url_encode(bytes)).find("missing strut"), std::string::npos);

    // Garbage appended to a valid link.
    const std::string good = body(icosahedron());
    bytes = base64url_decode(good);
    bytes.push_back(7);
    EXPECT_NE(link_error("m=2." + base64url_encode(bytes)).find("unexpected data"), std::string::npos);

    // Version 2: more face exceptions than nodes, and one that is out of range.
    bytes = base64url_decode(good);
    bytes.back() = 60; // the exception count (the icosahedron needs none)
    EXPECT_NE(link_error("m=2." + base64url_encode(bytes)).find("face exceptions"), std::string::npos);
    bytes.back() = 1;
    bytes.push_back(0);
    bytes.push_back(120); // node 0 has 5 struts: 4! = 24 rotations
    EXPECT_NE(link_error("m=2." + base64url_encode(bytes)).find("out of range"), std::string::npos);
}

TEST(ShareLink, TruncatedAndRandomLinksNeverCrash)
{
    ZOME_REQUIRE_SHARED();
    const std::string good = encode_share_link(bunny());
    for (size_t cut = 0; cut < good.size(); cut += 7)
        EXPECT_THROW(decode_share_link(good.substr(0, cut)), InvalidInputError) << "cut at " << cut;
    std::mt19937 rng(2024);
    const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
    for (int trial = 0; trial < 400; ++trial)
    {
        std::string m = good;
        for (int k = 0; k < 3; ++k)
            m[4 + rng() % (m.size() - 4)] = alphabet[rng() % alphabet.size()];
        try
        {
            decode_share_link(m); // may decode to another valid model
        }
        catch (const InvalidInputError&)
        {
        }
        std::string junk = trial % 2 ? "m=1." : "m=2.";
        for (size_t n = rng() % 200; n > 0; --n)
            junk.push_back(alphabet[rng() % alphabet.size()]);
        try
        {
            decode_share_link(junk);
        }
        catch (const InvalidInputError&)
        {
        }
    }
}

// Found by fuzzing (tests/fuzz, target share_link): one flipped bit in the icosahedron's link gave a
// face whose corners followed struts but whose closing edge was none; decoding accepted it and
// sharing the model again then failed. Every decoded model must be shareable again.
TEST(ShareLink, FacesMustCloseAlongAStrut)
{
    const std::string flipped =
        "m=1.AgweAAAKAAACBQkVG05UBB4kRUsDDzM2Aw8tPAMDM0UCLUsDADxOAjZUAhseAhUkAQkAFAAAAAEAAAECAAA"
        "CAQAAAwEAAAQCAAICAwAAAwEAAAQCAAIDAwAABAEAAgIDAAAEAgACAgQAAAQDAAIDAwACAgQAAAQCAAIDBAA"
        "GBAQAAgME";
    EXPECT_NE(link_error(flipped).find("does not close along a strut"), std::string::npos);

    for (const std::string version : {"1", "2"})
    {
        const std::vector<uint8_t> good =
            base64url_decode(version == "1" ? v1_icosahedron_body() : body(icosahedron()));
        for (size_t bit = 0; bit < 8 * good.size(); ++bit)
        {
            std::vector<uint8_t> bytes = good;
            bytes[bit / 8] ^= static_cast<uint8_t>(1u << (bit % 8));
            ZomeModel model;
            try
            {
                model = decode_share_link("m=" + version + "." + base64url_encode(bytes));
            }
            catch (const InvalidInputError&)
            {
                continue;
            }
            EXPECT_NO_THROW(encode_share_link(model)) << "version " << version << ", bit " << bit;
        }
    }
}

// Version 1 links made before version 2 still decode, to the same model.
TEST(ShareLink, Version1LinksStillDecode)
{
    const ZomeModel ico = decode_share_link("m=1." + v1_icosahedron_body());
    EXPECT_EQ(test::canonical(ico), test::canonical(icosahedron()));
    EXPECT_EQ(ico.faces.size(), 20u);
    std::string dodeca = read_file_bytes(test::test_data_path("../fuzz/seeds/share_link/dodecahedron.link"));
    const ZomeModel d = decode_share_link(dodeca);
    EXPECT_EQ(d.nodes.size(), 20u);
    EXPECT_EQ(d.struts.size(), 30u);
    // Sharing it again gives a version 2 link of the same model.
    EXPECT_EQ(test::canonical(decode_share_link(encode_share_link(ico))), test::canonical(ico));
}

// Faces the struts determine cost next to nothing: the icosahedron's 20 faces need no exception.
TEST(ShareLink, FacesTheStrutsDetermineAreNotStored)
{
    ZomeModel ico = icosahedron();
    const std::string with = encode_share_link(ico);
    ico.faces.clear();
    const std::string without = encode_share_link(ico);
    EXPECT_LE(with.size(), without.size() + 2) << with << " against " << without;
}

// Faces that are not a closed surface over the struts travel explicitly, and come back.
TEST(ShareLink, OtherFacesTravelExplicitly)
{
    ZomeModel ico = icosahedron();
    ico.faces.resize(7); // an open surface: some struts lie on one face only
    const ZomeModel back = decode_share_link(encode_share_link(ico));
    EXPECT_EQ(test::canonical(back), test::canonical(ico));
}

// The paper's bunny with the surface its struts carry (578 faces recovered with the input
// surface's normals, as tests/score/recover_faces_test.cpp does): the faces cost a few exceptions.
TEST(ShareLink, PapersBunnyWithItsFacesStaysShort)
{
    ZOME_REQUIRE_SHARED();
    ZomeModel b = bunny();
    const SurfaceProjector surface(load_surface(test::shared_path("data/meshes/bunny.obj")));
    b.transform = fit_translation(b, surface, 0.1179);
    std::vector<std::array<double, 3>> normals;
    for (const ZVec& p : b.nodes)
    {
        const auto d = p.to_double();
        const auto& t = b.transform;
        const Vec3 n = surface
                           .project(Vec3(t.scale * d[0] + t.translation[0], t.scale * d[1] + t.translation[1],
                                         t.scale * d[2] + t.translation[2]))
                           .normal;
        normals.push_back({n.x(), n.y(), n.z()});
    }
    const FaceRecovery r = recover_faces(b, normals);
    ASSERT_TRUE(r.ok) << r.error;
    b.faces = r.faces;
    b.transform = {};
    const std::string link = encode_share_link(b);
    RecordProperty("characters", static_cast<int>(link.size()));
    EXPECT_LE(link.size(), 1900u);
    // The guessed rotation uses only correctly rounded arithmetic, so a link made natively decodes
    // the same in WebAssembly: the link is pinned (FNV-1a), and the wasm lane runs this test too.
    uint64_t fnv = 1469598103934665603u;
    for (char c : link)
        fnv = (fnv ^ static_cast<uint8_t>(c)) * 1099511628211u;
    RecordProperty("fnv", std::to_string(fnv));
    EXPECT_EQ(fnv, 6629068043921644109u) << link;
    const ZomeModel back = decode_share_link(link);
    EXPECT_EQ(test::canonical(back), test::canonical(b));
    EXPECT_EQ(back.faces.size(), 578u);
}
