// Player 2.x/3.x writelog importer (docs/robot-driver.md "Importers"). Lines as writelog.cc
// writes them: "%014.3f %u %u %s %02u %03u %03u " (time host robot interface index type subtype),
// then the payload. Two passes: the first lists the devices (which position2d is the odometry,
// which sonar arrays and sonar-like rangers and their mounts), the second makes the frames.
// The ranger payloads (Player 3, Stage 4) are read in player_ranger.cc.
#include <algorithm>
#include <charconv>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "cogmap/hw/log_import.h"
#include "import_common.h"
#include "log_checks.h"
#include "player_ranger.h"

namespace cogmap::hw {
namespace {

// A Player device address (host, robot = port, index) of one interface. writelog writes the
// host as a number; it is kept as written.
using Device = std::tuple<std::string, long, long>;

std::string name_of(const Device& d, const std::string& interface) {
  return std::to_string(std::get<1>(d)) + ":" + interface + ":" + std::to_string(std::get<2>(d));
}

// "robot:interface:index" of any line, for the tally: as written, without validating the
// fields of lines that are skipped anyway (index "00" is 0).
std::string line_device(const detail::Fields& f) {
  const std::string& index = f.at(4);
  const auto digit = index.find_first_not_of('0');
  return f.at(2) + ":" + f.at(3) + ":" + (digit == std::string::npos ? "0" : index.substr(digit));
}

// Transducers that can be placed: a `sonar` device, or a `ranger` whose geometry has one pose
// per element (Stage 4's sonar rings).
struct SonarDevice {
  std::vector<mapper::SonarMount> mounts;  // from its first geometry line
  std::size_t geometry_line = 0;           // 0: none
  bool has_ranges = false;
  bool used = false;
  std::string name;        // "robot:interface:index"
  std::size_t offset = 0;  // its first transducer's index in the joined geometry
  // Rangers only: the first ranges line, the most ranges in one line, the first config.
  std::size_t ranges_line = 0;
  std::size_t most_ranges = 0;
  std::optional<detail::RangerConfig> config;
  std::size_t config_line = 0;
};

// What a ranger with ranges is, by its geometry. Stage publishes one range per sensor when a
// ranger has several (a sonar ring) and every range of its one sensor otherwise (a laser);
// libplayerc reads a one-element ranger as a scan from min_angle on.
enum class RangerKind { kSonar, kLaser, kUnplaced };

RangerKind kind_of(const SonarDevice& r) {
  if (r.geometry_line == 0) return RangerKind::kUnplaced;
  if (r.mounts.size() >= 2 || (r.mounts.size() == 1 && r.most_ranges <= 1)) {
    return RangerKind::kSonar;
  }
  return RangerKind::kLaser;
}

constexpr const char* kPlayer2 = "cogmap reads the files of Player 2.x and 3.x's writelog";

// The most transducers a geometry may join: a cogmap log's header holds no more (`sonars=N`,
// robot_log.cc), nor does CARMEN's num_sonars or one Player sonar array's count.
constexpr std::size_t kMaxTransducers = 255;

// Reads the common header of a data line; false for a comment or blank line. Refuses Player 1.x.
bool read_header(detail::Fields& f, bool comment) {
  if (comment) {
    // "## File version 0.3.0": Player 2.x and 3.x; 0.0.0-0.2.0 were Player 1.x's writelog.
    if (f.size() >= 4 && f.at(0) == "##" && f.at(1) == "File" && f.at(2) == "version" &&
        (f.at(3) == "0.0.0" || f.at(3) == "0.1.0" || f.at(3) == "0.2.0")) {
      f.fail_line("a Player 1.x log (file version " + f.at(3) + "): " + kPlayer2 +
                  " (file version 0.3.0), whose lines have type and subtype fields");
    }
    return false;
  }
  if (f.size() >= 4 && f.at(3) == "position") {
    f.fail_line("interface 'position' is Player 1.x's: " + std::string(kPlayer2) +
                " (position2d and sonar)");
  }
  if (f.size() < 7) f.fail("time host robot interface index type subtype", f.size());
  return true;
}

Device device_of(const detail::Fields& f) {
  return {f.at(1), f.integer(2, "robot (port)", 0, 4294967295L), f.integer(4, "index", 0, 65535)};
}

// A sonar geometry payload: count (x y yaw)*count.
std::vector<mapper::SonarMount> sonar_geometry(const detail::Fields& f) {
  const long n = f.integer(7, "pose count", 0, 255);
  if (f.size() != 8 + 3 * static_cast<std::size_t>(n)) {
    f.fail("sonar geometry count (x y yaw)*count", f.size());
  }
  std::vector<mapper::SonarMount> mounts;
  for (long i = 0; i < n; ++i) {
    const std::size_t k = 8 + 3 * static_cast<std::size_t>(i);
    mounts.push_back(
        {f.number(k, "sonar x"), f.number(k + 1, "sonar y"), f.number(k + 2, "sonar yaw")});
  }
  return mounts;
}

bool is_geometry(long type, long subtype) {
  return (type == 1 && subtype == 2) || (type == 4 && subtype == 1);
}

bool is_ranger_ranges(long type, long subtype) {
  return type == detail::kPlayerData &&
         (subtype == detail::kRangerDataRange || subtype == detail::kRangerDataRangeStamped);
}

bool is_ranger_geometry(long type, long subtype) {
  return type == detail::kPlayerRespAck && subtype == detail::kRangerReqGetGeom;
}

// The reply to GET_GEOM: a geometry and nothing after it.
std::vector<mapper::SonarMount> ranger_geometry_reply(const detail::Fields& f) {
  std::size_t end = 0;
  auto mounts = detail::ranger_geometry(f, 7, end);
  if (f.size() != end) f.fail("end of line after the ranger geometry", end);
  return mounts;
}

bool same_mounts(const std::vector<mapper::SonarMount>& a,
                 const std::vector<mapper::SonarMount>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].x_m != b[i].x_m || a[i].y_m != b[i].y_m || a[i].heading_rad != b[i].heading_rad) {
      return false;
    }
  }
  return true;
}

