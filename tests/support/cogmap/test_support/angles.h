#pragma once
// The angle constants the tests share. One definition, not one per test file: a unity build
// compiles a target's test files as one translation unit, where two files' own kDeg collide.

#include <numbers>

namespace cogmap {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kDeg = std::numbers::pi / 180.0;  // radians in one degree

/// Degrees to radians, as (deg · π) / 180.
inline double rad(double deg) { return deg * std::numbers::pi / 180.0; }

}  // namespace cogmap
