// The split of a step's work between threads (dynamics/work_split.hpp): every node belongs to
// exactly one member, in contiguous ranges; every member evaluates exactly the springs with a
// node of its own, in spring order; few springs are shared on a mesh numbered by rows.
#include "dynamics/work_split.hpp"

#include <gtest/gtest.h>

#include <set>

#include "model/model.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

Model lattice(int cells) {
  return build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
objects:
  - name: lattice
    mesh: {{grid: {{width: 1, height: 1, columns: {0}, rows: {0}, diagonals: one}}}}
    material: {{density: 1200, youngs_modulus: 2.0e7, radius: 0.001}}
    torsion: true
)",
                                                       cells)));
}

// The springs of each member's runs, and the members whose runs hold each spring.
void expect_members_hold_the_springs_of_their_nodes(const WorkSplit& split,
                                                    const std::vector<Index>& spring_nodes,
                                                    int per_spring,
                                                    std::vector<SpringRun> MemberShare::*runs) {
  const auto count = static_cast<Index>(spring_nodes.size() / static_cast<std::size_t>(per_spring));
  for (const MemberShare& share : split.shares) {
    std::vector<Index> held;
    for (const SpringRun& run : share.*runs) {
      EXPECT_GT(run.count, 0);
      for (Index s = run.first; s < run.first + run.count; ++s) {
        held.push_back(s);
      }
    }
    EXPECT_TRUE(std::is_sorted(held.begin(), held.end()));
    EXPECT_EQ(std::set<Index>(held.begin(), held.end()).size(), held.size());
    std::vector<Index> expected;
    for (Index s = 0; s < count; ++s) {
      bool own = false;
      for (int j = 0; j < per_spring; ++j) {
        own = own || share.owns(spring_nodes[static_cast<std::size_t>(per_spring * s + j)]);
      }
      if (own) {
        expected.push_back(s);
      }
    }
    EXPECT_EQ(held, expected);
  }
}

TEST(WorkSplit, EveryNodeHasOneOwnerAndEveryMemberItsNodesSprings) {
  const Model model = lattice(30);
  for (const int members : {1, 2, 3, 5}) {
    const WorkSplit split = split_work(model, members);
    ASSERT_EQ(split.shares.size(), static_cast<std::size_t>(members));
    Index next = 0;
    for (const MemberShare& share : split.shares) {
      EXPECT_EQ(share.first_node, next);
      EXPECT_TRUE(share.first_node % kNodeGrain == 0 || share.first_node == model.node_count());
      next = share.end_node;
    }
    EXPECT_EQ(next, model.node_count());
    expect_members_hold_the_springs_of_their_nodes(split, model.bar_nodes, 2, &MemberShare::bars);
    expect_members_hold_the_springs_of_their_nodes(split, model.bend_nodes, 3, &MemberShare::bends);
    expect_members_hold_the_springs_of_their_nodes(split, model.torsion_nodes, 4,
                                                   &MemberShare::torsions);
    if (members == 1) {
      EXPECT_EQ(split.shared_springs, 0);
    }
  }
}

// A grid is numbered by rows, so a member's nodes are a band of rows, its springs long runs, and
// only the springs across a band's edge are shared: a few rows' worth.
TEST(WorkSplit, AMeshNumberedByRowsSharesOnlyTheSpringsAtTheBandEdges) {
  const Model model = lattice(60);
  const WorkSplit split = split_work(model, 2);
  const Index springs = model.bar_count() + model.bend_count() + model.torsion_count();
  // One cut across 61 nodes a row: the bars, bending and torsion springs that reach across it,
  // at most a few rows' worth of them (each kind has about 3 springs a node).
  EXPECT_GT(split.shared_springs, 0);
  EXPECT_LT(split.shared_springs, 3 * 3 * 61 * 3);
  EXPECT_LT(split.shared_springs, springs / 20);
  // Long runs: on average at least half a block of 64 springs, so the loops stay as fast as on one
  // thread.
  for (const MemberShare& share : split.shares) {
    for (const std::vector<SpringRun>* runs : {&share.bars, &share.bends, &share.torsions}) {
      Index held = 0;
      for (const SpringRun& run : *runs) {
        held += run.count;
      }
      EXPECT_GE(held, 32 * static_cast<Index>(runs->size()));
    }
  }
}

}  // namespace
}  // namespace dinam
