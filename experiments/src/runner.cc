#include "cogmap/experiments/runner.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <future>
#include <numbers>
#include <system_error>

#include "cogmap/experiments/controller_factory.h"
#include "cogmap/experiments/error_breakdown.h"
#include "cogmap/experiments/nav_metrics.h"
#include "cogmap/experiments/plain_mapper_options.h"
#include "cogmap/experiments/ros_map.h"
#include "cogmap/experiments/run_directory.h"
#include "cogmap/experiments/run_outputs.h"
#include "cogmap/experiments/true_rooms.h"
#include "cogmap/experiments/visible_truth_tracker.h"
#include "cogmap/mapper/graph/asr_store.h"
#include "cogmap/mapper/io/asr_json.h"
#include "cogmap/mapper/io/directory_asr_store.h"
#include "cogmap/mapper/mapper.h"
#include "cogmap/mapper/nav/controller.h"
#include "cogmap/render/figures.h"
#include "cogmap/render/renderer.h"

namespace cogmap::experiments {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
constexpr double kRunnerDegPerRad = 180.0 / std::numbers::pi;

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

std::string room_stem(int id) {
  char buf[16];
  std::snprintf(buf, sizeof(buf), "%03d", id);
  return buf;
}

std::string grid_name(mapper::GridKind kind) {
  switch (kind) {
    case mapper::GridKind::kHimm:
      return "himm";
    case mapper::GridKind::kMhimm:
      return "mhimm";
    case mapper::GridKind::kBayes:
      return "bayes";
    case mapper::GridKind::kDempsterShafer:
      return "dempster_shafer";
  }
  return "?";
}

/// What the controller sees this cycle: `frame` (the true pose already removed), the mapper's
/// estimate and grid, or (controller.pose: truth, a diagnostic) the true pose and no grid,
/// since the grid lives in the estimate frame.
mapper::nav::NavInput nav_input(const ControllerConfig& c, const mapper::SensorFrame& frame,
                                const std::optional<mapper::Pose2>& true_pose,
                                const mapper::Mapper& mapper, const mapper::RobotGeometry& robot) {
  if (c.steer_by_truth && true_pose) return {&frame, *true_pose, nullptr, &robot};
  return {&frame, mapper.pose_estimate(), &mapper.grid(), &robot};
}

/// The frame as the robot's own software sees it: everything but the true pose, which only
/// the metrics (and the diagnostic truth controller) may read.
mapper::SensorFrame without_truth(const mapper::SensorFrame& frame) {
  mapper::SensorFrame seen = frame;
  seen.true_pose.reset();
  return seen;
}

/// The frame loop and its products, kept apart from the writing of files.
struct SessionResult {
  TrajectoryLog rows;                 // full chunks on disk: memory does not grow with the run
  std::vector<NavTraceRow> nav_rows;  // output.nav_trace only
  // Which mode's command led into the rows' frames: one entry a change (a mode flapping every
  // frame makes one a frame, 16 bytes against the row's 90 on disk).
  std::vector<ModeChange> mode_changes;
  std::optional<bool> route_completed;
  std::optional<double> closed_heading_rad;  // the estimate once the last room is closed
  double sim_time_s = 0.0;
  double wall_time_s = 0.0;
};

/// The nav block from the controller's own account and what the robot itself measured.
NavMetrics nav_metrics(const mapper::nav::Controller& controller, const ControllerConfig& c,
                       const SessionResult& session, double stalled_s) {
  NavMetrics nav;
  const mapper::nav::NavTrace& t = controller.trace();
  nav.route_completed = session.route_completed;
  if (c.type == ControllerKind::kRoute) nav.waypoints_total = c.waypoints.size();
  nav.waypoints_skipped = t.skipped_waypoints;
  nav.recoveries = t.recoveries;
  nav.door_passages = t.door_passages;
  nav.distance_m = odometry_distance_m(session.rows.view());
  nav.stalled_s = stalled_s;
  if (c.type == ControllerKind::kExplore) {
    if (t.rooms_visited > 0) nav.rooms_visited = t.rooms_visited;  // when the explorer counts
    nav.exploration_complete = t.exploration_complete;
  }
  return nav;
}

/// figures/map_error.png: the corrected map coloured by its samples' distance to the truth.
void draw_map_error(const std::string& title, const std::vector<mapper::Segment>& map,
                    const GroundTruth& truth, const ErrorBreakdownBuilder& breakdown,
                    const RunMetrics& m, const fs::path& out) {
  render::MapErrorFigure fig;
  fig.title = "map error (distance to the true walls)";
  if (m.map && m.map->wall_error_median_m && m.map->wall_error_p90_m) {
    char buf[96];
    std::snprintf(buf, sizeof(buf), "map error: median %.3f m, p90 %.3f m",
                  *m.map->wall_error_median_m, *m.map->wall_error_p90_m);
    fig.title = buf;
  }
  fig.caption = title + ", after localisation";
  fig.true_surfaces = truth.surfaces;
  // The same sampling as the map metrics, so the colours are the numbers in the title.
  for (const ErrorPiece& p :
       error_pieces(map, breakdown.truth_index(), MapMetricsOptions{}.sample_step_m)) {
    fig.pieces.push_back(p.piece);
    fig.error_m.push_back(p.error_m);
  }
  render::write_map_error_figure(fig, out / "figures" / "map_error.png");
}

}  // namespace