// A used array's mounts cannot change halfway: every earlier frame would be re-read with them.
void require_same_mounts(const detail::Fields& f, const SonarDevice& s,
                         const std::vector<mapper::SonarMount>& here, const char* interface) {
  if (f.line() != s.geometry_line && !same_mounts(here, s.mounts)) {
    f.fail_line("the geometry of " + name_of(device_of(f), interface) +
                " differs from the one at line " + std::to_string(s.geometry_line) +
                ": an array's mounts cannot change within a log");
  }
}

// Pass 1 of a ranger line: its ranges' counts, its first geometry and config.
void note_ranger(const detail::Fields& f, SonarDevice& r, long type, long subtype) {
  std::optional<std::vector<mapper::SonarMount>> geometry;
  if (is_ranger_ranges(type, subtype)) {
    detail::RangerRanges ranges = detail::ranger_ranges(f, subtype, false);
    r.has_ranges = true;
    if (r.ranges_line == 0) r.ranges_line = f.line();
    r.most_ranges = std::max(r.most_ranges, ranges.count);
    geometry = std::move(ranges.geometry);
  } else if (is_ranger_geometry(type, subtype)) {
    geometry = ranger_geometry_reply(f);
  } else if (type == detail::kPlayerRespAck && subtype == detail::kRangerReqGetConfig) {
    const detail::RangerConfig config = detail::ranger_config(f);
    if (!r.config) {
      r.config = config;
      r.config_line = f.line();
    }
  }
  if (geometry && r.geometry_line == 0) {
    r.mounts = std::move(*geometry);
    r.geometry_line = f.line();
  }
}

// Pass 1: the devices of the file.
struct Devices {
  std::set<Device> positions;  // position2d devices with state lines
  std::map<Device, SonarDevice> sonars;
  std::map<Device, SonarDevice> rangers;
  std::optional<Device> odometry;
  // The robot read (host, port): the odometry's, else that of the first device with readings.
  std::optional<std::pair<std::string, long>> robot;
  std::string sonar_read;  // "sonar:N", the robot's first `sonar` read; empty: none
  std::optional<detail::RangerConfig> config;  // the first used ranger's filled config
  std::size_t config_line = 0;
};

