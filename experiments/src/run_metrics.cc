#include "cogmap/experiments/run_metrics.h"

#include <cmath>
#include <numbers>

#include <nlohmann/json.hpp>

namespace cogmap::experiments {
namespace {

using Json = nlohmann::ordered_json;

Json opt(const std::optional<double>& v) { return v ? Json(*v) : Json(nullptr); }

void put_accuracy(Json& block, const MapAccuracy& a) {
  block["wall_error_median_m"] = opt(a.wall_error_median_m);
  block["wall_error_p90_m"] = opt(a.wall_error_p90_m);
  block["wall_coverage"] = opt(a.wall_coverage);
  block["spurious_fraction"] = opt(a.spurious_fraction);
}

void put_accuracy_extras(Json& block, const MapAccuracy& a) {
  block["segment_count"] = a.segment_count;
  block["map_length_m"] = a.map_length_m;
  block["error_samples"] = a.error_samples;
  block["visible_truth_samples"] = a.visible_truth_samples;
}

template <typename T>
Json opt_any(const std::optional<T>& v) {
  return v ? Json(*v) : Json(nullptr);
}

Json nav_json(const NavMetrics& n) {
  Json nav = Json::object();
  nav["route_completed"] = opt_any(n.route_completed);
  nav["waypoints_total"] = n.waypoints_total;
  nav["waypoints_skipped"] = n.waypoints_skipped;
  nav["recoveries"] = n.recoveries;
  nav["door_passages"] = n.door_passages;
  nav["contacts"] = opt_any(n.contacts);
  nav["contact_s"] = opt(n.contact_s);
  nav["contact_start_s"] = n.contacts ? Json(n.contact_start_s) : Json(nullptr);
  Json onsets = Json::array();
  for (const ContactOnset& c : n.contact_onsets) {
    onsets.push_back({{"t_s", c.t_s}, {"mode", c.mode}, {"body_m", {c.body_m.x(), c.body_m.y()}}});
  }
  nav["contact_onsets"] = n.contacts ? std::move(onsets) : Json(nullptr);
  nav["distance_m"] = n.distance_m;
  nav["stalled_s"] = n.stalled_s;
  nav["rooms_visited"] = opt_any(n.rooms_visited);
  nav["rooms_total_true"] = opt_any(n.rooms_total_true);
  nav["rooms_visited_true"] = opt_any(n.rooms_visited_true);
  nav["exploration_complete"] = opt_any(n.exploration_complete);
  nav["turn_deg"] = n.turn_deg;
  Json turn = Json::object(), time = Json::object();
  for (const auto& [mode, deg] : n.turn_deg_by_mode) turn[mode] = deg;
  for (const auto& [mode, s] : n.time_s_by_mode) time[mode] = s;
  nav["turn_deg_by_mode"] = std::move(turn);
  nav["time_s_by_mode"] = std::move(time);
  Json drift = Json::object();
  for (const auto& [mode, deg] : n.heading_drift_deg_by_mode) drift[mode] = deg;
  nav["heading_drift_deg_by_mode"] = std::move(drift);
  return nav;
}

Json similarity_json(const SimilarityFit& f) {
  return {
      {"scale", f.scale}, {"rotation_deg", f.rotation_deg}, {"residual_rmse_m", f.residual_rmse_m}};
}

Json stage_json(const StageError& e) {
  return {{"median_m", opt(e.median_m)}, {"p90_m", opt(e.p90_m)}, {"count", e.count}};
}

Json aligned_map_json(const AlignedMap& a) {
  Json j = stage_json(a.error);
  j["rotation_deg"] = opt(a.rotation_deg);
  j["start_shift_m"] =
      a.start_shift_m ? Json::array({a.start_shift_m->x(), a.start_shift_m->y()}) : Json(nullptr);
  return j;
}

Json aligned_rooms_json(const AlignedRooms& a) {
  Json j = stage_json(a.error);
  j["rooms_fitted"] = a.rooms_fitted;
  return j;
}

Json breakdown_json(const ErrorBreakdown& b) {
  const HeadingBreakdown& h = b.heading;
  return {{"grid", stage_json(b.grid)},
          {"cleaned", stage_json(b.cleaned)},
          {"points", stage_json(b.points)},
          {"lines", stage_json(b.lines)},
          {"aligned_map", aligned_map_json(b.aligned_map)},
          {"aligned_rooms", aligned_rooms_json(b.aligned_rooms)},
          {"heading",
           {{"rooms", h.rooms},
            {"entry_error_deg_mean_abs", opt(h.entry_error_deg_mean_abs)},
            {"exit_error_deg_mean_abs", opt(h.exit_error_deg_mean_abs)},
            {"exit_error_deg_max_abs", opt(h.exit_error_deg_max_abs)},
            {"within_room_drift_deg_mean_abs", opt(h.within_room_drift_deg_mean_abs)},
            {"within_room_drift_deg_max_abs", opt(h.within_room_drift_deg_max_abs)}}}};
}

}  // namespace

RoomLocalizationReport room_localization_report(const mapper::Localization& l) {
  constexpr double kDegPerRad = 180.0 / std::numbers::pi;
  RoomLocalizationReport r;
  r.measured_rotation_deg = l.measured_rotation_rad * kDegPerRad;
  r.measurement_sd_deg = l.measurement_sigma_rad * kDegPerRad;
  r.longest_wall_m = l.longest_wall_m;
  if (std::isfinite(l.prior_sigma_rad)) r.prior_sd_deg = l.prior_sigma_rad * kDegPerRad;
  r.gain = l.gain;
  r.applied = l.applied;
  if (l.translation_tried) {
    r.translation_m = std::array<double, 2>{l.translation_m.x(), l.translation_m.y()};
    r.translation_applied = l.translation_applied;
    r.translation_pairs = l.translation_pairs;
  }
  return r;
}

std::string metrics_json_text(const RunMetrics& m) {
  Json j;
  j["experiment"] = {{"name", m.name},
                     {"world", m.world},
                     {"seed", m.seed},
                     {"source", m.source},
                     {"controller", m.controller},
                     {"steering", m.steering},
                     {"grid", m.grid},
                     {"asr_boundary", m.boundary},
                     {"localization", m.localization_kind},
                     {"odometry_curvature_gain", m.odometry_curvature_gain},
                     {"odometry_track_m", m.odometry_track_m},
                     {"max_room_travel_m", m.max_room_travel_m}};
  j["asr_count"] = m.asr_count;
  j["frames"] = m.frames;
  if (m.route_completed) j["route_completed"] = *m.route_completed;

  j["nav"] = nav_json(m.nav);

  Json map = Json::object();
  if (m.map) put_accuracy(map, *m.map);
  map["polyline_bytes"] = m.memory.polyline_bytes;
  map["grid_bytes"] = m.memory.grid_bytes;
  map["compression_ratio"] = opt(m.memory.compression_ratio);
  map["grid_bytes_total"] = m.memory.grid_bytes_total;
  map["extracted_vertex_bytes"] = m.memory.extracted_vertex_bytes;
  map["vertex_count"] = m.memory.vertex_count;
  map["extracted_vertex_count"] = m.memory.extracted_vertex_count;
  if (m.map) put_accuracy_extras(map, *m.map);
  j["map"] = map;

  if (m.map_odometry) {
    Json before = Json::object();
    put_accuracy(before, *m.map_odometry);
    put_accuracy_extras(before, *m.map_odometry);
    j["map_odometry"] = before;
  }
  if (m.localization) {
    const LocalizationAccuracy& l = *m.localization;
    j["localization"] = {
        {"heading_error_final_deg",
         {{"odometry", l.heading_error_final_odometry_deg},
          {"corrected", l.heading_error_final_corrected_deg},
          {"closed", l.heading_error_final_closed_deg ? Json(*l.heading_error_final_closed_deg)
                                                      : Json(nullptr)}}},
        {"ate_rmse_m",
         {{"odometry", l.ate_rmse_odometry_m}, {"corrected", l.ate_rmse_corrected_m}}},
        {"similarity",
         {{"odometry", similarity_json(l.similarity_odometry)},
          {"corrected", similarity_json(l.similarity_corrected)}}},
        {"frames", l.frames}};
  }
  if (m.error_breakdown) j["error_breakdown"] = breakdown_json(*m.error_breakdown);
  j["readings"] = {{"used", m.readings_used},
                   {"rejected",
                    {{"not_finite", m.rejected.not_finite},
                     {"non_positive", m.rejected.non_positive},
                     {"beyond_max", m.rejected.beyond_max},
                     {"unknown_sonar", m.rejected.unknown_sonar},
                     {"total", m.rejected.total()}}}};
  j["door_fixes"] = {{"count", m.door_fixes}, {"total_m", m.door_fix_total_m}};
  j["held_turns"] = {{"count", m.held_turns}, {"removed_deg", m.held_turn_removed_deg}};
  if (m.relaxation) {
    j["relaxation"] = {{"rooms_moved", m.relaxation->rooms_moved},
                       {"total_m", m.relaxation->total_m},
                       {"max_m", m.relaxation->max_m},
                       {"wall_thickness_m", m.relaxation->wall_thickness_m},
                       {"pairs", m.relaxation->pairs}};
  }
  if (m.scan_match) {
    j["scan_match"] = {{"matches", m.scan_match->matches},
                       {"measured", m.scan_match->measured},
                       {"rotation_total_deg", m.scan_match->rotation_total_deg},
                       {"shift_total_m", m.scan_match->shift_total_m}};
  }
  Json rooms = Json::array();
  for (const RoomReport& r : m.rooms) {
    Json localization(nullptr);
    if (r.localization) {
      const RoomLocalizationReport& l = *r.localization;
      localization = {{"measured_rotation_deg", l.measured_rotation_deg},
                      {"measurement_sd_deg", l.measurement_sd_deg},
                      {"longest_wall_m", l.longest_wall_m},
                      {"prior_sd_deg", opt(l.prior_sd_deg)},
                      {"gain", l.gain},
                      {"applied", l.applied}};
      if (l.translation_m) {
        localization["translation_m"] = {(*l.translation_m)[0], (*l.translation_m)[1]};
        localization["translation_applied"] = l.translation_applied;
        localization["translation_pairs"] = l.translation_pairs;
      }
    }
    rooms.push_back({{"id", r.size.id},
                     {"parent", r.parent ? Json(*r.parent) : Json(nullptr)},
                     {"walls", r.size.wall_count},
                     {"vertex_count", r.size.vertex_count},
                     {"extracted_vertex_count", r.size.extracted_vertex_count},
                     {"polyline_bytes", r.size.polyline_bytes},
                     {"grid_bytes", r.size.grid_bytes},
                     {"heading_correction_deg", r.heading_correction_deg},
                     {"localization", localization},
                     {"start_time_s", r.start_time_s},
                     {"end_time_s", r.end_time_s}});
  }
  j["rooms"] = rooms;
  j["timing"] = {{"sim_time_s", m.sim_time_s},
                 {"wall_time_s", m.wall_time_s},
                 {"real_time_factor",
                  m.wall_time_s > 0.0 ? Json(m.sim_time_s / m.wall_time_s) : Json(nullptr)},
                 {"build_time_s", m.build_time_s},
                 {"localization_time_s", m.localization_time_s}};
  Json room_ms = Json::array();
  for (const double s : m.room_cpu_s) room_ms.push_back(s * 1000.0);
  j["timing"]["room_cpu_ms"] = room_ms;
  Json room_wall_ms = Json::array();
  for (const double s : m.room_wall_s) room_wall_ms.push_back(s * 1000.0);
  j["timing"]["room_wall_ms"] = room_wall_ms;
  // Names are checked for UTF-8 when the experiment is parsed; should a string still carry a
  // stray byte, it becomes U+FFFD rather than a type_error that loses a finished run's metrics.
  return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

std::optional<RunMetrics::Relaxation> relaxation_metrics(const mapper::MapperOptions& options,
                                                         const mapper::MapperStats& stats) {
  if (!options.relaxation.enabled || options.localization != mapper::LocalizationKind::kEm) {
    return std::nullopt;
  }
  return RunMetrics::Relaxation{stats.relaxed_rooms, stats.relaxation_abs_m, stats.relaxation_max_m,
                                stats.relaxation_wall_thickness_m, stats.relaxation_pairs};
}

std::optional<RunMetrics::ScanMatch> scan_match_metrics(const mapper::MapperOptions& options,
                                                        const mapper::MapperStats& stats) {
  if (!options.scan_match.enabled) return std::nullopt;
  return RunMetrics::ScanMatch{stats.scan_matches, stats.scan_matches_measured,
                               stats.scan_match_rotation_abs_rad * 180.0 / std::numbers::pi,
                               stats.scan_match_shift_abs_m};
}

}  // namespace cogmap::experiments
