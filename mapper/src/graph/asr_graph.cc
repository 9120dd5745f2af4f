// The room graph of thesis §2.4.1: nodes are ASRs, edges the exits that join them.

#include "cogmap/mapper/graph/asr_graph.h"

#include <algorithm>

namespace cogmap::mapper {

void AsrGraph::add_node(const AsrNode& node) {
  // Adding a known id replaces it: the graph has one node per room, whatever the caller does.
  const auto it =
      std::find_if(nodes_.begin(), nodes_.end(), [&](const AsrNode& n) { return n.id == node.id; });
  if (it != nodes_.end()) {
    *it = node;
  } else {
    nodes_.push_back(node);
  }
}

void AsrGraph::update_node(const AsrNode& node) {
  const auto it =
      std::find_if(nodes_.begin(), nodes_.end(), [&](const AsrNode& n) { return n.id == node.id; });
  if (it != nodes_.end()) *it = node;
}

void AsrGraph::add_edge(const AsrEdge& edge) {
  // The same exit of the same room reported twice is one edge: keep the latest position.
  const auto it = std::find_if(edges_.begin(), edges_.end(), [&](const AsrEdge& e) {
    return e.from == edge.from && e.to == edge.to && e.exit_index == edge.exit_index;
  });
  if (it != edges_.end()) {
    *it = edge;
  } else {
    edges_.push_back(edge);
  }
}

std::optional<AsrNode> AsrGraph::node(int id) const {
  const auto it =
      std::find_if(nodes_.begin(), nodes_.end(), [&](const AsrNode& n) { return n.id == id; });
  if (it == nodes_.end()) return std::nullopt;
  return *it;
}

std::vector<int> AsrGraph::neighbours(int id) const {
  std::vector<int> out;
  for (const AsrEdge& e : edges_) {
    if (e.from == id) out.push_back(e.to);
    if (e.to == id) out.push_back(e.from);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  out.erase(std::remove(out.begin(), out.end(), id), out.end());
  return out;
}

}  // namespace cogmap::mapper
