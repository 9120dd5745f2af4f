// Player 2.x/3.x writelog importer (docs/robot-driver.md "Importers"). Lines as writelog.cc
// writes them: "%014.3f %u %u %s %02u %03u %03u " (time host robot interface index type subtype),
// then the payload. Two passes: the first lists the devices (which position2d is the odometry,
// which sonar arrays and their mounts), the second makes the frames.
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "cogmap/hw/log_import.h"
#include "import_common.h"
#include "log_checks.h"

namespace cogmap::hw {
namespace {

// A Player device address (host, robot = port, index) of one interface. writelog writes the
// host as a number; it is kept as written.
using Device = std::tuple<std::string, long, long>;

std::string name_of(const Device& d, const char* interface) {
  return std::to_string(std::get<1>(d)) + ":" + interface + ":" + std::to_string(std::get<2>(d));
}

struct SonarDevice {
  std::vector<mapper::SonarMount> mounts;  // from its first geometry line
  std::size_t geometry_line = 0;           // 0: none
  bool has_ranges = false;
  bool used = false;
  std::size_t offset = 0;  // its first transducer's index in the joined geometry
};

constexpr const char* kPlayer2 = "cogmap reads the files of Player 2.x and 3.x's writelog";

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

// Pass 1: the devices of the file.
struct Devices {
  std::set<Device> positions;  // position2d devices with state lines
  std::map<Device, SonarDevice> sonars;
  std::optional<Device> odometry;
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
    if (f.at(3) != "position2d" && f.at(3) != "sonar") continue;
    const Device dev = device_of(f);
    const long type = f.integer(5, "message type", 0, 255);
    const long subtype = f.integer(6, "message subtype", 0, 255);
    if (f.at(3) == "position2d") {
      if (type == 1 && subtype == 1) d.positions.insert(dev);
      continue;
    }
    SonarDevice& s = d.sonars[dev];
    if (type == 1 && subtype == 1) s.has_ranges = true;
    if (is_geometry(type, subtype) && s.geometry_line == 0) {
      s.mounts = sonar_geometry(f);
      s.geometry_line = line_no;
    }
  }
  // The odometry: the lowest position2d address (drivers that wrap or estimate a pose — vfh,
  // nd, amcl — are usually given a higher index than the base device they require).
  if (!d.positions.empty()) d.odometry = *d.positions.begin();
  // The sonar arrays of that robot with readings; with several, those with a geometry (the
  // others cannot be placed), else the lowest alone.
  std::vector<SonarDevice*> used;
  std::optional<std::pair<std::string, long>> robot;
  if (d.odometry) robot = {std::get<0>(*d.odometry), std::get<1>(*d.odometry)};
  for (auto& [dev, s] : d.sonars) {
    if (!s.has_ranges) continue;
    if (!robot) robot = {std::get<0>(dev), std::get<1>(dev)};
    if (std::get<0>(dev) == robot->first && std::get<1>(dev) == robot->second) used.push_back(&s);
  }
  if (used.size() > 1) {
    std::vector<SonarDevice*> placed;
    for (SonarDevice* s : used) {
      if (s->geometry_line != 0) placed.push_back(s);
    }
    if (placed.empty()) placed.push_back(used.front());
    used = placed;
  }
  std::size_t offset = 0;
  for (SonarDevice* s : used) {
    s->used = true;
    s->offset = offset;
    offset += s->mounts.size();
  }
  return d;
}

}  // namespace

ImportedLog import_player_log(const std::filesystem::path& path) {
  Devices devices = list_devices(path);
  ImportedLog log;
  log.geometry = mapper::p2at_geometry();
  std::vector<mapper::SonarMount> mounts;
  bool any_used = false;
  for (const auto& [dev, s] : devices.sonars) {
    any_used = any_used || s.used;
    if (s.used) mounts.insert(mounts.end(), s.mounts.begin(), s.mounts.end());
  }
  if (!any_used) {  // no array with readings: the geometry of the robot's first array
    for (const auto& [dev, s] : devices.sonars) {
      if (s.geometry_line != 0 &&
          (!devices.odometry || std::get<1>(dev) == std::get<1>(*devices.odometry))) {
        mounts = s.mounts;
        break;
      }
    }
  }
  if (!mounts.empty()) log.geometry.sonars = mounts;  // else the P2-AT's

  std::ifstream in = detail::open_log(path);
  std::optional<detail::Stamp> t0;
  mapper::Pose2 odometry;
  bool stall = false;
  bool pending_position = false;  // a position line not yet carried by a frame
  double pending_time_s = 0.0;
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
  while (detail::read_bounded_line(in, text, path, line_no + 1, LogLimits{})) {
    ++line_no;
    auto tokens = detail::tokens_of(text);
    if (tokens.empty() || tokens[0][0] == '#') continue;
    detail::Fields f(path, line_no, std::move(tokens));
    const std::string& iface = f.at(3);
    const bool position = iface == "position2d";
    SonarDevice* sonar = nullptr;
    if (iface == "sonar") {
      auto it = devices.sonars.find(device_of(f));
      if (it != devices.sonars.end() && it->second.used) sonar = &it->second;
    }
    if (!(position && device_of(f) == devices.odometry) && !sonar) {
      ++log.ignored_lines;  // other interfaces, other devices, other robots
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
      stall = f.integer(13, "stall", 0, 255) != 0;  // a uint8_t; p2os writes 0 or 1
      pending_position = true;
      pending_time_s = time_s;
    } else if (sonar && is_geometry(type, subtype)) {
      const auto mounts_here = sonar_geometry(f);
      if (line_no != sonar->geometry_line && !same_mounts(mounts_here, sonar->mounts)) {
        const Device dev = device_of(f);
        f.fail_line("the geometry of " + name_of(dev, "sonar") + " differs from the one at line " +
                    std::to_string(sonar->geometry_line) +
                    ": an array's mounts cannot change within a log");
      }
    } else if (sonar && type == 1 && subtype == 1) {
      const long n = f.integer(7, "range count", 0, 255);
      if (f.size() != 8 + static_cast<std::size_t>(n)) f.fail("sonar count range*count", f.size());
      const std::size_t available =
          sonar->geometry_line != 0 ? sonar->mounts.size() : log.geometry.sonars.size();
      if (static_cast<std::size_t>(n) > available) {
        f.fail("at most " + std::to_string(available) + " ranges", 7);
      }
      mapper::SensorFrame frame;
      frame.time_s = time_s;
      frame.odometry = odometry;
      frame.stall_left = frame.stall_right = stall;
      for (long i = 0; i < n; ++i) {
        frame.sonar.push_back(detail::reading(static_cast<int>(sonar->offset) + static_cast<int>(i),
                                              f.number(8 + static_cast<std::size_t>(i), "range"),
                                              time_s, log.geometry));
      }
      pending_position = false;  // this frame carries the latest position
      detail::push_frame(log, std::move(frame), path, line_no);
    } else {
      ++log.ignored_lines;
    }
  }
  flush_position();
  detail::require_frames(log, path, "Player", "position2d or sonar");
  return log;
}

}  // namespace cogmap::hw
