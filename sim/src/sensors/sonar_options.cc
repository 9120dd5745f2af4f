#include <string>

#include "cogmap/sim/sonar_model.h"

namespace cogmap::sim {

SonarModelOptions parse_sonar_options(const yaml::Node& node) {
  node.expect_keys({"critical_angle_deg", "rays_per_cone", "range_noise_fraction",
                    "range_noise_floor_m", "dropout_probability", "multipath",
                    "transducer_period_s", "firing_order", "corner_radius_m"});
  SonarModelOptions o;
  // Range checks here too, so the message points at the line in the experiment file.
  auto read = [&](const std::string& key, double& value, double lo, double hi,
                  const std::string& range_text) {
    if (const auto c = node.child(key)) {
      value = c->as<double>();
      if (!(value >= lo && value <= hi)) c->fail("must be " + range_text);
    }
  };
  read("critical_angle_deg", o.critical_angle_deg, 1e-9, 90.0 - 1e-9, "in (0, 90)");
  read("range_noise_fraction", o.range_noise_fraction, 0.0, 1.0, "in [0, 1]");
  read("range_noise_floor_m", o.range_noise_floor_m, 0.0, 1.0, "in [0, 1]");
  read("dropout_probability", o.dropout_probability, 0.0, 1.0, "in [0, 1]");
  read("transducer_period_s", o.transducer_period_s, 1e-6, 10.0, "in (0, 10]");
  read("corner_radius_m", o.corner_radius_m, 0.0, 1.0, "in [0, 1]");
  if (const auto c = node.child("rays_per_cone")) {
    o.rays_per_cone = c->as<int>();
    if (o.rays_per_cone < 1 || o.rays_per_cone > 1000) c->fail("must be in [1, 1000]");
  }
  o.multipath = node.get_or<bool>("multipath", o.multipath);
  if (const auto c = node.child("firing_order")) {
    c->expect_sequence();
    for (std::size_t i = 0; i < c->size(); ++i) {
      const yaml::Node item = c->at(i);
      const int index = item.as<int>();
      if (index < 0) item.fail("transducer index must be >= 0");
      o.firing_order.push_back(index);
    }
  }
  return o;
}

}  // namespace cogmap::sim
