#pragma once
//! \file dir3.h
//! Plain double 3-vectors for the face-recovery code (the mesh module sits beside geom, so no Eigen).

#include <array>
#include <cmath>

namespace zomeify::dir3 {

using Dir = std::array<double, 3>;

inline Dir sub(const Dir& a, const Dir& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Dir add(const Dir& a, const Dir& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Dir neg(const Dir& a) { return {-a[0], -a[1], -a[2]}; }
inline double dot(const Dir& a, const Dir& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Dir cross(const Dir& a, const Dir& b)
{
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Dir unit(const Dir& a)
{
    const double n = std::sqrt(dot(a, a));
    return n > 0 ? Dir{a[0] / n, a[1] / n, a[2] / n} : Dir{0, 0, 0};
}

} // namespace zomeify::dir3
