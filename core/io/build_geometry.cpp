#include "core/io/build_geometry.h"

#include <cmath>

#include "core/base/errors.h"
#include "core/zome/real_sizes.h"

namespace zomeify {

namespace {

constexpr float kPi = 3.14159265358979f;

float srgb_to_linear(float c)
{
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

std::array<float, 3> linear(float r, float g, float b)
{
    return {srgb_to_linear(r), srgb_to_linear(g), srgb_to_linear(b)};
}

// The unit quaternion rotating +Y onto the unit vector d.
std::array<float, 4> rotation_from_y(const std::array<double, 3>& d)
{
    const double dot = d[1];
    if (dot < -1.0 + 1e-12)
        return {1.0f, 0.0f, 0.0f, 0.0f}; // half turn about X
    // q = (y × d, 1 + y·d), normalised.
    const double x = d[2], y = 0.0, z = -d[0], w = 1.0 + dot;
    const double n = std::sqrt(x * x + y * y + z * z + w * w);
    return {static_cast<float>(x / n), static_cast<float>(y / n), static_cast<float>(z / n), static_cast<float>(w / n)};
}

} // namespace

SimpleMesh make_cylinder(float radius, float length, int sides)
{
    SimpleMesh m;
    const auto ring = static_cast<uint32_t>(sides);
    for (int end = 0; end < 2; ++end)
        for (int i = 0; i < sides; ++i)
        {
            const float a = 2 * kPi * static_cast<float>(i) / static_cast<float>(sides);
            m.positions.push_back({radius * std::cos(a), end ? length : 0.0f, -radius * std::sin(a)});
            m.normals.push_back({std::cos(a), 0.0f, -std::sin(a)});
        }
    for (uint32_t i = 0; i < ring; ++i)
    {
        const uint32_t j = (i + 1) % ring;
        m.indices.insert(m.indices.end(), {i, j, ring + j, i, ring + j, ring + i});
    }
    // Caps with their own vertices so their normals are flat.
    for (int end = 0; end < 2; ++end)
    {
        const auto base = static_cast<uint32_t>(m.positions.size());
        const float y = end ? length : 0.0f, ny = end ? 1.0f : -1.0f;
        m.positions.push_back({0.0f, y, 0.0f});
        m.normals.push_back({0.0f, ny, 0.0f});
        for (int i = 0; i < sides; ++i)
        {
            const float a = 2 * kPi * static_cast<float>(i) / static_cast<float>(sides);
            m.positions.push_back({radius * std::cos(a), y, -radius * std::sin(a)});
            m.normals.push_back({0.0f, ny, 0.0f});
        }
        for (uint32_t i = 0; i < ring; ++i)
        {
            const uint32_t a = base + 1 + i, b = base + 1 + (i + 1) % ring;
            if (end)
                m.indices.insert(m.indices.end(), {base, a, b});
            else
                m.indices.insert(m.indices.end(), {base, b, a});
        }
    }
    return m;
}

SimpleMesh make_sphere(float radius, int slices, int stacks)
{
    SimpleMesh m;
    for (int s = 0; s <= stacks; ++s)
    {
        const float theta = kPi * static_cast<float>(s) / static_cast<float>(stacks);
        for (int i = 0; i <= slices; ++i)
        {
            const float phi = 2 * kPi * static_cast<float>(i) / static_cast<float>(slices);
            const std::array<float, 3> n{std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi)};
            m.normals.push_back(n);
            m.positions.push_back({radius * n[0], radius * n[1], radius * n[2]});
        }
    }
    const auto row = static_cast<uint32_t>(slices + 1);
    for (uint32_t s = 0; s < static_cast<uint32_t>(stacks); ++s)
        for (uint32_t i = 0; i < static_cast<uint32_t>(slices); ++i)
        {
            const uint32_t a = s * row + i, b = a + 1, c = a + row, d = c + 1;
            if (s != 0)
                m.indices.insert(m.indices.end(), {a, c, b});
            if (s + 1 != static_cast<uint32_t>(stacks))
                m.indices.insert(m.indices.end(), {b, c, d});
        }
    return m;
}

std::array<float, 3> zome_color_linear(Color c)
{
    switch (c)
    {
    case Color::Blue:
        return linear(0.05f, 0.36f, 0.75f);
    case Color::Yellow:
        return linear(0.98f, 0.78f, 0.05f);
    case Color::Red:
        return linear(0.80f, 0.10f, 0.10f);
    }
    return {1, 1, 1};
}

std::array<float, 3> ball_color_linear()
{
    return linear(0.93f, 0.93f, 0.93f);
}

BuildGeometry build_geometry(const ZomeModel& model)
{
    BuildGeometry g;
    auto mm = [](const ZVec& p) {
        const auto d = p.to_double();
        return std::array<float, 3>{static_cast<float>(d[0] * kMmPerB0), static_cast<float>(d[1] * kMmPerB0),
                                    static_cast<float>(d[2] * kMmPerB0)};
    };
    for (const ZVec& p : model.nodes)
        g.ball_centres.push_back(mm(p));
    for (size_t s = 0; s < model.struts.size(); ++s)
    {
        const auto& st = model.struts[s];
        if (st[0] >= model.nodes.size() || st[1] >= model.nodes.size())
            throw InvalidInputError("strut " + std::to_string(s) + " refers to a missing node");
        const ZVec v = model.nodes[st[1]] - model.nodes[st[0]];
        const int id = vector_id_of(v);
        if (id < 0)
            throw InvalidInputError("strut " + std::to_string(s) + " is not a Zome strut");
        auto d = v.to_double();
        const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (double& x : d)
            x /= len;
        g.struts_by_kind[static_cast<size_t>(vector_kind(id))].push_back({mm(model.nodes[st[0]]), rotation_from_y(d)});
    }
    return g;
}

std::array<float, 3> place(const Placement& p, const std::array<float, 3>& v)
{
    // v' = q v q* + t, written out.
    const float qx = p.rotation[0], qy = p.rotation[1], qz = p.rotation[2], qw = p.rotation[3];
    const float tx = 2 * (qy * v[2] - qz * v[1]), ty = 2 * (qz * v[0] - qx * v[2]), tz = 2 * (qx * v[1] - qy * v[0]);
    return {v[0] + qw * tx + (qy * tz - qz * ty) + p.translation[0],
            v[1] + qw * ty + (qz * tx - qx * tz) + p.translation[1],
            v[2] + qw * tz + (qx * ty - qy * tx) + p.translation[2]};
}

} // namespace zomeify
