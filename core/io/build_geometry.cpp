#include "core/io/build_geometry.h"

#include <algorithm>
#include <cmath>

#include "core/base/errors.h"
#include "core/zome/real_sizes.h"

namespace zomeify {

namespace {

constexpr float kPi = 3.14159265358979f;

float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

std::array<float, 3> linear(const std::array<float, 3>& srgb)
{
    return {srgb_to_linear(srgb[0]), srgb_to_linear(srgb[1]), srgb_to_linear(srgb[2])};
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
    auto add = [&](const std::array<float, 3>& n) {
        m.normals.push_back(n);
        m.positions.push_back({radius * n[0], radius * n[1], radius * n[2]});
    };
    add({0.0f, 1.0f, 0.0f}); // top pole: vertex 0
    for (int s = 1; s < stacks; ++s)
    {
        const float theta = kPi * static_cast<float>(s) / static_cast<float>(stacks);
        for (int i = 0; i < slices; ++i)
        {
            const float phi = 2 * kPi * static_cast<float>(i) / static_cast<float>(slices);
            add({std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi)});
        }
    }
    add({0.0f, -1.0f, 0.0f}); // bottom pole: the last vertex
    const auto n_slices = static_cast<uint32_t>(slices), n_stacks = static_cast<uint32_t>(stacks);
    const auto bottom = static_cast<uint32_t>(m.positions.size() - 1);
    // Vertex of stack s (0 = top pole, stacks = bottom pole) and slice i (wrapping around).
    auto at = [&](uint32_t s, uint32_t i) -> uint32_t {
        if (s == 0)
            return 0;
        if (s == n_stacks)
            return bottom;
        return 1 + (s - 1) * n_slices + i % n_slices;
    };
    for (uint32_t s = 0; s < n_stacks; ++s)
        for (uint32_t i = 0; i < n_slices; ++i)
        {
            const uint32_t a = at(s, i), b = at(s, i + 1), c = at(s + 1, i), d = at(s + 1, i + 1);
            if (s != 0)
                m.indices.insert(m.indices.end(), {a, c, b});
            if (s + 1 != n_stacks)
                m.indices.insert(m.indices.end(), {b, c, d});
        }
    return m;
}

std::array<float, 3> zome_color_srgb(Color c)
{
    switch (c)
    {
    case Color::Blue:
        return {0.05f, 0.36f, 0.75f};
    case Color::Yellow:
        return {0.98f, 0.78f, 0.05f};
    case Color::Red:
        return {0.80f, 0.10f, 0.10f};
    }
    return {1, 1, 1};
}

std::array<float, 3> ball_color_srgb() { return {0.93f, 0.93f, 0.93f}; }

std::array<float, 3> zome_color_linear(Color c) { return linear(zome_color_srgb(c)); }

std::array<float, 3> ball_color_linear() { return linear(ball_color_srgb()); }

BuildGeometry build_geometry(const ZomeModel& model)
{
    BuildGeometry g;
    // On the table: x and z centred on the balls' extent, the lowest ball resting on y = 0.
    std::array<double, 3> lo{0, 0, 0}, hi{0, 0, 0};
    for (size_t i = 0; i < model.nodes.size(); ++i)
    {
        const auto d = model.nodes[i].to_double();
        for (size_t k = 0; k < 3; ++k)
        {
            lo[k] = i == 0 ? d[k] : std::min(lo[k], d[k]);
            hi[k] = i == 0 ? d[k] : std::max(hi[k], d[k]);
        }
    }
    const double radius = kBallDiameterMm / 2;
    for (size_t k = 0; k < 3; ++k)
        g.size_mm[k] = model.nodes.empty() ? 0.0 : (hi[k] - lo[k]) * kMmPerB0 + kBallDiameterMm;
    g.shift_mm = {-0.5 * (lo[0] + hi[0]) * kMmPerB0, radius - lo[1] * kMmPerB0, -0.5 * (lo[2] + hi[2]) * kMmPerB0};
    auto mm = [&g](const ZVec& p) {
        const auto d = p.to_double();
        return std::array<float, 3>{static_cast<float>(d[0] * kMmPerB0 + g.shift_mm[0]),
                                    static_cast<float>(d[1] * kMmPerB0 + g.shift_mm[1]),
                                    static_cast<float>(d[2] * kMmPerB0 + g.shift_mm[2])};
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
        g.struts_by_kind[static_cast<size_t>(vector_kind(id))].push_back(
            {mm(model.nodes[st[0]]), rotation_from_y(d), static_cast<uint32_t>(s)});
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
