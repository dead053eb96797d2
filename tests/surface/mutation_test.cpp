// Hostile input beyond the hand-written corpus: every prefix and many random mutations of valid
// files in each format. Each read either succeeds (and the repair then runs without crashing) or
// throws InvalidInputError; anything else fails. Run under ASan/UBSan this catches out-of-bounds
// reads and overflows that a clean message would hide.
#include <random>

#include <gtest/gtest.h>

#include "core/base/errors.h"
#include "core/surface/prepare.h"
#include "core/surface/read_mesh.h"
#include "tests/surface/surface_fixtures.h"

namespace zomeify::surface_test {
namespace {

struct Sample
{
    std::string name;
    std::string bytes;
};

std::vector<Sample> valid_samples()
{
    const PolygonSoup prism = pentagonal_prism();
    return {
        {"m.obj", to_obj(prism)},
        {"m.off", to_off(prism)},
        {"m.stl", to_stl_ascii(cube_quads())},
        {"m.stl", to_stl_binary(cube_quads())},
        {"m.ply", to_ply(prism, PlyEncoding::ascii)},
        {"m.ply", to_ply(prism, PlyEncoding::little_endian)},
        {"m.ply", to_ply(prism, PlyEncoding::big_endian, true)},
        {"m.glb", to_gltf(cube_quads(), true)},
        {"m.gltf", to_gltf(cube_quads(), false)},
    };
}

// Reads and repairs; returns false (with a test failure) only for an unexpected exception type.
void read_and_repair(const std::string& bytes, const std::string& name)
{
    try
    {
        const PolygonSoup soup = read_mesh_buffer(bytes_of(bytes), name);
        const SurfaceReport report = diagnose(soup);
        if (report.ok())
            EXPECT_NO_THROW(prepare_surface(soup));
        else
            EXPECT_THROW(prepare_surface(soup), InvalidInputError);
    }
    catch (const InvalidInputError& e)
    {
        const std::string message = e.what();
        EXPECT_EQ(message.find('\n'), std::string::npos) << "a multi-line message: " << message;
        EXPECT_EQ(message.rfind(name + ": ", 0), 0u) << message;
    }
    catch (const std::exception& e)
    {
        ADD_FAILURE() << name << ": unexpected exception: " << e.what();
    }
}

TEST(SurfaceMutation, EveryPrefix)
{
    for (const Sample& s : valid_samples())
    {
        SCOPED_TRACE(s.name);
        for (size_t n = 0; n < s.bytes.size(); ++n)
            read_and_repair(s.bytes.substr(0, n), s.name);
    }
}

TEST(SurfaceMutation, RandomByteChanges)
{
    std::mt19937 rng(2026);
    for (const Sample& s : valid_samples())
    {
        SCOPED_TRACE(s.name);
        for (int round = 0; round < 400; ++round)
        {
            std::string bytes = s.bytes;
            const int changes = 1 + static_cast<int>(rng() % 4);
            for (int c = 0; c < changes; ++c)
            {
                const size_t at = rng() % bytes.size();
                // Half the time a digit or separator, which keeps text formats parseable and so
                // reaches deeper checks (counts, indices) than random bytes do.
                const char* const pool = "0123456789 -.\n";
                bytes[at] = rng() % 2 ? pool[rng() % 14] : static_cast<char>(rng() & 0xFF);
            }
            read_and_repair(bytes, s.name);
        }
    }
}

} // namespace
} // namespace zomeify::surface_test