Devices list_devices(const std::filesystem::path& path) {
  std::ifstream in = detail::open_log(path);
  Devices d;
  std::string text;
  std::size_t line_no = 0;
  while (detail::read_bounded_line(in, text, path, line_no + 1, LogLimits{})) {
    ++line_no;
    auto tokens = detail::tokens_of(text);
    if (tokens.empty()) continue;
    const bool comment = tokens[0][0] == '#';
    detail::Fields f(path, line_no, std::move(tokens));
    if (!read_header(f, comment)) continue;
    const std::string& iface = f.at(3);
    if (iface != "position2d" && iface != "sonar" && iface != "ranger") continue;
    const Device dev = device_of(f);
    const long type = f.integer(5, "message type", 0, 255);
    const long subtype = f.integer(6, "message subtype", 0, 255);
    if (iface == "position2d") {
      if (type == 1 && subtype == 1) d.positions.insert(dev);
    } else if (iface == "ranger") {
      note_ranger(f, d.rangers[dev], type, subtype);
    } else {
      SonarDevice& s = d.sonars[dev];
      // A ranges line with a count of 0 (`... 001 001 0`) reads nothing: such a device is no
      // sonar read (a ranger beside it is then the ring).
      if (type == 1 && subtype == 1 && f.size() > 8) s.has_ranges = true;
      if (is_geometry(type, subtype) && s.geometry_line == 0) {
        s.mounts = sonar_geometry(f);
        s.geometry_line = line_no;
      }
    }
  }
  // The odometry: the lowest position2d address (drivers that wrap or estimate a pose — vfh,
  // nd, amcl — are usually given a higher index than the base device they require).
  if (!d.positions.empty()) d.odometry = *d.positions.begin();
  // The sonar arrays of that robot with readings, else its sonar-like rangers: a ranger beside
  // a sonar read is taken for the same ring (Player 3's sonartoranger beside p2os's sonar:0),
  // whose echoes would otherwise count twice. With several, those with a geometry (the others
  // cannot be placed), else the lowest alone.
  auto& robot = d.robot;
  if (d.odometry) robot = {std::get<0>(*d.odometry), std::get<1>(*d.odometry)};
  for (const auto* devices : {&d.sonars, &d.rangers}) {
    for (const auto& [dev, s] : *devices) {
      if (s.has_ranges && !robot) robot = {std::get<0>(dev), std::get<1>(dev)};
    }
  }
  const auto of_robot = [&](const Device& dev) {
    return robot && std::get<0>(dev) == robot->first && std::get<1>(dev) == robot->second;
  };
  std::vector<SonarDevice*> used;
  for (auto& [dev, s] : d.sonars) {
    if (s.has_ranges && of_robot(dev)) used.push_back(&s);
    s.name = name_of(dev, "sonar");
  }
  const bool sonar_read = !used.empty();
  for (auto& [dev, r] : d.rangers) {
    if (r.has_ranges && of_robot(dev) && kind_of(r) == RangerKind::kSonar && !sonar_read) {
      used.push_back(&r);
    }
    r.name = name_of(dev, "ranger");
  }
  if (used.size() > 1) {
    std::vector<SonarDevice*> placed;
    for (SonarDevice* s : used) {
      if (s->geometry_line != 0) placed.push_back(s);
    }
    if (placed.empty()) placed.push_back(used.front());
    used = placed;
  }
  if (sonar_read) d.sonar_read = used.front()->name.substr(used.front()->name.find(':') + 1);
  // A ranger without a geometry may be a laser as well as a sonar ring: beside sonar read
  // elsewhere it is skipped; alone it is the log's sonar, which cannot be read.
  for (const auto& [dev, r] : d.rangers) {
    if (!used.empty() || !r.has_ranges || !of_robot(dev) || kind_of(r) != RangerKind::kUnplaced) {
      continue;
    }
    throw LogError(path.string() + ":" + std::to_string(r.ranges_line) + ": " +
                   name_of(dev, "ranger") + " logs ranges (" + std::to_string(r.most_ranges) +
                   " a line at most) but never its geometry (the reply to GET_GEOM, type 4 "
                   "subtype 1, which writelog writes first): without one pose per element it "
                   "cannot be told from a laser, nor its readings placed");
  }
  std::size_t offset = 0;
  for (SonarDevice* s : used) {
    s->used = true;
    s->offset = offset;
    offset += s->mounts.size();
    // Before: imported (a ranger of 256 element poses, two arrays of 200), and the export of
    // the import was a cogmap log its own reader refused ("expected sonars=N (integer 0..255)").
    if (offset > kMaxTransducers) {
      throw LogError(path.string() + ":" + std::to_string(s->geometry_line) + ": the geometry of " +
                     s->name + " has " + std::to_string(s->mounts.size()) + " poses, " +
                     std::to_string(offset) + " sonar transducers in all: cogmap reads at most " +
                     std::to_string(kMaxTransducers) + " (as many as a cogmap log holds)");
    }
    if (!d.config && s->config && s->config->max_range_m > 0.0) {
      d.config = s->config;
      d.config_line = s->config_line;
    }
  }
  return d;
}

