// The robot model table. Every number below is a fact from ARIA's robot parameter files
// (AriaCoda params/*.p: SonarUnit i x_mm y_mm heading_deg, RobotLength, RobotWidth,
// DiffConvFactor) or, for speed limits, the AMRISim/MobileSim robot models
// (PioneerRobotModels.world.inc: max_speed, accel, decel). The `--peers` test
// (tests/peers/aria_params_test) checks the mounts against the parameter files themselves.
#include <algorithm>
#include <array>
#include <cctype>
#include <numbers>

#include "cogmap/mapper/seam/robot_models.h"

namespace cogmap::mapper {
namespace {

struct Mount {
  double x_mm, y_mm, heading_deg;
};

// p2at.p, p2at8.p, p2at8+.p, p3at.p, p3at-sh.p: SonarUnit 0-15.
constexpr std::array<Mount, 16> kAtRing{{{147, 136, 90},
                                         {193, 119, 50},
                                         {227, 79, 30},
                                         {245, 27, 10},
                                         {245, -27, -10},
                                         {227, -79, -30},
                                         {193, -119, -50},
                                         {147, -136, -90},
                                         {-144, -136, -90},
                                         {-189, -119, -130},
                                         {-223, -79, -150},
                                         {-241, -27, -170},
                                         {-241, 27, 170},
                                         {-223, 79, 150},
                                         {-189, 119, 130},
                                         {-144, 136, 90}}};

// p3dx.p, p3dx-sh.p, p2dx.p, p2de.p, p2d8.p, p2d8+.p, and SonarUnit 0-15 of peoplebot-sh.p.
constexpr std::array<Mount, 16> kDxRing{{{69, 136, 90},
                                         {114, 119, 50},
                                         {148, 78, 30},
                                         {166, 27, 10},
                                         {166, -27, -10},
                                         {148, -78, -30},
                                         {114, -119, -50},
                                         {69, -136, -90},
                                         {-157, -136, -90},
                                         {-203, -119, -130},
                                         {-237, -78, -150},
                                         {-255, -27, -170},
                                         {-255, 27, 170},
                                         {-237, 78, 150},
                                         {-203, 119, 130},
                                         {-157, 136, 90}}};

// peoplebot-sh.p SonarUnit 16-23 (the upper front ring) and 24-31 (the upper rear ring).
constexpr std::array<Mount, 16> kPeopleBotUpper{{{-20, 136, 90},
                                                 {24, 119, 50},
                                                 {58, 78, 30},
                                                 {77, 27, 10},
                                                 {77, -27, -10},
                                                 {58, -78, -30},
                                                 {24, -119, -50},
                                                 {-20, -136, -90},
                                                 {-191, -136, -90},
                                                 {-237, -119, -130},
                                                 {-271, -78, -150},
                                                 {-290, -27, -170},
                                                 {-290, 27, 170},
                                                 {-271, 78, 150},
                                                 {-237, 119, 130},
                                                 {-191, 136, 90}}};

struct Body {
  double length_mm, width_mm;            // RobotLength, RobotWidth
  double max_speed_mps, max_turn_radps;  // AMRISim max_speed [x 0 theta]
  double diff_conv;                      // DiffConvFactor, rad/s per mm/s of wheel speed difference
};

RobotModel make(const char* name, const char* params, DriveKind drive, const Body& body,
                std::initializer_list<const std::array<Mount, 16>*> rings) {
  RobotModel m;
  m.name = name;
  m.aria_params = params;
  RobotGeometry& g = m.geometry;
  g.drive = drive;
  g.odometry_track_m = 2.0 / body.diff_conv / 1000.0;
  for (const auto* ring : rings) {
    for (const Mount& s : *ring) {
      g.sonars.push_back(
          {s.x_mm / 1000.0, s.y_mm / 1000.0, s.heading_deg * std::numbers::pi / 180.0});
    }
  }
  // Polaroid transducers on every Pioneer: ~0.1-5 m (ARIA caps readings at 5000 mm; AMRISim's
  // pioneerSonar `sview [0.1 5.0 30]`), 30 degree beam.
  g.sonar_min_range_m = 0.1;
  g.sonar_max_range_m = 5.0;
  g.sonar_beam_width_rad = 30.0 * std::numbers::pi / 180.0;
  g.length_m = body.length_mm / 1000.0;
  g.width_m = body.width_mm / 1000.0;
  g.max_speed_mps = body.max_speed_mps;
  g.max_turn_rate_radps = body.max_turn_radps;
  g.max_accel_mps2 = 0.3;  // AMRISim `pioneer` accel [0.3 0 1.74]
  g.max_decel_mps2 = 0.6;  // AMRISim `pioneer` decel [0.6 0 1.74]
  return m;
}

std::vector<RobotModel> build_table() {
  using enum DriveKind;
  // p2at/p2at8 share the body; AMRISim limits the P2-AT to 0.75 m/s, 1.74 rad/s.
  const Body at{626, 505, 0.75, 1.74, 0.0034};
  // AMRISim's p3at: max_speed [0.6 0 0.75].
  const Body p3at{626, 505, 0.6, 0.75, 0.0034};
  // AMRISim's p3dx: max_speed [1.0 0 1.74]; p2de/p2d8: [0.75 0 1.74].
  const Body p3dx{511, 425, 1.0, 1.74, 0.0056};
  const Body p2dx{511, 425, 0.75, 1.74, 0.0056};
  // peoplebot-sh.p: 513 x 425 mm, DiffConvFactor 0.006; AMRISim max_speed [0.75 0 1.74].
  const Body peoplebot{513, 425, 0.75, 1.74, 0.006};
  return {
      make("p2at", "p2at.p", kSkidSteer, at, {&kAtRing}),
      make("p2at8", "p2at8.p", kSkidSteer, at, {&kAtRing}),
      make("p3at", "p3at.p", kSkidSteer, p3at, {&kAtRing}),
      make("p3dx", "p3dx.p", kDifferential, p3dx, {&kDxRing}),
      make("p2dx", "p2dx.p", kDifferential, p2dx, {&kDxRing}),
      make("p2de", "p2de.p", kDifferential, p2dx, {&kDxRing}),
      make("peoplebot", "peoplebot-sh.p", kDifferential, peoplebot, {&kDxRing, &kPeopleBotUpper}),
  };
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// ARIA subclasses whose parameter file has the same sonar mounts and body as a model above.
struct Alias {
  const char* subclass;
  const char* model;
};
constexpr std::array<Alias, 6> kAliases{{{"p2at8+", "p2at8"},
                                         {"p3at-sh", "p3at"},
                                         {"p3dx-sh", "p3dx"},
                                         {"p2d8", "p2dx"},
                                         {"p2d8+", "p2dx"},
                                         {"peoplebot-sh", "peoplebot"}}};

}  // namespace

const std::vector<RobotModel>& robot_models() {
  static const std::vector<RobotModel> table = build_table();
  return table;
}

const RobotModel* find_robot_model(std::string_view name) {
  std::string key = lower(name);
  for (const Alias& a : kAliases) {
    if (key == a.subclass) key = a.model;
  }
  for (const RobotModel& m : robot_models()) {
    if (m.name == key) return &m;
  }
  return nullptr;
}

std::string robot_model_names() {
  std::string out;
  for (const RobotModel& m : robot_models()) {
    if (!out.empty()) out += ", ";
    out += m.name;
  }
  return out;
}

}  // namespace cogmap::mapper
