#include "cogmap/experiments/experiment_config.h"

#include <cmath>
#include <numbers>
#include <sstream>
#include <string_view>

#include "cogmap/sim/sim_robot.h"
#include "cogmap/sim/world_spec.h"
#include "config_numbers.h"

namespace cogmap::experiments {
namespace {

using detail::number_above;
using detail::number_in;
using yaml::ConfigError;
using yaml::Node;

int line_or(const YAML::Mark& mark, int fallback) {
  return mark.is_null() ? fallback : mark.line + 1;
}

// The line of `key_path` ("controller.waypoints") as the file wrote it: its key's line, or for
// a key the file does not have, the line of the block it would be in (`line` for none). Not the
// value's own line: yaml-cpp marks an empty value ("name:" and nothing) at the next token, a
// line further down, and a --set value carries the lines of its own text (always 1).
int written_line(const YAML::Node& map, std::string_view key_path, int line = 0) {
  if (!map.IsMap()) return line;
  line = line_or(map.Mark(), line);
  const std::size_t dot = std::min(key_path.find('.'), key_path.size());
  for (const auto& kv : map) {
    if (!kv.first.IsScalar() || kv.first.Scalar() != key_path.substr(0, dot)) continue;
    if (kv.first.Mark().is_null()) return line;  // a key --set created
    line = kv.first.Mark().line + 1;
    return dot == key_path.size() ? line : written_line(kv.second, key_path.substr(dot + 1), line);
  }
  return line;
}

// A free text the run writes out (metrics.json, the sweep tables, figure titles). JSON holds
// UTF-8 only: a name of bytes FF FE ran the whole simulation and then failed writing it, so
// the text is checked here, where the error can still name the line.
std::string utf8_text(const Node& node) {
  std::string text = node.as<std::string>();
  if (const std::size_t at = yaml::invalid_utf8_at(text); at != std::string_view::npos) {
    std::ostringstream msg;
    msg << "not valid UTF-8 text (byte 0x" << std::hex
        << static_cast<int>(static_cast<unsigned char>(text[at])) << std::dec << " at offset " << at
        << "); the run writes it into metrics.json, which holds UTF-8 only";
    node.fail(msg.str());
  }
  return text;
}

// The text of `key`, UTF-8 and not empty.
std::string required_text(const Node& map, const std::string& key, const std::string& if_empty) {
  const Node value = map[key];  // "missing required key" when absent
  // An empty value is reported on its key's line (Node::line()), not the next key's.
  if (value.raw().IsNull()) value.fail(if_empty);
  std::string text = utf8_text(value);
  if (text.empty()) value.fail(if_empty);
  return text;
}

// The text of an optional `key`, UTF-8; empty when absent.
std::string optional_text(const Node& map, const std::string& key) {
  const auto value = map.child(key);
  if (!value) return "";
  if (value->raw().IsNull()) value->fail("expected a string (or no key at all)");
  return utf8_text(*value);
}

RobotSource parse_source(const Node& n) {
  const std::string s = n.as<std::string>();
  if (s == "sim") return RobotSource::kSim;
  if (s == "p2os") return RobotSource::kP2os;
  if (s == "log") return RobotSource::kLog;
  n.fail("unknown robot source '" + s + "' (expected sim, p2os or log)");
}

ControllerConfig parse_controller(const Node& block) {
  block.expect_keys({"type", "speed_mps", "waypoints", "waypoint_tolerance_m", "pose", "strategy",
                     "time_budget_s", "distance_budget_m", "door_search", "grazing_walls",
                     "plan_over_trail", "blocked_path_s", "arc_guard_s", "progress_along_path"});
  ControllerConfig c;
  const Node type = block["type"];
  const std::string t = type.as<std::string>();
  if (t == "route") {
    c.type = ControllerKind::kRoute;
  } else if (t == "explore") {
    c.type = ControllerKind::kExplore;
  } else if (t == "none" || t == "teleop") {
    c.type = ControllerKind::kNone;
  } else {
    type.fail("unknown controller type '" + t + "' (expected route, explore or none)");
  }
  c.speed_mps = number_in(block, "speed_mps", 0.01, 2.0, c.speed_mps);
  // A tolerance beyond a room's size would make every waypoint (and every explorer goal)
  // "reached" where it stands.
  c.waypoint_tolerance_m =
      number_in(block, "waypoint_tolerance_m", 0.01, 5.0, c.waypoint_tolerance_m);
  if (const auto wps = block.child("waypoints")) {
    wps->expect_sequence();
    for (std::size_t i = 0; i < wps->size(); ++i) {
      const Node p = wps->at(i);
      if (!p.is_sequence() || p.size() != 2) p.fail("a waypoint is [x_m, y_m]");
      // The world's bound: a waypoint at 1e155 m overflowed the distance to it and counted as
      // reached at once.
      c.waypoints.emplace_back(sim::parse_coordinate(p.at(0)), sim::parse_coordinate(p.at(1)));
    }
  }
  if (const auto pose = block.child("pose")) {
    const std::string p = pose->as<std::string>();
    if (p != "estimate" && p != "plain_estimate" && p != "truth") {
      pose->fail("unknown pose source '" + p + "' (expected estimate, plain_estimate or truth)");
    }
    c.steer_by_truth = p == "truth";
    c.steer_by_plain_estimate = p == "plain_estimate";
  }
  if (const auto strategy = block.child("strategy")) {
    if (c.type != ControllerKind::kExplore) strategy->fail("strategy is only used by explore");
    const std::string st = strategy->as<std::string>();
    if (st == "frontier") {
      c.explore_strategy = mapper::nav::ExploreStrategy::kFrontier;
    } else if (st == "heading") {
      c.explore_strategy = mapper::nav::ExploreStrategy::kHeading;
    } else if (st == "edge") {
      c.explore_strategy = mapper::nav::ExploreStrategy::kEdge;
    } else {
      strategy->fail("unknown explore strategy '" + st + "' (expected frontier, edge or heading)");
    }
  }
  for (const char* key : {"time_budget_s", "distance_budget_m", "plan_over_trail", "blocked_path_s",
                          "progress_along_path"}) {
    if (block.child(key) && c.type != ControllerKind::kExplore) {
      block[key].fail(std::string(key) + " is only used by explore");
    }
  }
  if (const auto search = block.child("door_search")) c.door_search = search->as<bool>();
  if (const auto walls = block.child("grazing_walls")) c.grazing_walls = walls->as<bool>();
  if (const auto trail = block.child("plan_over_trail")) c.plan_over_trail = trail->as<bool>();
  if (const auto along = block.child("progress_along_path")) {
    c.progress_along_path = along->as<bool>();
  }
  c.explore_time_budget_s = number_in(block, "time_budget_s", 0.0, 1e6, 0.0);
  c.explore_distance_budget_m = number_in(block, "distance_budget_m", 0.0, 1e6, 0.0);
  // Beyond an hour a blocked path is never left before give_up_s anyway.
  c.blocked_path_s = number_in(block, "blocked_path_s", 0.0, 3600.0, c.blocked_path_s);
  // Beyond 5 s (2.5 m at 0.5 m/s) every doorway's jambs lie on the arc ahead.
  if (block.child("arc_guard_s")) c.arc_guard_s = number_in(block, "arc_guard_s", 0.0, 5.0, 0.0);
  if (c.type == ControllerKind::kRoute && c.waypoints.empty()) {
    block.fail("a route controller needs at least one waypoint in 'waypoints'");
  }
  if (c.type != ControllerKind::kRoute && !c.waypoints.empty()) {
    block["waypoints"].fail("waypoints are only used by a route controller");
  }
  return c;
}

// `inner` is `outer` or a node inside it ("a.b" and "a.b[0]" are inside "a").
bool key_within(const std::string& inner, const std::string& outer) {
  return !outer.empty() &&
         (inner == outer || inner.starts_with(outer + ".") || inner.starts_with(outer + "["));
}

// An override as the user typed it, on one line and printable: a value may hold newlines,
// control characters or bytes that are not UTF-8, which a terminal would garble.
std::string printable(const std::string& override_text) {
  const bool utf8 = yaml::invalid_utf8_at(override_text) == std::string_view::npos;
  std::string out;
  for (const char ch : override_text) {
    const auto b = static_cast<unsigned char>(ch);
    if (ch == '\n') {
      out += "\\n";
    } else if (b < 0x20 || b == 0x7F || (b >= 0x80 && !utf8)) {
      constexpr char kHex[] = "0123456789abcdef";
      out += {'\\', 'x', kHex[b >> 4], kHex[b & 0xF]};
    } else {
      out += ch;
    }
  }
  return out;
}

std::string shown(const std::string& override_text) {
  return "(from --set " + printable(override_text) + ")";
}

// Every override, for an error none of them wrote but which they may have caused: a file key
// that another key's new value makes invalid (`--set controller.type=explore` against a
// route's `waypoints`) is reported at the file's line, which looks right on its own.
std::string applied(const std::vector<std::string>& overrides) {
  std::string out;
  for (const std::string& o : overrides) {
    out += (out.empty() ? "(with --set " : ", --set ") + printable(o);
  }
  return out + ")";
}

// The override an error at `key` comes from, and whether the error lies in the value it wrote
// (the node itself or something in it) rather than at a parent it created or changed
// (`--set a.b=1` makes the unknown key `a`; `--set mapper.grid.x=1` turns `grid` into a
// mapping). Null when no override did it.
struct Cause {
  const std::string* override_text = nullptr;
  bool in_value = false;
};

Cause override_of(const std::string& key, const std::vector<std::string>& overrides) {
  if (key.empty()) return {};
  for (const std::string& o : overrides) {
    if (key_within(key, o.substr(0, o.find('=')))) return {&o, true};
  }
  for (const std::string& o : overrides) {
    if (key_within(o.substr(0, o.find('=')), key)) return {&o, false};
  }
  return {};
}

// Re-raises an error caused by a --set override so it also says which override did it, at the
// line of the key it overrides. The value's own nodes carry lines of the value's text (always
// 1), and the parents it created none: those would point at the wrong line of the file. An
// error at a key no override touched keeps its place and lists the overrides applied.
[[noreturn]] void rethrow_with_override(const ConfigError& e, const YAML::Node& root,
                                        const std::vector<std::string>& overrides) {
  const Cause cause = override_of(e.key(), overrides);
  if (!cause.override_text) {
    if (overrides.empty()) throw e;
    throw ConfigError(e.file(), e.line(), e.key(), bare_message(e) + " " + applied(overrides));
  }
  const std::string& o = *cause.override_text;
  int line = e.line();
  if (cause.in_value) {
    line = written_line(root, o.substr(0, o.find('=')));
  } else if (line == 0) {
    line = written_line(root, e.key());
  }
  throw ConfigError(e.file(), line, e.key(), bare_message(e) + " " + shown(o));
}

}  // namespace

std::string bare_message(const ConfigError& e) {
  std::string message = e.what();
  std::string prefix = e.file();
  if (e.line() > 0) prefix += ":" + std::to_string(e.line());
  prefix += ": ";
  if (!e.key().empty()) prefix += e.key() + ": ";
  return message.starts_with(prefix) ? message.substr(prefix.size()) : message;
}

std::string_view to_string(RobotSource source) {
  switch (source) {
    case RobotSource::kSim:
      return "sim";
    case RobotSource::kP2os:
      return "p2os";
    case RobotSource::kLog:
      return "log";
  }
  return "?";
}

std::string_view to_string(ControllerKind kind) {
  switch (kind) {
    case ControllerKind::kRoute:
      return "route";
    case ControllerKind::kExplore:
      return "explore";
    case ControllerKind::kNone:
      return "none";
  }
  return "?";
}

Experiment parse_experiment(const Node& root, const std::filesystem::path& file) {
  root.expect_keys({"name", "description", "world", "seed", "duration_s", "start", "robot",
                    "controller", "mapper", "output"});
  Experiment e;
  e.file = file;
  e.name = required_text(root, "name", "must not be empty");
  // Found by fuzzing (session 56): an ESC sequence in a name was printed raw on the terminal.
  yaml::expect_one_printable_line(root["name"], e.name);
  (void)optional_text(root, "description");
  const std::string world =
      required_text(root, "world", "must not be empty (a world file, or 'none')");
  e.world_line = root["world"].line();
  const std::filesystem::path world_path(world);
  e.world = world_path.is_absolute() ? world_path : file.parent_path() / world_path;
  e.world = e.world.lexically_normal();
  e.seed = root.get_or<std::uint64_t>("seed", e.seed);
  e.duration_s = number_above(root, "duration_s", 0.0, e.duration_s);
  if (e.duration_s > ExperimentLimits{}.max_duration_s) {
    std::ostringstream msg;
    msg << "must be at most " << ExperimentLimits{}.max_duration_s
        << " s (the run-duration limit, docs/reliability.md), got " << e.duration_s;
    root["duration_s"].fail(msg.str());
  }

  if (const auto start = root.child("start")) {
    start->expect_keys({"x_m", "y_m", "theta_deg"});
    // The bounds a world's own start has: beyond them the physics is single-precision noise,
    // and a heading of 1e308 degrees was infinite in radians (Box2D aborted on it).
    const auto theta = start->child("theta_deg");
    e.start = mapper::Pose2{sim::parse_coordinate((*start)["x_m"]),
                            sim::parse_coordinate((*start)["y_m"]),
                            theta ? mapper::wrap_angle_rad(sim::parse_angle_deg(*theta)) : 0.0};
  }
  if (const auto robot = root.child("robot")) {
    robot->expect_map();
    if (const auto src = robot->child("source")) e.robot_source = parse_source(*src);
    e.robot = *robot;
  }
  if (const auto c = root.child("controller")) {
    e.controller = parse_controller(*c);
    e.steering_given = c->child("pose").has_value();
  }
  if (const auto m = root.child("mapper")) {
    e.mapper = parse_mapper_options(*m);
    e.room_travel_given = m->child("max_room_travel_m").has_value();
    e.scan_match_given = m->child("scan_match").has_value();
    e.scan_match_shift_given = m->child("scan_match_shift").has_value();
  }
  apply_controller_defaults(e);
  if (const auto out = root.child("output")) {
    out->expect_keys({"figures", "nav_trace", "explore_map"});
    e.figures = out->get_or<bool>("figures", e.figures);
    e.nav_trace = out->get_or<bool>("nav_trace", e.nav_trace);
    e.explore_map = out->get_or<bool>("explore_map", e.explore_map);
  }
  YAML::Emitter emitter;
  emitter << root.raw();
  e.resolved_yaml = std::string(emitter.c_str()) + "\n";
  return e;
}

void apply_controller_defaults(Experiment& e) {
  const bool explore = e.controller.type == ControllerKind::kExplore;
  if (!e.room_travel_given) e.mapper.max_room_travel_m = explore ? kExploreMaxRoomTravelM : 0.0;
  // An explorer's map is drawn with the echoes matched against the last minute, turning only,
  // while the robot steers by an estimate without them: on generated buildings the maps came
  // 13-21 % closer to the walls at the very same drives; steering by the matcher doubled the
  // contacts (docs/algorithms.md, "The matcher in the map only"). Routes keep the thesis's
  // correction between rooms alone.
  const mapper::ScanMatchOptions library;
  if (!e.scan_match_given) e.mapper.scan_match.enabled = explore || library.enabled;
  if (!e.scan_match_shift_given) e.mapper.scan_match.shift = explore ? false : library.shift;
  if (!e.steering_given) {
    e.controller.steer_by_truth = false;
    e.controller.steer_by_plain_estimate = explore;
  }
}

namespace {

Experiment parse_with_overrides(Node root, const std::filesystem::path& file,
                                const std::vector<std::string>& overrides,
                                std::optional<std::uint64_t> seed_override) {
  root.expect_map();
  for (const std::string& o : overrides) {
    try {
      yaml::apply_override(root.raw(), o);
    } catch (const ConfigError& e) {
      // apply_override knows only the override ("--set", no line): name the file and the line
      // of the key it could not set, as for every other error an override causes (none for an
      // override that is no key=value at all).
      const std::size_t eq = o.find('=');
      const bool has_key = eq != std::string::npos && eq > 0;
      throw ConfigError(root.file(), has_key ? written_line(root.raw(), e.key()) : 0, e.key(),
                        bare_message(e) + " " + shown(o));
    }
  }
  if (seed_override) root.raw()["seed"] = *seed_override;
  Experiment experiment;
  try {
    experiment = parse_experiment(root, file);
    // The simulator's robot block is read by the run, which knows no overrides: checked here
    // too, an error `--set robot.sonar.rays_per_cone=0` causes names its line and override
    // (it said `e.yaml:1: robot.sonar.rays_per_cone: ...` and nothing of the --set).
    if (experiment.robot_source == RobotSource::kSim && experiment.robot) {
      (void)sim::parse_sim_robot_options(*experiment.robot);
    }
  } catch (const ConfigError& e) {
    rethrow_with_override(e, root.raw(), overrides);
  }
  // The world file is read later (by the run): its errors name the `world` key where the file
  // wrote it and the override that set it, as parse errors do.
  if (const Cause cause = override_of("world", overrides); cause.override_text) {
    experiment.world_line = written_line(root.raw(), "world");
    experiment.world_override = shown(*cause.override_text);
  }
  return experiment;
}

}  // namespace

Experiment load_experiment(const std::filesystem::path& path,
                           const std::vector<std::string>& overrides,
                           std::optional<std::uint64_t> seed_override) {
  return parse_with_overrides(Node::load_file(path), path, overrides, seed_override);
}

Experiment load_experiment_text(const std::string& text, const std::string& name,
                                const std::vector<std::string>& overrides) {
  return parse_with_overrides(Node::load_string(text, name), std::filesystem::current_path() / name,
                              overrides, std::nullopt);
}

}  // namespace cogmap::experiments
