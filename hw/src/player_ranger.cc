#include "player_ranger.h"

#include <algorithm>
#include <string>

#include "cogmap/mapper/seam/pose2.h"

namespace cogmap::hw::detail {
namespace {

// Counts beyond any ranger a mobile robot carries (a 0.25° laser has 1081 ranges), so that a
// corrupt count fails on its own field rather than as a line too short.
constexpr long kMaxCount = 65535;

}  // namespace

std::vector<mapper::SonarMount> ranger_geometry(const Fields& f, std::size_t at, std::size_t& end) {
  // Six numbers of a pose (px py pz proll ppitch pyaw) from field k: the planar part.
  const auto pose_at = [&f](std::size_t k, const char* what) {
    double v[6];
    for (std::size_t j = 0; j < 6; ++j) v[j] = f.number(k + j, what);
    return mapper::Pose2{v[0], v[1], v[5]};
  };
  const char* const device = "ranger device pose and size (px py pz proll ppitch pyaw sw sl sh)";
  const mapper::Pose2 device_pose = pose_at(at, device);
  for (std::size_t i = 6; i < 9; ++i) (void)f.number(at + i, device);
  const auto poses =
      static_cast<std::size_t>(f.integer(at + 9, "ranger element_poses_count", 0, kMaxCount));
  const std::size_t sizes_at = at + 10 + 6 * poses;
  if (f.size() <= sizes_at) {
    f.fail("ranger geometry: " + std::to_string(poses) +
               " element poses (px py pz proll ppitch pyaw) then element_sizes_count",
           f.size());
  }
  std::vector<mapper::SonarMount> mounts;
  for (std::size_t i = 0; i < poses; ++i) {
    const mapper::Pose2 mount = device_pose.compose(
        pose_at(at + 10 + 6 * i, "ranger element pose (px py pz proll ppitch pyaw)"));
    mounts.push_back({mount.x_m, mount.y_m, mount.theta_rad});
  }
  const auto sizes =
      static_cast<std::size_t>(f.integer(sizes_at, "ranger element_sizes_count", 0, kMaxCount));
  end = sizes_at + 1 + 3 * sizes;
  for (std::size_t i = sizes_at + 1; i < end; ++i) {
    (void)f.number(i, "ranger element size (sw sl sh)");
  }
  return mounts;
}

RangerConfig ranger_config(const Fields& f) {
  const char* const what =
      "ranger config min_angle max_angle angular_res min_range max_range range_res frequency";
  if (f.size() != 14) f.fail(what, f.size() < 14 ? f.size() : 14);
  for (std::size_t i = 7; i < 14; ++i) (void)f.number(i, what);
  return {f.number(8, what) - f.number(7, what), f.number(11, what)};
}

RangerRanges ranger_ranges(const Fields& f, long subtype, bool with_ranges) {
  RangerRanges r;
  r.count = static_cast<std::size_t>(f.integer(7, "ranges_count", 0, kMaxCount));
  const std::size_t after = 8 + r.count;
  if (subtype == kRangerDataRange && f.size() != after) {
    f.fail("ranger ranges_count range*ranges_count", f.size() < after ? f.size() : after);
  }
  if (subtype == kRangerDataRangeStamped && f.size() <= after) {
    f.fail("ranger ranges_count range*ranges_count have_geom", f.size());
  }
  if (with_ranges) {
    for (std::size_t i = 8; i < after; ++i) r.ranges_m.push_back(f.number(i, "range"));
  }
  if (subtype != kRangerDataRangeStamped) return r;
  std::size_t end = after + 1;
  if (f.integer(after, "have_geom", 0, 255) != 0) r.geometry = ranger_geometry(f, after + 1, end);
  // ranger_geometry read every field before `end`. writelog writes the config's seven numbers
  // without its have_config flag; the flag is accepted too (readlog reads one): nothing, the
  // flag 0, seven numbers, or the flag and seven.
  const std::size_t rest = f.size() - end;
  if (rest != 0 && rest != 1 && rest != 7 && rest != 8) {
    f.fail("nothing or the ranger config's 7 numbers after the geometry",
           std::min(end + 8, f.size()));
  }
  if (rest == 1) (void)f.integer(end, "have_config (0: no config follows)", 0, 0);
  for (std::size_t i = end; i < f.size(); ++i) (void)f.number(i, "ranger config");
  return r;
}

}  // namespace cogmap::hw::detail
