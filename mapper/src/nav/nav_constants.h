#pragma once
// Constants several navigation sources use: defined once, since a unity build compiles a
// target's sources as one translation unit, where two files' own kPi collide.

#include <limits>
#include <numbers>

namespace cogmap::mapper::nav {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace cogmap::mapper::nav
