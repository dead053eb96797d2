// GLB and OBJ exports of the paper's bunny load back with the expected parts.
#include <gtest/gtest.h>

#include "core/io/file_bytes.h"
#include "core/io/glb_export.h"
#include "core/io/model_io.h"
#include "core/io/obj_export.h"
#include "core/io/vef.h"
#include "core/parts/parts_list.h"
#include "core/surface/read_mesh.h"
#include "core/surface/tiny_gltf_config.h"
#include "tests/support/paths.h"

using namespace zomeify;

TEST(Export, GlbOfTheBunnyLoadsBackWithOneMeshPerKind)
{
    const ZomeModel bunny = read_vef_file(test::shared_path("data/vef/bunny.vef"));
    const std::string glb = write_glb(bunny);
    tinygltf::Model m;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    ASSERT_TRUE(loader.LoadBinaryFromMemory(&m, &err, &warn, reinterpret_cast<const unsigned char*>(glb.data()),
                                            static_cast<unsigned int>(glb.size())))
        << err;
    ASSERT_EQ(m.meshes.size(), 10u); // the ball and the nine strut kinds
    std::map<std::string, size_t> instances;
    for (const auto& node : m.nodes)
        if (node.mesh >= 0)
            ++instances[m.meshes[static_cast<size_t>(node.mesh)].name];
    const PartsList parts = parts_list(bunny);
    EXPECT_EQ(instances["ball"], 392u);
    for (int k = 0; k < kStrutKindCount; ++k)
    {
        const StrutKindInfo& info = kind_info(static_cast<StrutKind>(k));
        EXPECT_EQ(instances[std::string(info.name)], parts.struts[static_cast<size_t>(k)]) << info.name;
    }
    // Real sizes in mm: the B1 mesh spans 74.86 mm along its axis.
    for (const auto& mesh : m.meshes)
        if (mesh.name == "B1")
        {
            const auto& pos = m.accessors[static_cast<size_t>(mesh.primitives[0].attributes.at("POSITION"))];
            EXPECT_NEAR(pos.maxValues[1] - pos.minValues[1], 74.86, 0.01);
        }
    EXPECT_EQ(m.materials.size(), 4u);
}

TEST(Export, ObjOfTheBunnyParsesBack)
{
    const ZomeModel bunny = read_vef_file(test::shared_path("data/vef/bunny.vef"));
    const ObjExport out = write_obj(bunny, "bunny.mtl");
    EXPECT_NE(out.obj.find("mtllib bunny.mtl"), std::string::npos);
    for (const char* mat : {"ball_white", "strut_blue", "strut_yellow", "strut_red"})
        EXPECT_NE(out.mtl.find(std::string("newmtl ") + mat), std::string::npos) << mat;
    const auto* bytes = reinterpret_cast<const uint8_t*>(out.obj.data());
    const PolygonSoup soup = read_mesh_buffer(std::span<const uint8_t>(bytes, out.obj.size()), "bunny.obj");
    // Sphere 12x8 → 13·9 = 117 vertices; cylinder of 8 sides → 16 + 2·9 = 34 vertices.
    EXPECT_EQ(soup.positions.size(), 392u * 117u + 968u * 34u);
}

TEST(Export, CsvAndFilesByExtension)
{
    const ZomeModel bunny = read_vef_file(test::shared_path("data/vef/bunny.vef"));
    const std::string csv = write_model_buffer(bunny, "parts.csv");
    EXPECT_NE(csv.find("PST-B0-BLU,B0,blue,46.27,179"), std::string::npos);
    const std::string obj_path = test::temp_path("bunny.obj");
    write_model_file(obj_path, bunny);
    EXPECT_FALSE(read_mesh_file(obj_path).positions.empty());
    EXPECT_NE(read_file_bytes(test::temp_path("bunny.mtl")).find("newmtl strut_red"), std::string::npos);
}
