#pragma once
// One degree of angle in radians, pi / 180. Angles are computed in radians
// (SI) and read and shown in degrees: `a_deg * degree` is an angle in
// radians, `a_rad / degree` one in degrees. Every file that converts uses
// this one constant (a file-local copy in each would also collide in a unity
// batch, cmake/unity_build.cmake).
#include <numbers>

namespace rollcheck
{
inline constexpr double degree = std::numbers::pi / 180;
} // namespace rollcheck
