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

/// An optional whole number that must lie in [lo, hi]; `fallback` when absent. A number with a
/// fraction is refused by the YAML reader ("expected an integer").
inline int whole_number_in(const yaml::Node& block, const std::string& key, int lo, int hi,
                           int fallback) {
  const auto c = block.child(key);
  if (!c) return fallback;
  const int v = c->as<int>();
  if (v < lo || v > hi) {
    c->fail(key + " must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
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
