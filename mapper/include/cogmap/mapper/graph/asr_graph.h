#pragma once
/// Rooms as nodes, exits as edges (thesis §2.4.1, Fig. 4.1b). Only the summary of each room
/// lives here; the room bodies live in an AsrStore.

#include <optional>
#include <vector>

#include "cogmap/mapper/seam/pose2.h"

namespace cogmap::mapper {

/// One room's summary.
struct AsrNode {
  int id = -1;                             ///< the ASR's id
  Pose2 pose;                              ///< local -> world, corrected
  Point2 reference_point_world{0.0, 0.0};  ///< the room's pivot, world frame, metres
};

/// An exit joining two rooms (undirected for neighbours(); `from` owns the exit).
struct AsrEdge {
  int from = -1;                ///< room whose exits[exit_index] this is
  int to = -1;                  ///< room on the other side
  int exit_index = -1;          ///< index into the `from` room's exits
  Point2 exit_world{0.0, 0.0};  ///< exit centre, world frame, metres
};

/// The graph of rooms, in insertion order.
class AsrGraph {
 public:
  /// Adds a node; a node with the same id is replaced (one node per room).
  void add_node(const AsrNode& node);
  /// Replaces the node with `node.id` (after a localisation correction); unknown ids are ignored.
  void update_node(const AsrNode& node);
  /// Adds an edge; the same (from, to, exit_index) again replaces the earlier one.
  void add_edge(const AsrEdge& edge);
  /// All nodes in insertion order.
  const std::vector<AsrNode>& nodes() const { return nodes_; }
  /// All edges in insertion order.
  const std::vector<AsrEdge>& edges() const { return edges_; }
  /// The node with this id, if any.
  std::optional<AsrNode> node(int id) const;
  /// Ids of the rooms joined to `id` by an edge in either direction, ascending, no duplicates.
  std::vector<int> neighbours(int id) const;

 private:
  std::vector<AsrNode> nodes_;
  std::vector<AsrEdge> edges_;
};

}  // namespace cogmap::mapper
