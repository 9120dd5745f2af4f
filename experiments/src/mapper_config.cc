// The experiment file's `mapper:` block (docs/experiment-format.md): every key of the mapper's
// options, with its range; thesis defaults come from MapperOptions itself.
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>

#include "cogmap/experiments/experiment_config.h"
#include "config_numbers.h"

namespace cogmap::experiments {

using detail::number_above;
using detail::number_in;
using detail::whole_number_in;
using yaml::Node;

mapper::MapperOptions parse_mapper_options(const Node& block) {
  block.expect_keys({"grid",
                     "cell_scale_mm",
                     "occupied_threshold",
                     "vertex_tolerance_cells",
                     "polyline_gap_cells",
                     "douglas_peucker_cells",
                     "min_abs_correlation",
                     "window_m",
                     "asr_boundary",
                     "asr_distance_m",
                     "localization",
                     "door_close_side_m",
                     "min_room_travel_m",
                     "min_room_duration_s",
                     "max_room_extent_m",
                     "max_room_travel_m",
                     "max_correction_deg",
                     "no_echo_clear_m",
                     "hit_increment",
                     "neighbour_increment",
                     "miss_decrement",
                     "em_odometry_prior",
                     "em_prior_shrinks",
                     "em_reference_rooms",
                     "em_reference_bin_deg",
                     "em_drift_per_rad",
                     "em_smear_variance",
                     "em_label_sources",
                     "em_clutter_weight",
                     "em_weight_by_length",
                     "em_min_direction_sigma_deg",
                     "em_measurement_sd_deg_m",
                     "em_echo_refit_band_m",
                     "em_echo_refit_min_echoes",
                     "em_echo_refit_max_turn_deg",
                     "translation",
                     "translation_max_offset_m",
                     "translation_moves_estimate",
                     "glimpse",
                     "glimpse_distance_m",
                     "glimpse_turn_deg",
                     "glimpse_min_wall_m",
                     "glimpse_min_total_wall_m",
                     "scan_match",
                     "scan_match_interval_m",
                     "scan_match_interval_deg",
                     "scan_match_correlated_echoes",
                     "scan_match_memory_readings",
                     "scan_match_min_window_echoes",
                     "scan_match_sigma_m",
                     "scan_match_rotation",
                     "scan_match_shift",
                     "door_fix",
                     "door_fix_radius_m",
                     "door_fix_drift_sd_per_m",
                     "relax",
                     "relax_wall_thickness_m",
                     "relax_continuation_gap_m",
                     "relax_continuation_angle_sd_deg",
                     "odometry_curvature_gain",
                     "held_turn"});
  mapper::MapperOptions o;
  if (const auto g = block.child("grid")) {
    const std::string name = g->as<std::string>();
    // Parsed here rather than with mapper::parse_grid_kind so the names users type are checked
    // in the same place as every other key (and the message lists them).
    if (name == "himm") {
      o.grid = mapper::GridKind::kHimm;
    } else if (name == "mhimm") {
      o.grid = mapper::GridKind::kMhimm;
    } else if (name == "bayes") {
      o.grid = mapper::GridKind::kBayes;
    } else if (name == "dempster_shafer") {
      o.grid = mapper::GridKind::kDempsterShafer;
    } else {
      g->fail("unknown grid '" + name + "' (expected himm, mhimm, bayes or dempster_shafer)");
    }
  }
  o.grid_options.cell_scale_mm =
      number_in(block, "cell_scale_mm", 10.0, 1000.0, o.grid_options.cell_scale_mm);
  o.grid_options.window_m = number_above(block, "window_m", 0.0, o.grid_options.window_m);
  o.grid_options.no_echo_clear_m =
      number_in(block, "no_echo_clear_m", -1.0, 100.0, o.grid_options.no_echo_clear_m);
  o.grid_options.hit_increment =
      number_in(block, "hit_increment", 0.0, 15.0, o.grid_options.hit_increment);
  o.grid_options.neighbour_increment =
      number_in(block, "neighbour_increment", 0.0, 15.0, o.grid_options.neighbour_increment);
  o.grid_options.miss_decrement =
      number_in(block, "miss_decrement", 0.0, 15.0, o.grid_options.miss_decrement);
  // ε lives on the HIMM scale [-3, 15]; at or above the cap nothing would ever be occupied.
  o.builder.occupied_threshold = number_in(
      block, "occupied_threshold", 0.0, mapper::kHistogramMax - 1.0, o.builder.occupied_threshold);
  o.builder.vertex_tolerance_cells =
      number_in(block, "vertex_tolerance_cells", 0.0, 100.0, o.builder.vertex_tolerance_cells);
  o.builder.polyline_gap_cells =
      number_above(block, "polyline_gap_cells", 0.0, o.builder.polyline_gap_cells);
  o.builder.douglas_peucker_cells =
      number_in(block, "douglas_peucker_cells", 0.0, 100.0, o.builder.douglas_peucker_cells);
  o.builder.min_abs_correlation =
      number_in(block, "min_abs_correlation", 0.0, 1.0, o.builder.min_abs_correlation);
  if (const auto b = block.child("asr_boundary")) {
    const std::string s = b->as<std::string>();
    if (s == "doorway") {
      o.boundary = mapper::BoundaryKind::kDoorway;
    } else if (s == "distance") {
      o.boundary = mapper::BoundaryKind::kDistance;
    } else {
      b->fail("unknown asr_boundary '" + s + "' (expected doorway or distance)");
    }
  }
  o.distance.asr_distance_m = number_above(block, "asr_distance_m", 0.0, o.distance.asr_distance_m);
  o.doorway.close_side_m = number_above(block, "door_close_side_m", 0.0, o.doorway.close_side_m);
  o.doorway.min_room_travel_m =
      number_in(block, "min_room_travel_m", 0.0, 1000.0, o.doorway.min_room_travel_m);
  o.min_room_duration_s = number_in(block, "min_room_duration_s", 0.0, 1e6, o.min_room_duration_s);
  o.max_room_extent_m = number_in(block, "max_room_extent_m", 1.0, 2000.0, o.max_room_extent_m);
  {
    // Each bound alone leaves the product unbounded: 10 mm cells at the default 200 m, or
    // 2000 m at 100 mm, is a grid of ~4e8 cells (docs/reliability.md "Limits").
    const double limit = ExperimentLimits{}.max_room_grid_side_cells;
    const double cell_m = o.grid_options.cell_scale_mm / 1000.0;
    const double side = (o.max_room_extent_m + 10.0) / cell_m;
    if (side > limit) {
      const auto extent = block.child("max_room_extent_m");
      const auto cell = block.child("cell_scale_mm");
      // Blame the key that left its safe default: a wider room than 200 m, else finer cells.
      const bool wide = extent && o.max_room_extent_m > mapper::MapperOptions{}.max_room_extent_m;
      const std::optional<Node> at = wide ? extent : (cell ? cell : extent);
      std::ostringstream msg;
      msg << o.grid_options.cell_scale_mm << " mm cells with max_room_extent_m "
          << o.max_room_extent_m << " m allow a room grid of " << std::ceil(side)
          << " cells a side (the room plus 5 m of sonar range each way), more than the " << limit
          << "-cell limit (docs/reliability.md); use cell_scale_mm of at least "
          << std::ceil((o.max_room_extent_m + 10.0) / limit * 1000.0)
          << " or max_room_extent_m of at most " << std::floor(limit * cell_m - 10.0);
      if (at) {
        at->fail(msg.str());
      } else {
        block.fail(msg.str());
      }
    }
  }
  o.max_room_travel_m = number_in(block, "max_room_travel_m", 0.0, 1e6, o.max_room_travel_m);
  o.localizer.odometry_prior = block.get_or<bool>("em_odometry_prior", o.localizer.odometry_prior);
  o.localizer.prior_shrinks = block.get_or<bool>("em_prior_shrinks", o.localizer.prior_shrinks);
  o.localizer.reference_rooms = static_cast<std::size_t>(whole_number_in(
      block, "em_reference_rooms", 1, 1000, static_cast<int>(o.localizer.reference_rooms)));
  if (const auto b = block.child("em_reference_bin_deg")) {  // 0: every direction on its own
    const double deg = number_in(block, "em_reference_bin_deg", 0.0, 10.0, 0.0);
    // Narrower bins than 0.01° (9 000 to the quarter circle) pool nothing a 10 cm grid's walls
    // could tell apart, and a vanishing width would ask for billions of bins.
    if (deg > 0.0 && deg < 0.01) b->fail("em_reference_bin_deg must be 0 or in [0.01, 10]");
    o.localizer.reference_bin_rad = deg * std::numbers::pi / 180.0;
  }
  o.localizer.drift.per_rad_turned =
      number_in(block, "em_drift_per_rad", 0.0, 1.0, o.localizer.drift.per_rad_turned);
  o.localizer.smear_variance = block.get_or<bool>("em_smear_variance", o.localizer.smear_variance);
  // The three departures of our EM from Fig. A.6's mixture, each selectable so that the thesis's
  // own EM can be run (docs/algorithms.md, "The thesis's EM, exactly").
  o.localizer.label_sources = block.get_or<bool>("em_label_sources", o.localizer.label_sources);
  o.localizer.clutter_weight =
      number_in(block, "em_clutter_weight", 0.0, 0.9, o.localizer.clutter_weight);
  o.localizer.weight_by_length =
      block.get_or<bool>("em_weight_by_length", o.localizer.weight_by_length);
  o.localizer.min_direction_sigma_rad =
      number_in(block, "em_min_direction_sigma_deg", 0.0, 45.0,
                o.localizer.min_direction_sigma_rad * 180.0 / std::numbers::pi) *
      std::numbers::pi / 180.0;
  // A room's measurement is as sharp as its longest wall (docs/algorithms.md, "A room's
  // measurement is as sharp as its longest wall"); 0 = the sd EM's mixture claims.
  o.localizer.measurement_sd_rad_m =
      number_in(block, "em_measurement_sd_deg_m", 0.0, 100.0,
                o.localizer.measurement_sd_rad_m * 180.0 / std::numbers::pi) *
      std::numbers::pi / 180.0;
  o.localizer.echo_refit.band_m =
      number_in(block, "em_echo_refit_band_m", 0.0, 1.0, o.localizer.echo_refit.band_m);
  o.localizer.echo_refit.min_echoes = whole_number_in(block, "em_echo_refit_min_echoes", 2, 100000,
                                                      o.localizer.echo_refit.min_echoes);
  o.localizer.echo_refit.max_turn_rad =
      number_in(block, "em_echo_refit_max_turn_deg", 0.0, 45.0,
                o.localizer.echo_refit.max_turn_rad * 180.0 / std::numbers::pi) *
      std::numbers::pi / 180.0;
  o.translation.enabled = block.get_or<bool>("translation", o.translation.enabled);
  o.translation.moves_estimate =
      block.get_or<bool>("translation_moves_estimate", o.translation.moves_estimate);
  o.translation.max_offset_m =
      number_in(block, "translation_max_offset_m", 0.05, 10.0, o.translation.max_offset_m);
  o.glimpse.enabled = block.get_or<bool>("glimpse", o.glimpse.enabled);
  o.glimpse.distance_m = number_in(block, "glimpse_distance_m", 0.5, 100.0, o.glimpse.distance_m);
  o.glimpse.turn_rad = number_in(block, "glimpse_turn_deg", 10.0, 1e6,
                                 o.glimpse.turn_rad * 180.0 / std::numbers::pi) *
                       std::numbers::pi / 180.0;
  o.glimpse.min_wall_length_m =
      number_in(block, "glimpse_min_wall_m", 0.0, 100.0, o.glimpse.min_wall_length_m);
  o.glimpse.min_total_wall_m =
      number_in(block, "glimpse_min_total_wall_m", 0.0, 1000.0, o.glimpse.min_total_wall_m);
  o.scan_match.enabled = block.get_or<bool>("scan_match", o.scan_match.enabled);
  o.scan_match.rotation = block.get_or<bool>("scan_match_rotation", o.scan_match.rotation);
  o.scan_match.shift = block.get_or<bool>("scan_match_shift", o.scan_match.shift);
  o.scan_match.interval_m =
      number_in(block, "scan_match_interval_m", 0.1, 100.0, o.scan_match.interval_m);
  o.scan_match.interval_rad = number_in(block, "scan_match_interval_deg", 1.0, 1e6,
                                        o.scan_match.interval_rad * 180.0 / std::numbers::pi) *
                              std::numbers::pi / 180.0;
  o.scan_match.correlated_echoes =
      number_in(block, "scan_match_correlated_echoes", 1.0, 1000.0, o.scan_match.correlated_echoes);
  o.scan_match.sigma_m = number_in(block, "scan_match_sigma_m", 0.02, 1.0, o.scan_match.sigma_m);
  // Whole numbers ("expected an integer" otherwise): a window below the 30 matched echoes a
  // match needs could never measure, and every match redraws the whole memory (20 000 readings
  // are seven minutes of the ring).
  o.scan_match.min_window_echoes =
      static_cast<std::size_t>(whole_number_in(block, "scan_match_min_window_echoes", 30, 100000,
                                               static_cast<int>(o.scan_match.min_window_echoes)));
  o.scan_match.memory_readings =
      static_cast<std::size_t>(whole_number_in(block, "scan_match_memory_readings", 100, 20000,
                                               static_cast<int>(o.scan_match.memory_readings)));
  o.door_fix.enabled = block.get_or<bool>("door_fix", o.door_fix.enabled);
  o.door_fix.match_radius_m =
      number_in(block, "door_fix_radius_m", 0.05, 10.0, o.door_fix.match_radius_m);
  o.door_fix.drift_sd_per_m =
      number_in(block, "door_fix_drift_sd_per_m", 0.0, 100.0, o.door_fix.drift_sd_per_m);
  o.relaxation.enabled = block.get_or<bool>("relax", o.relaxation.enabled);
  o.relaxation.wall_thickness_m =
      number_in(block, "relax_wall_thickness_m", 0.0, 2.0, o.relaxation.wall_thickness_m);
  // A wall line carried past a gap (0: never; 1 m, a door, was the default before 2026-12-08),
  // and how well two pieces' directions agree (docs/algorithms.md, "Relaxing the rooms'
  // positions"). Up to 200 m, the most a room grid spans (MapperOptions::max_room_extent_m).
  o.relaxation.continuation_gap_m =
      number_in(block, "relax_continuation_gap_m", 0.0, 200.0, o.relaxation.continuation_gap_m);
  if (block.child("relax_continuation_angle_sd_deg")) {
    o.relaxation.continuation_angle_sd_rad =
        number_in(block, "relax_continuation_angle_sd_deg", 0.0, 45.0, 0.0) * std::numbers::pi /
        180.0;
  }
  // A skid-steer's arcs (docs/algorithms.md, "Odometry recalibrated for arcs"): a track that
  // changes by half either way is no skid-steer any more.
  o.odometry_calibration.curvature_gain =
      number_in(block, "odometry_curvature_gain", -0.5, 0.5, o.odometry_calibration.curvature_gain);
  // A turn on the spot the sonar ring did not see (docs/algorithms.md, "Turns made while held").
  o.held_turn.enabled = block.get_or<bool>("held_turn", o.held_turn.enabled);
  if (const auto l = block.child("localization")) {
    const std::string s = l->as<std::string>();
    if (s == "em") {
      o.localization = mapper::LocalizationKind::kEm;
    } else if (s == "none") {
      o.localization = mapper::LocalizationKind::kNone;
    } else {
      l->fail("unknown localization '" + s + "' (expected em or none)");
    }
  }
  const double max_corr_deg = number_in(block, "max_correction_deg", 0.0, 180.0,
                                        o.localizer.max_correction_rad * 180.0 / std::numbers::pi);
  o.localizer.max_correction_rad = max_corr_deg * std::numbers::pi / 180.0;
  return o;
}

}  // namespace cogmap::experiments
