#include <gtest/gtest.h>

#include <stdexcept>

#include "cogmap/mapper/graph/asr_graph.h"
#include "cogmap/mapper/graph/asr_store.h"

namespace cogmap::mapper {
namespace {

AsrGraph chain_of_three() {
  AsrGraph g;
  g.add_node({0, {0, 0, 0}, {1, 1}});
  g.add_node({1, {5, 0, 0.1}, {6, 1}});
  g.add_node({2, {10, 0, 0.2}, {11, 1}});
  g.add_edge({0, 1, 1, {5, 0.5}});
  g.add_edge({1, 2, 1, {10, 0.5}});
  return g;
}

TEST(AsrGraph, NodesAndLookup) {
  const AsrGraph g = chain_of_three();
  ASSERT_EQ(g.nodes().size(), 3u);
  EXPECT_EQ(g.nodes()[1].id, 1);
  ASSERT_TRUE(g.node(2).has_value());
  EXPECT_DOUBLE_EQ(g.node(2)->pose.x_m, 10.0);
  EXPECT_FALSE(g.node(7).has_value());
}

TEST(AsrGraph, NeighboursAreUndirectedSortedAndUnique) {
  AsrGraph g = chain_of_three();
  g.add_edge({2, 0, 2, {12, 3}});   // a loop closes back to room 0
  g.add_edge({1, 0, 0, {5, 0.5}});  // the entry of room 1 seen from room 1: same neighbour
  EXPECT_EQ(g.neighbours(0), (std::vector<int>{1, 2}));
  EXPECT_EQ(g.neighbours(1), (std::vector<int>{0, 2}));
  EXPECT_EQ(g.neighbours(2), (std::vector<int>{0, 1}));
  EXPECT_TRUE(g.neighbours(9).empty());
}

TEST(AsrGraph, UpdateNodeReplacesPoseOnlyForKnownIds) {
  AsrGraph g = chain_of_three();
  g.update_node({1, {5, 0.2, -0.05}, {6.1, 1.2}});
  EXPECT_DOUBLE_EQ(g.node(1)->pose.theta_rad, -0.05);
  EXPECT_DOUBLE_EQ(g.node(1)->reference_point_world.x(), 6.1);
  g.update_node({42, {}, {}});
  EXPECT_EQ(g.nodes().size(), 3u);
}

TEST(AsrGraph, AddingAKnownIdOrExitReplaces) {
  AsrGraph g = chain_of_three();
  g.add_node({0, {0.5, 0, 0}, {1, 1}});
  EXPECT_EQ(g.nodes().size(), 3u);
  EXPECT_DOUBLE_EQ(g.node(0)->pose.x_m, 0.5);
  g.add_edge({0, 1, 1, {5.1, 0.4}});
  ASSERT_EQ(g.edges().size(), 2u);
  EXPECT_DOUBLE_EQ(g.edges()[0].exit_world.x(), 5.1);
}

TEST(MemoryAsrStore, SavesReplacesAndListsSorted) {
  MemoryAsrStore store;
  Asr a;
  a.id = 3;
  a.cell_scale_mm = 55;
  store.save(a);
  a.id = 1;
  store.save(a);
  a.cell_scale_mm = 85;
  store.save(a);
  EXPECT_EQ(store.ids(), (std::vector<int>{1, 3}));
  EXPECT_DOUBLE_EQ(store.load(1).cell_scale_mm, 85);
  EXPECT_THROW(store.load(2), std::out_of_range);
}

}  // namespace
}  // namespace cogmap::mapper
