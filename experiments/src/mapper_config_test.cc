// The experiment file's mapper block (mapper_config.cc): every extension of the thesis's mapper
// parses, defaults as MapperOptions says, and refuses what is out of range.
#include <gtest/gtest.h>

#include <numbers>

#include "cogmap/experiments/experiment_config.h"
#include "experiment_config_test_support.h"

namespace cogmap::experiments {
namespace {

namespace fs = std::filesystem;
using test::error_of;
using test::write_temp;

TEST(MapperConfig, LocalisationExtensionsParseAndDefault) {
  const fs::path p = write_temp("minimal_em.yaml", "name: m\nworld: w.yaml\n");
  const Experiment defaults = load_experiment(p);
  EXPECT_TRUE(defaults.mapper.localizer.odometry_prior);      // the prior is EM's gate
  EXPECT_TRUE(defaults.mapper.localizer.prior_shrinks);       // ... and the posterior mean applied
  EXPECT_EQ(defaults.mapper.localizer.reference_rooms, 32u);  // against the last 32 rooms
  EXPECT_FALSE(defaults.mapper.glimpse.enabled);
  const Experiment e = load_experiment(
      p, {"mapper.em_prior_shrinks=false", "mapper.em_reference_rooms=8", "mapper.glimpse=true",
          "mapper.glimpse_distance_m=4.5", "mapper.glimpse_turn_deg=90",
          "mapper.glimpse_min_wall_m=0.5", "mapper.glimpse_min_total_wall_m=2"});
  EXPECT_FALSE(e.mapper.localizer.prior_shrinks);
  EXPECT_EQ(e.mapper.localizer.reference_rooms, 8u);
  EXPECT_TRUE(e.mapper.glimpse.enabled);
  EXPECT_DOUBLE_EQ(e.mapper.glimpse.distance_m, 4.5);
  EXPECT_NEAR(e.mapper.glimpse.turn_rad, std::numbers::pi / 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(e.mapper.glimpse.min_wall_length_m, 0.5);
  EXPECT_DOUBLE_EQ(e.mapper.glimpse.min_total_wall_m, 2.0);
  EXPECT_NE(error_of(p, {"mapper.em_reference_rooms=0"}), "no error");
  EXPECT_NE(error_of(p, {"mapper.em_reference_rooms=2.5"}).find("expected an integer"),
            std::string::npos);
  EXPECT_NE(error_of(p, {"mapper.glimpse_distance_m=0.1"}), "no error");
  // The thesis's own mixture (docs/algorithms.md, "The thesis's EM, exactly"): unlabelled
  // sources, no clutter component, every direction weighing the same.
  EXPECT_TRUE(defaults.mapper.localizer.label_sources);
  EXPECT_DOUBLE_EQ(defaults.mapper.localizer.clutter_weight, 0.1);
  EXPECT_TRUE(defaults.mapper.localizer.weight_by_length);
  const Experiment thesis =
      load_experiment(p, {"mapper.em_label_sources=false", "mapper.em_clutter_weight=0",
                          "mapper.em_weight_by_length=false"});
  EXPECT_FALSE(thesis.mapper.localizer.label_sources);
  EXPECT_DOUBLE_EQ(thesis.mapper.localizer.clutter_weight, 0.0);
  EXPECT_FALSE(thesis.mapper.localizer.weight_by_length);
  EXPECT_NE(error_of(p, {"mapper.em_clutter_weight=1"}), "no error");
  EXPECT_NE(error_of(p, {"mapper.em_clutter_weight=nan"}), "no error");
  // EM's wall directions from the echoes (docs/algorithms.md, "Wall directions from the
  // echoes"): off (the thesis's fitted lines); 20 echoes and 5° unless set.
  EXPECT_DOUBLE_EQ(defaults.mapper.localizer.echo_refit.band_m, 0.0);
  EXPECT_EQ(defaults.mapper.localizer.echo_refit.min_echoes, 20);
  EXPECT_NEAR(defaults.mapper.localizer.echo_refit.max_turn_rad, 5.0 * std::numbers::pi / 180.0,
              1e-6);
  const Experiment refit =
      load_experiment(p, {"mapper.em_echo_refit_band_m=0.12", "mapper.em_echo_refit_min_echoes=40",
                          "mapper.em_echo_refit_max_turn_deg=3"});
  EXPECT_DOUBLE_EQ(refit.mapper.localizer.echo_refit.band_m, 0.12);
  EXPECT_EQ(refit.mapper.localizer.echo_refit.min_echoes, 40);
  EXPECT_NEAR(refit.mapper.localizer.echo_refit.max_turn_rad, 3.0 * std::numbers::pi / 180.0,
              1e-12);
  EXPECT_NE(error_of(p, {"mapper.em_echo_refit_band_m=-0.1"}), "no error");
  EXPECT_NE(error_of(p, {"mapper.em_echo_refit_band_m=2"}), "no error");
  EXPECT_NE(error_of(p, {"mapper.em_echo_refit_min_echoes=1"}).find("[2, 100000]"),
            std::string::npos);
  EXPECT_NE(error_of(p, {"mapper.em_echo_refit_min_echoes=2.5"}).find("expected an integer"),
            std::string::npos);
  EXPECT_NE(error_of(p, {"mapper.em_echo_refit_max_turn_deg=50"}), "no error");
  // Scan matching: off; 1 m or half a radian, 100 echoes, 3 000 readings of memory unless set.
  EXPECT_FALSE(defaults.mapper.scan_match.enabled);
  EXPECT_EQ(defaults.mapper.scan_match.min_window_echoes, 100u);
  const Experiment matched = load_experiment(
      p, {"mapper.scan_match=true", "mapper.scan_match_interval_m=2",
          "mapper.scan_match_interval_deg=45", "mapper.scan_match_min_window_echoes=150",
          "mapper.scan_match_memory_readings=6000", "mapper.scan_match_correlated_echoes=5",
          "mapper.scan_match_sigma_m=0.15", "mapper.scan_match_rotation=false",
          "mapper.scan_match_shift=false"});
  EXPECT_TRUE(matched.mapper.scan_match.enabled);
  EXPECT_DOUBLE_EQ(matched.mapper.scan_match.interval_m, 2.0);
  EXPECT_NEAR(matched.mapper.scan_match.interval_rad, std::numbers::pi / 4.0, 1e-12);
  EXPECT_EQ(matched.mapper.scan_match.min_window_echoes, 150u);
  EXPECT_EQ(matched.mapper.scan_match.memory_readings, 6000u);
  EXPECT_DOUBLE_EQ(matched.mapper.scan_match.correlated_echoes, 5.0);
  EXPECT_DOUBLE_EQ(matched.mapper.scan_match.sigma_m, 0.15);
  EXPECT_FALSE(matched.mapper.scan_match.rotation);
  EXPECT_FALSE(matched.mapper.scan_match.shift);
  EXPECT_TRUE(defaults.mapper.scan_match.shift);
  EXPECT_NE(error_of(p, {"mapper.scan_match_min_window_echoes=10"}).find("[30, 100000]"),
            std::string::npos);
  EXPECT_NE(error_of(p, {"mapper.scan_match_memory_readings=1.5"}).find("expected an integer"),
            std::string::npos);
  EXPECT_NE(error_of(p, {"mapper.scan_match_memory_readings=50000"}), "no error");
  EXPECT_NE(error_of(p, {"mapper.scan_match_sigma_m=0"}), "no error");
  // Position fixes at doorways passed again: on, 0.8 m, 0.016 m per metre unless set.
  EXPECT_TRUE(defaults.mapper.door_fix.enabled);
  EXPECT_DOUBLE_EQ(defaults.mapper.door_fix.match_radius_m, 0.8);
  EXPECT_DOUBLE_EQ(defaults.mapper.door_fix.drift_sd_per_m, 0.016);
  const Experiment doors =
      load_experiment(p, {"mapper.door_fix=false", "mapper.door_fix_radius_m=1.2",
                          "mapper.door_fix_drift_sd_per_m=0.05"});
  EXPECT_FALSE(doors.mapper.door_fix.enabled);
  EXPECT_DOUBLE_EQ(doors.mapper.door_fix.match_radius_m, 1.2);
  EXPECT_DOUBLE_EQ(doors.mapper.door_fix.drift_sd_per_m, 0.05);
  EXPECT_NE(error_of(p, {"mapper.door_fix_radius_m=0"}), "no error");
  EXPECT_NE(error_of(p, {"mapper.door_fix_drift_sd_per_m=-0.1"}), "no error");
  // The end-of-run relaxation: on, a first guess of 0.15 m walls unless set.
  EXPECT_TRUE(defaults.mapper.relaxation.enabled);
  EXPECT_DOUBLE_EQ(defaults.mapper.relaxation.wall_thickness_m, 0.15);
  const Experiment relaxed =
      load_experiment(p, {"mapper.relax=false", "mapper.relax_wall_thickness_m=0.3"});
  EXPECT_FALSE(relaxed.mapper.relaxation.enabled);
  EXPECT_DOUBLE_EQ(relaxed.mapper.relaxation.wall_thickness_m, 0.3);
  EXPECT_NE(error_of(p, {"mapper.relax_wall_thickness_m=-0.1"}), "no error");
  EXPECT_NE(error_of(p, {"mapper.relax=maybe"}), "no error");
  // Wall lines carried 20 m past a gap, weaker by 0.04 rad a metre; the keys in metres and
  // degrees, 0 allowed (no continuation; no weakening).
  EXPECT_DOUBLE_EQ(defaults.mapper.relaxation.continuation_gap_m, 20.0);
  EXPECT_DOUBLE_EQ(defaults.mapper.relaxation.continuation_angle_sd_rad, 0.04);
  const Experiment lines = load_experiment(
      p, {"mapper.relax_continuation_gap_m=1", "mapper.relax_continuation_angle_sd_deg=0"});
  EXPECT_DOUBLE_EQ(lines.mapper.relaxation.continuation_gap_m, 1.0);
  EXPECT_DOUBLE_EQ(lines.mapper.relaxation.continuation_angle_sd_rad, 0.0);
  EXPECT_NEAR(load_experiment(p, {"mapper.relax_continuation_angle_sd_deg=3"})
                  .mapper.relaxation.continuation_angle_sd_rad,
              3.0 * std::numbers::pi / 180.0, 1e-15);
  EXPECT_NE(error_of(p, {"mapper.relax_continuation_gap_m=-1"}), "no error");
  EXPECT_NE(error_of(p, {"mapper.relax_continuation_gap_m=201"}), "no error");
  EXPECT_NE(error_of(p, {"mapper.relax_continuation_angle_sd_deg=nan"}), "no error");
  EXPECT_NE(error_of(p, {"mapper.relax_continuation_angle_sd_deg=46"}), "no error");
  // The reference's bins, in degrees: none unless set (every direction on its own).
  EXPECT_EQ(defaults.mapper.localizer.reference_bin_rad, 0.0);
  EXPECT_NEAR(
      load_experiment(p, {"mapper.em_reference_bin_deg=0.5"}).mapper.localizer.reference_bin_rad,
      0.5 * std::numbers::pi / 180.0, 1e-15);
  EXPECT_EQ(
      load_experiment(p, {"mapper.em_reference_bin_deg=0"}).mapper.localizer.reference_bin_rad,
      0.0);
  EXPECT_NE(error_of(p, {"mapper.em_reference_bin_deg=-1"}), "no error");
  EXPECT_NE(error_of(p, {"mapper.em_reference_bin_deg=nan"}), "no error");
  EXPECT_NE(error_of(p, {"mapper.em_reference_bin_deg=1e-9"}).find("[0.01, 10]"),
            std::string::npos);
  EXPECT_NEAR(
      load_experiment(p, {"mapper.em_reference_bin_deg=0.01"}).mapper.localizer.reference_bin_rad,
      0.01 * std::numbers::pi / 180.0, 1e-18);
  // A room's measurement sd from its longest wall: EM's own sd (0) unless set, in degrees·m.
  EXPECT_EQ(defaults.mapper.localizer.measurement_sd_rad_m, 0.0);
  EXPECT_NEAR(load_experiment(p, {"mapper.em_measurement_sd_deg_m=4.4"})
                  .mapper.localizer.measurement_sd_rad_m,
              4.4 * std::numbers::pi / 180.0, 1e-15);
  EXPECT_NE(error_of(p, {"mapper.em_measurement_sd_deg_m=-1"}).find("em_measurement_sd_deg_m"),
            std::string::npos);
  EXPECT_NE(error_of(p, {"mapper.em_measurement_sd_deg_m=nan"}), "no error");
  // The skid-steer's curvature gain: the odometry as reported unless set; at most ±0.5.
  EXPECT_EQ(defaults.mapper.odometry_calibration.curvature_gain, 0.0);
  EXPECT_DOUBLE_EQ(load_experiment(p, {"mapper.odometry_curvature_gain=0.066"})
                       .mapper.odometry_calibration.curvature_gain,
                   0.066);
  EXPECT_NE(error_of(p, {"mapper.odometry_curvature_gain=0.6"}).find("[-0.5, 0.5]"),
            std::string::npos);
  EXPECT_NE(error_of(p, {"mapper.odometry_curvature_gain=nan"}), "no error");
  // Turns made while held: on unless switched off; a boolean.
  EXPECT_TRUE(defaults.mapper.held_turn.enabled);
  EXPECT_FALSE(load_experiment(p, {"mapper.held_turn=false"}).mapper.held_turn.enabled);
  EXPECT_NE(error_of(p, {"mapper.held_turn=3"}), "no error");
  // Long rooms: a route keeps the thesis's rule (0), an explorer cuts at 4.5 m, unless the
  // experiment says otherwise.
  EXPECT_EQ(defaults.mapper.max_room_travel_m, 0.0);
  EXPECT_EQ(load_experiment(p, {"mapper.max_room_travel_m=3"}).mapper.max_room_travel_m, 3.0);
  EXPECT_NE(error_of(p, {"mapper.max_room_travel_m=-1"}).find("max_room_travel_m"),
            std::string::npos);
  EXPECT_NE(error_of(p, {"mapper.max_room_travel_m=nan"}), "no error");
}

}  // namespace
}  // namespace cogmap::experiments
