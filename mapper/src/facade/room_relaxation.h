#pragma once
/// The facade's side of the end-of-run relaxation (docs/algorithms.md, "Relaxing the rooms'
/// positions at the end of a run"): what each finished room contributes, kept in RAM as a few
/// wall pieces a room, and the re-placing of the rooms in the store and the graph at the end.

#include <span>
#include <utility>
#include <vector>

#include "cogmap/mapper/asr/asr.h"
#include "cogmap/mapper/graph/asr_graph.h"
#include "cogmap/mapper/graph/asr_store.h"
#include "cogmap/mapper/localization/map_relaxation.h"
#include "cogmap/mapper/mapper.h"

namespace cogmap::mapper::internal {

class RoomRelaxation {
 public:
  explicit RoomRelaxation(const RelaxationOptions& options) : options_(options) {}

  /// Records a finished room as `placement` (local -> world, the estimate's own continuity)
  /// places it: its `accepted_walls` (local frame) facing where its path saw them from.
  void remember(const Asr& asr, std::span<const Polyline> accepted_walls, const Pose2& placement);

  std::size_t rooms() const { return rooms_.size(); }

  /// Relaxes the remembered rooms together and re-saves each room that moved (its asr.pose,
  /// its graph node and the edge from its parent); the relaxation's figures go to `stats`.
  /// Returns, per moved room, the world-frame move from where it stood to where it stands now.
  std::vector<std::pair<int, Pose2>> relax(AsrStore& store, AsrGraph& graph,
                                           MapperStats& stats) const;

 private:
  RelaxationOptions options_;
  std::vector<RelaxationRoom> rooms_;
  std::vector<std::pair<int, Pose2>> placements_;  ///< room id, placement
};

}  // namespace cogmap::mapper::internal
