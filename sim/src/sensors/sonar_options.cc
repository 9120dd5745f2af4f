#include <string>

#include "cogmap/sim/sonar_model.h"

namespace cogmap::sim {

SonarModelOptions parse_sonar_options(const yaml::Node& node) {
  node.expect_keys({"beam_sigma_deg", "fan_half_width_deg", "rays_per_cone", "detection_gain_db",
                    "corner_strength", "threshold_walk_m", "diffuse_range_gain_exponent",
                    "range_noise_fraction", "range_noise_floor_m", "dropout_probability",
                    "multipath", "cycle_ms", "polling", "corner_radius_m"});
  SonarModelOptions o;
  // Range checks here too, so the message points at the line in the experiment file.
  auto read = [&](const std::string& key, double& value, double lo, double hi,
                  const std::string& range_text) {
    if (const auto c = node.child(key)) {
      value = c->as<double>();
      if (!(value >= lo && value <= hi)) c->fail("must be " + range_text);
    }
  };
  read("beam_sigma_deg", o.beam_sigma_deg, 1e-3, 90.0, "in (0, 90]");
  read("fan_half_width_deg", o.fan_half_width_deg, 1e-3, 89.0, "in (0, 89]");
  read("detection_gain_db", o.detection_gain_db, -60.0, 60.0, "in [-60, 60]");
  read("corner_strength", o.corner_strength, 0.0, 1e6, "in [0, 1e6]");
  read("threshold_walk_m", o.threshold_walk_m, 0.0, 1.0, "in [0, 1]");
  read("diffuse_range_gain_exponent", o.diffuse_range_gain_exponent, -10.0, 10.0, "in [-10, 10]");
  read("range_noise_fraction", o.range_noise_fraction, 0.0, 1.0, "in [0, 1]");
  read("range_noise_floor_m", o.range_noise_floor_m, 0.0, 1.0, "in [0, 1]");
  read("dropout_probability", o.dropout_probability, 0.0, 1.0, "in [0, 1]");
  read("cycle_ms", o.cycle_ms, 2.0, 120.0, "in [2, 120] (P2OS SONAR_CYCLE)");
  read("corner_radius_m", o.corner_radius_m, 0.0, 1.0, "in [0, 1]");
  if (const auto c = node.child("rays_per_cone")) {
    o.rays_per_cone = c->as<int>();
    if (o.rays_per_cone < 1 || o.rays_per_cone > 1000) c->fail("must be in [1, 1000]");
  }
  o.multipath = node.get_or<bool>("multipath", o.multipath);
  if (const auto c = node.child("polling")) {
    // One list per array: [[0, 1, ..., 7], [8, ..., 15]]; array a holds transducers 8a..8a+7.
    c->expect_sequence();
    if (c->size() > 4) c->fail("at most 4 sonar arrays (P2OS numbers 1-32)");
    for (std::size_t a = 0; a < c->size(); ++a) {
      const yaml::Node array = c->at(a);
      array.expect_sequence();
      if (array.size() > 16) array.fail("a polling sequence holds at most 16 entries");
      std::vector<int> sequence;
      for (std::size_t i = 0; i < array.size(); ++i) {
        const yaml::Node item = array.at(i);
        const int index = item.as<int>();
        const int first = static_cast<int>(a) * kSonarsPerArray;
        if (index < first || index >= first + kSonarsPerArray) {
          item.fail("array " + std::to_string(a) + " holds transducers " + std::to_string(first) +
                    "-" + std::to_string(first + kSonarsPerArray - 1));
        }
        sequence.push_back(index);
      }
      o.polling.push_back(sequence);
    }
  }
  return o;
}

}  // namespace cogmap::sim
