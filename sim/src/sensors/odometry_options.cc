#include <string>

#include "cogmap/sim/skid_steer.h"

namespace cogmap::sim {

OdometryOptions parse_odometry_options(const yaml::Node& node) {
  node.expect_keys({"preset", "track_m", "calibrated_track_factor", "effective_track_factor",
                    "curvature_gain", "track_noise_sd", "track_noise_correlation_s",
                    "heading_walk_sd_rad_per_sqrt_m", "speed_scale_bias", "speed_scale_sd",
                    "encoder_tick_m"});
  OdometryOptions o;
  if (const auto c = node.child("preset")) {
    const std::string preset = c->as<std::string>();
    if (preset == "ideal") {
      o = ideal_odometry_options();
    } else if (preset != "p2at") {
      c->fail("unknown preset '" + preset + "' (allowed: p2at, ideal)");
    }
  }
  // Range checks here too, so the message points at the line in the experiment file.
  auto read = [&](const std::string& key, double& value, double lo, double hi,
                  const std::string& range_text) {
    if (const auto c = node.child(key)) {
      value = c->as<double>();
      if (!(value >= lo && value <= hi)) c->fail("must be " + range_text);
    }
  };
  read("track_m", o.track_m, 1e-3, 10.0, "in (0, 10]");
  read("calibrated_track_factor", o.calibrated_track_factor, 0.1, 10.0, "in [0.1, 10]");
  read("effective_track_factor", o.effective_track_factor, 0.1, 10.0, "in [0.1, 10]");
  read("curvature_gain", o.curvature_gain, -0.9, 0.9, "in [-0.9, 0.9]");
  read("track_noise_sd", o.track_noise_sd, 0.0, 0.5, "in [0, 0.5]");
  read("track_noise_correlation_s", o.track_noise_correlation_s, 1e-3, 1e6, "in (0, 1e6]");
  read("heading_walk_sd_rad_per_sqrt_m", o.heading_walk_sd_rad_per_sqrt_m, 0.0, 1.0, "in [0, 1]");
  read("speed_scale_bias", o.speed_scale_bias, -0.5, 0.5, "in [-0.5, 0.5]");
  read("speed_scale_sd", o.speed_scale_sd, 0.0, 0.5, "in [0, 0.5]");
  read("encoder_tick_m", o.encoder_tick_m, 0.0, 0.1, "in [0, 0.1]");
  return o;
}

}  // namespace cogmap::sim
