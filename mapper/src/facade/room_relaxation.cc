#include "facade/room_relaxation.h"

#include <algorithm>

#include "cogmap/mapper/localization/localizer.h"
#include "cogmap/mapper/localization/wall_offsets.h"

namespace cogmap::mapper::internal {

void RoomRelaxation::remember(const Asr& asr, std::span<const Polyline> accepted_walls,
                              const Pose2& placement) {
  rooms_.push_back(
      {placed_facing_segments(accepted_walls, asr.path, placement, options_.min_segment_m),
       path_length_m(asr.path)});
  placements_.emplace_back(asr.id, placement);
}

std::vector<std::pair<int, Pose2>> RoomRelaxation::relax(AsrStore& store, AsrGraph& graph,
                                                         MapperStats& stats) const {
  std::vector<std::pair<int, Pose2>> moves;
  const Relaxation r = relax_room_positions(rooms_, options_);
  stats.relaxation_wall_thickness_m = r.wall_thickness_m;
  stats.relaxation_pairs = static_cast<std::size_t>(r.same_side_pairs + r.two_face_pairs);
  for (std::size_t k = 0; k < placements_.size(); ++k) {
    const auto& [id, placement] = placements_[k];
    const Pose2 relaxed = Pose2{r.shifts[k].x(), r.shifts[k].y(), 0.0}.compose(placement);
    Asr asr = store.load(id);
    // What the relaxation changes: the shift against where the room was placed on leaving it
    // (its online translation, if any, is undone or kept as the relaxation decides).
    const Point2 change = relaxed.translation() - asr.pose.translation();
    if (!(change.norm() >= 1e-6)) continue;  // a micrometre: not a move (room 0, the anchor)
    moves.emplace_back(id, relaxed.compose(asr.pose.inverse()));
    asr.pose = relaxed;
    store.save(asr);
    graph.update_node({asr.id, asr.pose, asr.pose.transform(asr.reference_point)});
    if (asr.parent) {
      graph.add_edge({*asr.parent, asr.id, 1, asr.pose.transform(asr.reference_point)});
    }
    ++stats.relaxed_rooms;
    stats.relaxation_abs_m += change.norm();
    stats.relaxation_max_m = std::max(stats.relaxation_max_m, change.norm());
  }
  return moves;
}

}  // namespace cogmap::mapper::internal
