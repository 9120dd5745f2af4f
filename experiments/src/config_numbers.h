#pragma once
/// The number checks every block of an experiment file shares (experiment_config.cc,
/// mapper_config.cc): an optional key's value, its range, and the line it is refused at.

#include <sstream>
#include <string>

#include "cogmap/sim/yaml_strict.h"

namespace cogmap::experiments::detail {

/// An optional number that must lie in [lo, hi]; `fallback` when absent.
inline double number_in(const yaml::Node& block, const std::string& key, double lo, double hi,
                        double fallback) {
  const auto c = block.child(key);
  if (!c) return fallback;
  const double v = c->as<double>();
  if (v < lo || v > hi) {
    std::ostringstream msg;
    msg << "must be in [" << lo << ", " << hi << "], got " << v;
    c->fail(msg.str());
  }
  return v;
}

/// An optional number that must be > lo (strictly).
inline double number_above(const yaml::Node& block, const std::string& key, double lo,
                           double fallback) {
  const auto c = block.child(key);
  if (!c) return fallback;
  const double v = c->as<double>();
  if (!(v > lo)) {
    std::ostringstream msg;
    msg << "must be greater than " << lo << ", got " << v;
    c->fail(msg.str());
  }
  return v;
}

}  // namespace cogmap::experiments::detail