RunSummary run_robot_session(mapper::Robot& robot, const Experiment& experiment,
                             const GroundTruth* truth, const RunOptions& options) {
  const fs::path out = options.out_dir;
  const bool want_figures = options.figures.value_or(experiment.figures);
  const bool figures = want_figures;
  // The renderer is a plugin: a run that cannot draw its figures stops before it writes anything.
  if (figures) render::require_renderer();
  // Held to the end of the session: no second writer (thread or process) enters `out`.
  std::optional<RunDirectoryLock> lock;
  try {
    // Before the lock file is created in it. Whether a finished run may be replaced is the
    // command's decision (`--force`), taken before it called here.
    check_run_directory(out, {experiment.file}, FinishedRun::kReplace);
    lock.emplace(out);
    prepare_run_directory(out, experiment, options.durability);
  } catch (const RunDirectoryError&) {
    throw;
  } catch (const std::exception& e) {
    throw RunError(std::string("cannot prepare the run directory: ") + e.what());
  }
  if (want_figures && !figures) {
    std::fprintf(stderr, "cogmap: built without the render module; figures are skipped\n");
  }

  const mapper::RobotGeometry geometry = robot.geometry();
  const mapper::Pose2 start = truth ? truth->start_pose : options.start_pose;
  const mapper::io::Durability durability = options.durability;
  mapper::io::DirectoryAsrStore store(out / "asrs", durability);
  mapper::Mapper mapper(experiment.mapper, geometry, store, start);
  // `controller.pose: plain_estimate`: the controller's own mapper, fed the same frames, keeps
  // its finished rooms in RAM (walls and path only, a few kB a room) and writes nothing. With
  // no map-only refinement on it would repeat the map's mapper exactly: then that one steers.
  mapper::MemoryAsrStore steering_store;
  std::optional<mapper::Mapper> steering_mapper;
  if (experiment.controller.steer_by_plain_estimate &&
      has_map_only_refinements(experiment.mapper)) {
    steering_mapper.emplace(plain_mapper_options(experiment.mapper), geometry, steering_store,
                            start);
  }
  const mapper::Mapper& steering = steering_mapper ? *steering_mapper : mapper;
  const double occupied_threshold = experiment.mapper.builder.occupied_threshold;
  Clock::duration figure_time{0};  // figures: not the frame loop's time
  // The room's grid file (grid_NNN.pgm/.yaml) and the per-stage error need the room's grids,
  // which live only for the listener call: a copy of them goes to a second thread (~1 ms of
  // nearest-wall queries and the two files a room, done while the robot drives on), one room at
  // a time and in order, so the sums are the same. The room itself (asrs/) is saved by the
  // mapper before the listener is called, durable as it finishes whatever happens here.
  std::optional<ErrorBreakdownBuilder> breakdown;
  if (truth) breakdown.emplace(truth->surfaces, occupied_threshold);
  std::future<void> room_task;       // after `breakdown`: destroyed (so joined) before it
  bool closing_run = false;          // mapper.finish() closes the last room after the last row
  std::vector<double> room_cpu_s;    // per finished room: its pipeline and EM time
  double mapping_cpu_s = 0.0;        // the two, summed over the rooms before
  std::vector<double> room_wall_s;   // per finished room: the loop's wall time since the last
  Clock::time_point room_wall_mark;  // the last room's end (the loop's start), figures excluded
  // The master maps (Fig. 4.4), corrected and odometry only, and the room reports, gathered as
  // each room is stored (the listener gets the very room the store just saved; reading them all
  // back at the end cost 0.65 M instructions a room): the walls stay, the grids go.
  std::vector<mapper::Mapper::MapSegment> corrected, odometry;
  std::vector<RoomReport> room_reports;
  std::vector<std::pair<int, mapper::Point2>> labels;
  mapper.set_room_listener([&](const mapper::Asr& asr, const mapper::AsrTrace& trace,
                               const std::optional<mapper::Localization>& localized) {
    mapper::Mapper::append_room_segments(asr, true, corrected);
    mapper::Mapper::append_room_segments(asr, false, odometry);
    RoomReport report;
    report.size = {asr.id,
                   asr.walls.size(),
                   asr.vertex_count(),
                   asr.extracted_vertex_count,
                   asr.polyline_bytes(),
                   asr.grid_bytes};
    report.parent = asr.parent;
    report.heading_correction_deg = asr.heading_correction_rad * kRunnerDegPerRad;
    if (localized) report.localization = room_localization_report(*localized);
    report.start_time_s = asr.start_time_s;
    report.end_time_s = asr.end_time_s;
    room_reports.push_back(report);
    labels.emplace_back(asr.id, asr.pose.transform(asr.reference_point));
    const double mapping_now_s = mapper.stats().build_time_s + mapper.stats().localization_time_s;
    room_cpu_s.push_back(mapping_now_s - mapping_cpu_s);
    mapping_cpu_s = mapping_now_s;
    const Clock::time_point wall_now = Clock::now() - figure_time;
    room_wall_s.push_back(seconds(wall_now - room_wall_mark));
    room_wall_mark = wall_now;
    const std::string stem = room_stem(asr.id);
    mapper::AsrTrace stages;  // what the grid file and add_room read
    stages.raw = trace.raw;
    if (breakdown) {
      stages.cleaned = trace.cleaned;
      stages.extracted = trace.extracted;
      stages.fitted = trace.fitted;
    }
    const RoomSpan span{asr.start_time_s, asr.end_time_s, asr.pose.theta_rad, !closing_run};
    if (room_task.valid()) room_task.get();  // the previous room's (rethrows its failure)
    room_task = std::async(std::launch::async, [&, id = asr.id, pose = asr.pose,
                                                stages = std::move(stages), span, stem] {
      write_ros_map(stages.raw, occupied_threshold, out, "grid_" + stem, durability);
      if (breakdown) {
        breakdown->add_room(id, pose, stages);
        breakdown->add_room_span(span);
      }
    });
    if (figures) {
      const auto t0 = Clock::now();
      render::write_room_stages_figure(trace, experiment.name + ": room " + std::to_string(asr.id),
                                       out / "figures" / ("room_" + stem + "_stages.png"));
      figure_time += Clock::now() - t0;
    }
  });

  auto controller = make_controller(experiment.controller);
  if (experiment.controller.steer_by_truth && !truth) {
    throw RunError("controller.pose: truth needs ground truth (a simulated robot)");
  }
  SessionResult session;
  double stalled_s = 0.0;  // time with a stall flag set (nav block)
  NavMetrics turning;      // odometry turning by commanding mode (nav block)
  // The mode whose command led into the frame being processed (the last step's).
  mapper::nav::NavMode mode = mapper::nav::NavMode::kIdle;
  std::optional<mapper::Pose2> last_odometry;
  std::optional<double> last_true_theta_rad;  // the drift-by-mode metric's truth
  // Which true surfaces the robot could have sensed (the coverage's denominator) depends only
  // on the truth and the true path, and is the largest piece of the metrics (7 % of a nine-room
  // run's instructions): a worker works it out on the second core while the run goes.
  MapMetricsOptions metric_options;
  metric_options.sonar_max_range_m = geometry.sonar_max_range_m;
  std::optional<VisibleTruthTracker> visible_truth;
  if (truth) visible_truth.emplace(truth->surfaces, metric_options);
  const auto wall_start = Clock::now();
  room_wall_mark = wall_start;
  try {
    double next_progress_s = 0.0;
    double last_time_s = 0.0;
    while (true) {
      const std::optional<mapper::SensorFrame> frame = robot.next_frame();
      if (!frame) break;
      const mapper::SensorFrame seen = without_truth(*frame);
      mapper.process(seen);
      if (steering_mapper) steering_mapper->process(seen);
      stalled_s += (seen.stall_left || seen.stall_right) ? seen.time_s - last_time_s : 0.0;
      const mapper::Pose2 odometry = mapper.odometry_pose();
      if (last_odometry) {
        const std::string mode_name = mapper::nav::to_string(mode);
        add_mode_interval(turning, mode_name, odometry.theta_rad - last_odometry->theta_rad,
                          seen.time_s - last_time_s);
        if (frame->true_pose && last_true_theta_rad) {  // a metric: truth only measures here
          add_mode_drift(turning, mode_name, odometry.theta_rad - last_odometry->theta_rad,
                         frame->true_pose->theta_rad - *last_true_theta_rad);
        }
      }
      last_odometry = odometry;
      if (frame->true_pose) last_true_theta_rad = frame->true_pose->theta_rad;
      last_time_s = seen.time_s;
      session.rows.push_back({frame->time_s, frame->true_pose, odometry, mapper.pose_estimate()});
      if (session.mode_changes.empty() || session.mode_changes.back().mode != mode) {
        session.mode_changes.push_back({session.rows.size() - 1, mode});
      }
      if (visible_truth && frame->true_pose) visible_truth->add(frame->true_pose->translation());
      session.sim_time_s = frame->time_s;
      if (options.on_progress && frame->time_s >= next_progress_s) {
        options.on_progress(frame->time_s, experiment.duration_s);
        next_progress_s = std::floor(frame->time_s) + 1.0;
      }
      if (frame->time_s >= experiment.duration_s) break;
      if (controller->done()) break;  // a finished route, or an exploration with no exit left
      const mapper::VelocityCommand cmd = controller->step(
          nav_input(experiment.controller, seen, frame->true_pose, steering, geometry));
      robot.command(cmd);
      const mapper::nav::NavTrace& t = controller->trace();
      mode = t.mode;
      if (experiment.nav_trace) {
        session.nav_rows.push_back({seen.time_s, mapper::nav::to_string(t.mode), t.waypoint_index,
                                    t.target_rad, t.direction_rad, t.has_direction,
                                    t.front_clearance_m, t.door_active, t.door_center_m,
                                    t.door_normal_rad, t.door_width_m, cmd.v_mps, cmd.w_radps});
      }
    }
    robot.stop();
    closing_run = true;
    mapper.finish();
    if (!session.rows.empty()) session.closed_heading_rad = mapper.pose_estimate().theta_rad;
    // The end-of-run relaxation re-placed rooms the listener already drew: move their walls,
    // labels and breakdown samples with them.
    if (room_task.valid()) room_task.get();
    move_rooms(mapper.room_moves(), corrected, labels);
    if (breakdown) breakdown->move_rooms(mapper.room_moves());
  } catch (const std::exception& e) {
    try {
      robot.stop();
    } catch (...) {
      // Already failing; the original error is the one to report.
    }
    throw RunError(std::string("run failed at t = ") + std::to_string(session.sim_time_s) +
                   " s: " + e.what());
  }
  session.wall_time_s = seconds(Clock::now() - wall_start - figure_time);
  if (experiment.controller.type == ControllerKind::kRoute) {
    // Completed means every waypoint reached or passed: a route that ended by giving
    // waypoints up is finished, not completed (nav.waypoints_skipped says how many).
    session.route_completed = controller->done() && controller->skipped_waypoints() == 0;
  }

  RunSummary summary;
  summary.out_dir = out;
  RunMetrics& m = summary.metrics;
  m.name = experiment.name;
  m.world = experiment.world.filename().string();
  m.seed = experiment.seed;
  m.source = std::string(to_string(experiment.robot_source));
  m.controller = std::string(to_string(experiment.controller.type));
  m.steering = experiment.controller.steer_by_truth            ? "truth"
               : experiment.controller.steer_by_plain_estimate ? "plain_estimate"
                                                               : "estimate";
  m.grid = grid_name(experiment.mapper.grid);
  m.boundary =
      experiment.mapper.boundary == mapper::BoundaryKind::kDoorway ? "doorway" : "distance";
  m.localization_kind =
      experiment.mapper.localization == mapper::LocalizationKind::kEm ? "em" : "none";
  m.odometry_curvature_gain =
      mapper::applied_curvature_gain(experiment.mapper.odometry_calibration, geometry);
  m.odometry_track_m = geometry.odometry_track_m;
  m.max_room_travel_m = mapper::applied_max_room_travel_m(experiment.mapper);
  m.frames = session.rows.size();
  m.route_completed = session.route_completed;
  m.nav = nav_metrics(*controller, experiment.controller, session, stalled_s);
  m.nav.turn_deg = turning.turn_deg;
  m.nav.turn_deg_by_mode = std::move(turning.turn_deg_by_mode);
  m.nav.time_s_by_mode = std::move(turning.time_s_by_mode);
  m.nav.heading_drift_deg_by_mode = std::move(turning.heading_drift_deg_by_mode);
  m.sim_time_s = session.sim_time_s;
  m.wall_time_s = session.wall_time_s;
  const mapper::MapperStats& stats = mapper.stats();
  m.readings_used = stats.readings_used;
  m.rejected = stats.rejected;
  m.door_fixes = stats.door_fixes;
  m.door_fix_total_m = stats.door_fix_abs_m;
  m.held_turns = stats.held_turns;
  m.held_turn_removed_deg = stats.held_turn_removed_abs_rad * 180.0 / std::numbers::pi;
  m.relaxation = relaxation_metrics(experiment.mapper, stats);
  m.scan_match = scan_match_metrics(experiment.mapper, stats);
  m.build_time_s = stats.build_time_s;
  m.localization_time_s = stats.localization_time_s;
  m.room_cpu_s = room_cpu_s;
  m.room_wall_s = room_wall_s;

  try {
    std::vector<RoomSize> sizes;
    for (const RoomReport& r : room_reports) {
      sizes.push_back(r.size);
      m.rooms.push_back(r);
    }
    m.asr_count = m.rooms.size();
    m.memory = memory_metrics(sizes);

    if (room_task.valid()) room_task.get();  // the last room's grid file and breakdown
    const TrajectoryView rows = session.rows.view();
    // trajectory.csv (and the nav trace) only read the rows: written on a second thread while
    // this one works out the truth metrics and the maps (it formats ~10 numbers a frame).
    auto trajectory_files = std::async(std::launch::async, [&] {
      mapper::io::write_file_atomic_chunks(
          out / "trajectory.csv",
          [&](const mapper::io::ChunkSink& emit) { trajectory_csv_chunks(rows, emit); },
          durability);
      if (experiment.nav_trace) {
        mapper::io::write_file_atomic_chunks(
            out / "nav_trace.csv",
            [&](const mapper::io::ChunkSink& emit) {
              nav_trace_csv_chunks(session.nav_rows, emit);
            },
            durability);
      }
      if (experiment.explore_map) {
        // The frontier explorer's map as it ended (other controllers have none).
        if (const auto image = controller->explore_map())
          write_explore_map(*image, out, durability);
      }
    });

    // The figures and the SVG draw the paths at 5 cm spacing.
    constexpr double kDrawnPathStep_m = 0.05;
    PathSubsampler true_path(kDrawnPathStep_m), est_path(kDrawnPathStep_m),
        odom_path(kDrawnPathStep_m);
    for (const TrajectoryRow& r : rows) {
      est_path.add(r.estimate.translation());  // the SVG's
      if (!figures) continue;                  // the other two only for the figures
      if (r.truth) true_path.add(r.truth->translation());
      odom_path.add(r.odometry.translation());
    }
    if (truth) {
      m.localization = evaluate_trajectory(rows, session.closed_heading_rad);
      m.error_breakdown = breakdown->finish(rows);
      add_contacts(m.nav, rows, truth->surfaces, geometry, &breakdown->truth_index(),
                   session.mode_changes);
      if (experiment.controller.type == ControllerKind::kExplore) {
        const TrueRooms rooms = count_true_rooms(truth->surfaces, rows);
        if (rooms.measurable) {  // else null: a world too large to rasterise finely
          m.nav.rooms_total_true = rooms.total;
          m.nav.rooms_visited_true = rooms.visited;
        }
      }
    }

    mapper::io::write_file_atomic(out / "map_segments.csv", segments_csv(corrected), durability);
    mapper::io::write_file_atomic(out / "map_segments_odom.csv", segments_csv(odometry),
                                  durability);
    mapper::io::write_asr_graph_json(mapper.graph(), out / "asr_graph.json", durability);
    SvgMap svg{corrected, truth ? truth->surfaces : std::vector<mapper::Segment>{}, est_path.path(),
               labels};
    mapper::io::write_file_atomic(out / "map.svg", map_svg(svg), durability);
    if (truth) {
      const std::vector<mapper::Point2> visible = visible_truth->finish();
      // The two maps are scored on the two cores (pure functions: the same result either way),
      // against the breakdown's index of the true surfaces.
      const SegmentIndex& truth_index = breakdown->truth_index();
      auto odometry_score = std::async(std::launch::async, [&] {
        return evaluate_map(segments_of(odometry), truth_index, visible, metric_options);
      });
      m.map = evaluate_map(segments_of(corrected), truth_index, visible, metric_options);
      m.map_odometry = odometry_score.get();
    }

    if (figures) {
      render::MapFigure fig;
      fig.title = experiment.name + " (seed " + std::to_string(experiment.seed) + ")";
      if (truth) fig.true_surfaces = truth->surfaces;
      fig.map_odometry = segments_of(odometry);
      fig.map_corrected = segments_of(corrected);
      fig.true_path = true_path.path();
      fig.odometry_path = odom_path.path();
      fig.estimated_path = est_path.path();
      for (const auto& [id, p] : labels) {
        fig.room_labels_at.push_back(p);
        fig.room_labels.push_back(std::to_string(id));
      }
      render::write_map_figure(fig, out / "figures" / "map_before_after.png");
      if (truth) draw_map_error(fig.title, fig.map_corrected, *truth, *breakdown, m, out);
      render::write_graph_figure(mapper.graph(), experiment.name + ": room graph",
                                 out / "figures" / "graph.png");
    }
    trajectory_files.get();  // rethrows a failed write
    // Last: its presence marks the run as finished (sweeps skip finished runs).
    mapper::io::write_file_atomic(out / "metrics.json", metrics_json_text(m), durability);
  } catch (const std::exception& e) {
    throw RunError(std::string("writing the results failed: ") + e.what());
  }
  return summary;
}

}  // namespace cogmap::experiments