// Why the lines of an unused ranger of the robot read are skipped (empty: no ranges).
std::string why_skipped(const SonarDevice& r, const std::string& sonar_read) {
  if (!r.has_ranges) return "";
  switch (kind_of(r)) {
    case RangerKind::kLaser:
      return std::string(r.mounts.empty() ? "no element pose" : "one element pose") + ", up to " +
             std::to_string(r.most_ranges) + " ranges a line: a laser, not a sonar ring";
    case RangerKind::kUnplaced:
      return "no geometry logged";
    case RangerKind::kSonar:
      if (!sonar_read.empty()) {
        return "the robot's " + sonar_read +
               " is read; a ranger beside it is taken for the same ring (Player's sonartoranger)";
      }
      break;
  }
  return "";
}

// Why a line is skipped when its device is another robot's (empty: the robot read's, or no
// robot is read). Fields as written, unvalidated: skipped lines are not checked.
std::string other_robot(const Devices& d, const detail::Fields& f) {
  if (!d.robot) return "";
  const std::string& port = f.at(2);
  long value = -1;
  const auto [end, ec] = std::from_chars(port.data(), port.data() + port.size(), value);
  if (ec != std::errc() || end != port.data() + port.size()) return "";
  const auto& [host, robot] = *d.robot;
  if (f.at(1) == host && value == robot) return "";
  // The host is named when it differs: writelog writes it as a number, as the robot's port.
  return std::string("another robot's (") + (d.odometry ? "the odometry" : "the sonar read") +
         " is " + (f.at(1) == host ? "" : host + ":") + std::to_string(robot) + "'s)";
}

SonarDevice* used_device(std::map<Device, SonarDevice>& devices, const Device& dev) {
  auto it = devices.find(dev);
  return it != devices.end() && it->second.used ? &it->second : nullptr;
}

}  // namespace

