#pragma once
/// Rooms as nodes, exits as edges (thesis §2.4.1, Fig. 4.1b). Only the summary of each room
/// lives here; the room bodies live in an AsrStore.

#include <optional>
#include <vector>

#include "cogmap/mapper/seam/pose2.h"

namespace cogmap::mapper {

struct AsrNode {
  int id = -1;
  Pose2 pose;  ///< local -> world, corrected
  Point2 reference_point_world{0.0, 0.0};
};

struct AsrEdge {
  int from = -1;
  int to = -1;
  int exit_index = -1;  ///< index into the `from` room's exits
  Point2 exit_world{0.0, 0.0};
};

class AsrGraph {
 public:
  void add_node(const AsrNode& node);
  void update_node(const AsrNode& node);
  void add_edge(const AsrEdge& edge);
  const std::vector<AsrNode>& nodes() const { return nodes_; }
  const std::vector<AsrEdge>& edges() const { return edges_; }
  std::optional<AsrNode> node(int id) const;
  /// Ids of the rooms joined to `id` by an edge.
  std::vector<int> neighbours(int id) const;

 private:
  std::vector<AsrNode> nodes_;
  std::vector<AsrEdge> edges_;
};

}  // namespace cogmap::mapper
