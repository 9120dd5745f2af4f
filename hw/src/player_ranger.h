#pragma once
// Player 3's `ranger` interface as its writelog driver writes it (server/drivers/shell/
// writelog.cc, WriteRanger; docs/robot-driver.md "Importers"): the payloads the Player importer
// reads. Stage 4 and Player 3 drivers log sonar rings (and lasers) through this interface.

#include <cstddef>
#include <optional>
#include <vector>

#include "cogmap/mapper/seam/robot_geometry.h"
#include "import_common.h"

namespace cogmap::hw::detail {

// Message types and the ranger's subtypes (Player 3's player_interfaces.h).
inline constexpr long kPlayerData = 1;       // PLAYER_MSGTYPE_DATA
inline constexpr long kPlayerRespAck = 4;    // PLAYER_MSGTYPE_RESP_ACK: replies writelog logs
inline constexpr long kRangerDataRange = 1;  // PLAYER_RANGER_DATA_RANGE
inline constexpr long kRangerDataRangeStamped = 2;  // PLAYER_RANGER_DATA_RANGESTAMPED
inline constexpr long kRangerReqGetGeom = 1;        // PLAYER_RANGER_REQ_GET_GEOM
inline constexpr long kRangerReqGetConfig = 5;      // PLAYER_RANGER_REQ_GET_CONFIG

/// A player_ranger_geom_t from field `at` on: the device pose and size (px py pz proll ppitch
/// pyaw sw sl sh), `element_poses_count` then (px py pz proll ppitch pyaw) each, and
/// `element_sizes_count` then (sw sl sh) each. Returns one mount per element pose in the robot
/// frame: the element's pose composed onto the device's (Stage gives its sensors' poses relative
/// to the ranger model, which sits at the device pose; drivers that give robot-relative element
/// poses log a zero device pose). Heights, roll and pitch are dropped. `end` is set to the field
/// after the geometry. Throws LogError naming the line and field.
std::vector<mapper::SonarMount> ranger_geometry(const Fields& f, std::size_t at, std::size_t& end);

/// The parts of a player_ranger_config_t (`min_angle max_angle angular_res min_range max_range
/// range_res frequency`, the reply to GET_CONFIG) that a sonar ring's geometry takes.
struct RangerConfig {
  double fov_rad = 0.0;      ///< max_angle - min_angle: the beam of a one-range element
  double max_range_m = 0.0;  ///< 0 from drivers that fill no config (sonartoranger)
};
/// A type 4 subtype 5 line: exactly seven numbers.
RangerConfig ranger_config(const Fields& f);

/// A ranges line: subtype 1 `count range*count`, or subtype 2 `count range*count have_geom
/// [geometry] [config]`, whose config writelog writes without the have_config flag its readlog
/// expects (seven numbers or none after the geometry; with the flag, one or eight).
struct RangerRanges {
  std::size_t count = 0;
  std::vector<double> ranges_m;                             ///< empty unless asked for
  std::optional<std::vector<mapper::SonarMount>> geometry;  ///< subtype 2 with have_geom
};
/// Reads the layout (and the ranges themselves when `with_ranges`). Throws LogError naming the
/// line and field.
RangerRanges ranger_ranges(const Fields& f, long subtype, bool with_ranges);

}  // namespace cogmap::hw::detail