ImportedLog import_player_log(const std::filesystem::path& path) {
  Devices devices = list_devices(path);
  ImportedLog log;
  log.geometry = mapper::p2at_geometry();
  std::vector<mapper::SonarMount> mounts;
  for (const auto* arrays : {&devices.sonars, &devices.rangers}) {
    for (const auto& [dev, s] : *arrays) {
      if (s.used) mounts.insert(mounts.end(), s.mounts.begin(), s.mounts.end());
    }
  }
  if (!mounts.empty()) log.geometry.sonars = mounts;  // else the P2-AT's
  if (const auto& c = devices.config) {
    // A ranger's config: its maximum range marks a reading without echo, its field of view is
    // the beam (Stage's describes its first sensor only; the ring's others are alike).
    log.geometry.sonar_max_range_m = c->max_range_m;
    if (c->fov_rad > 0.0) log.geometry.sonar_beam_width_rad = c->fov_rad;
    detail::check_geometry(log.geometry, path.string() + ":" + std::to_string(devices.config_line));
  }

  std::ifstream in = detail::open_log(path);
  std::optional<detail::Stamp> t0;
  mapper::Pose2 odometry;
  bool stall = false;
  bool pending_position = false;  // a position line not yet carried by a frame
  double pending_time_s = 0.0;
  detail::LineTally tally;  // what the log holds, should it hold no sonar readings
  std::string text;
  std::size_t line_no = 0;
  const auto flush_position = [&] {
    if (!pending_position) return;
    mapper::SensorFrame frame;
    frame.time_s = pending_time_s;
    frame.odometry = odometry;
    frame.stall_left = frame.stall_right = stall;
    detail::push_frame(log, std::move(frame), path, line_no);
    pending_position = false;
  };
  // One frame of readings (transducers from `offset` on) with the latest position.
  const auto push_readings = [&](const SonarDevice& s, const std::vector<double>& ranges_m,
                                 double time_s) {
    mapper::SensorFrame frame;
    frame.time_s = time_s;
    frame.odometry = odometry;
    frame.stall_left = frame.stall_right = stall;
    for (std::size_t i = 0; i < ranges_m.size(); ++i) {
      frame.sonar.push_back(
          detail::reading(static_cast<int>(s.offset + i), ranges_m[i], time_s, log.geometry));
    }
    pending_position = false;  // this frame carries the latest position
    detail::push_frame(log, std::move(frame), path, line_no);
  };
  while (detail::read_bounded_line(in, text, path, line_no + 1, LogLimits{})) {
    ++line_no;
    auto tokens = detail::tokens_of(text);
    if (tokens.empty() || tokens[0][0] == '#') continue;
    detail::Fields f(path, line_no, std::move(tokens));
    const std::string& iface = f.at(3);
    const auto skip = [&](const std::string& why) {
      ++log.ignored_lines;  // other interfaces, other devices, other robots, other messages
      tally.skipped(line_device(f), why);
    };
    if (const std::string other = other_robot(devices, f); !other.empty()) {
      skip(other);
      continue;
    }
    if (iface == "sonar" && f.size() == 8 && f.integer(5, "message type", 0, 255) == 1 &&
        f.integer(6, "message subtype", 0, 255) == 1 && f.integer(7, "range count", 0, 255) == 0) {
      skip("no ranges");  // as CARMEN's SONAR lines of 0 ranges
      continue;
    }
    const bool position = iface == "position2d" && device_of(f) == devices.odometry;
    SonarDevice* sonar = iface == "sonar" ? used_device(devices.sonars, device_of(f)) : nullptr;
    SonarDevice* ranger = nullptr;
    if (iface == "ranger") {
      ranger = used_device(devices.rangers, device_of(f));
      if (!ranger) {
        skip(why_skipped(devices.rangers.at(device_of(f)), devices.sonar_read));
        continue;
      }
    }
    if (!position && !sonar && !ranger) {
      skip("");
      continue;
    }
    const long type = f.integer(5, "message type", 0, 255);
    const long subtype = f.integer(6, "message subtype", 0, 255);
    const detail::Stamp ts = f.stamp(0, "time");
    if (!t0) t0 = ts;
    const double time_s = detail::seconds_between(ts, *t0);
    if (position && type == 1 && subtype == 1) {
      // px py pa vx vy va stall
      if (f.size() != 14) f.fail("position2d data px py pa vx vy va stall", f.size());
      flush_position();  // two position lines in a row: the first becomes its own frame
      odometry = {f.number(7, "px"), f.number(8, "py"), mapper::wrap_angle_rad(f.number(9, "pa"))};
      // The velocities are not mapped, but a line of a type that is read is read whole: garbage
      // there means the line is not what it claims to be.
      f.number(10, "vx");
      f.number(11, "vy");
      f.number(12, "va");
      stall = f.integer(13, "stall", 0, 255) != 0;  // a uint8_t; p2os writes 0 or 1
      pending_position = true;
      pending_time_s = time_s;
    } else if (sonar && is_geometry(type, subtype)) {
      require_same_mounts(f, *sonar, sonar_geometry(f), "sonar");
    } else if (sonar && type == 1 && subtype == 1) {
      const long n = f.integer(7, "range count", 0, 255);
      if (f.size() != 8 + static_cast<std::size_t>(n)) f.fail("sonar count range*count", f.size());
      const std::size_t available =
          sonar->geometry_line != 0 ? sonar->mounts.size() : log.geometry.sonars.size();
      if (static_cast<std::size_t>(n) > available) {
        f.fail("at most " + std::to_string(available) + " ranges", 7);
      }
      std::vector<double> ranges_m;
      for (std::size_t i = 8; i < f.size(); ++i) ranges_m.push_back(f.number(i, "range"));
      push_readings(*sonar, ranges_m, time_s);
    } else if (ranger && is_ranger_geometry(type, subtype)) {
      require_same_mounts(f, *ranger, ranger_geometry_reply(f), "ranger");
    } else if (ranger && is_ranger_ranges(type, subtype)) {
      const detail::RangerRanges ranges = detail::ranger_ranges(f, subtype, true);
      if (ranges.geometry) require_same_mounts(f, *ranger, *ranges.geometry, "ranger");
      if (ranges.count > ranger->mounts.size()) {
        f.fail("at most " + std::to_string(ranger->mounts.size()) +
                   " ranges (one per element pose of the geometry at line " +
                   std::to_string(ranger->geometry_line) + ")",
               7);
      }
      push_readings(*ranger, ranges.ranges_m, time_s);
    } else if (!(ranger && type == detail::kPlayerRespAck &&
                 subtype == detail::kRangerReqGetConfig)) {  // configs were read in pass 1
      skip("");  // intensities, geometry of position2d, header-only lines
      continue;
    }
    tally.read(line_device(f));
  }
  flush_position();
  if (tally.empty()) detail::require_frames(log, path, "Player", "position2d or sonar");
  detail::require_sonar_readings(
      log, path, "sonar ranges, or ranges of a ranger with one pose per element", tally);
  return log;
}

}  // namespace cogmap::hw
