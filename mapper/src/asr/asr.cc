#include "cogmap/mapper/asr/asr.h"

namespace cogmap::mapper {

std::size_t Asr::vertex_count() const {
  std::size_t n = 0;
  for (const Polyline& line : walls) n += line.size();
  return n;
}

std::vector<Segment> Asr::world_segments(bool corrected) const {
  const Pose2& to_world = corrected ? pose : odometry_pose;
  std::vector<Segment> out;
  for (const Polyline& line : walls) {
    for (std::size_t i = 1; i < line.size(); ++i) {
      out.push_back({to_world.transform(line[i - 1]), to_world.transform(line[i])});
    }
  }
  return out;
}

}  // namespace cogmap::mapper
