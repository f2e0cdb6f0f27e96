#include "dynamics/work_split.hpp"

#include <algorithm>

#include "model/model.hpp"

namespace dinam {
namespace {

// Appends spring s to the runs, extending the last run when s follows it.
void append(std::vector<SpringRun>& runs, Index s) {
  if (!runs.empty() && runs.back().first + runs.back().count == s) {
    ++runs.back().count;
  } else {
    runs.push_back({s, 1});
  }
}

// Gives each member the springs with a node it owns, in spring order; counts the springs that
// more than one member evaluates.
void share_springs(const std::vector<Index>& spring_nodes, int nodes_per_spring,
                   std::vector<SpringRun> MemberShare::*runs, WorkSplit& split) {
  const auto per_spring = static_cast<std::size_t>(nodes_per_spring);
  const auto count = static_cast<Index>(spring_nodes.size() / per_spring);
  // The member that owns a node: the last whose range starts at or before it.
  std::vector<Index> starts;
  for (const MemberShare& share : split.shares) {
    starts.push_back(share.first_node);
  }
  auto owner = [&](Index node) {
    return static_cast<std::size_t>(std::upper_bound(starts.begin(), starts.end(), node) -
                                    starts.begin() - 1);
  };
  for (Index s = 0; s < count; ++s) {
    const Index* nodes = &spring_nodes[per_spring * static_cast<std::size_t>(s)];
    std::size_t members[4];
    int sharing = 0;
    for (int j = 0; j < nodes_per_spring; ++j) {
      const std::size_t member = owner(nodes[j]);
      if (std::find(members, members + sharing, member) == members + sharing) {
        members[sharing++] = member;
      }
    }
    // Each member's runs stay in spring order whatever order the nodes named the members in.
    for (int k = 0; k < sharing; ++k) {
      append(split.shares[members[k]].*runs, s);
    }
    split.shared_springs += sharing > 1 ? 1 : 0;
  }
}

// What a step costs at each grain of nodes, in axial springs' worth: a node's own loops, and each
// spring's cost shared among its nodes (relative costs from bench_force_costs: a bending spring
// about 2.7 axial springs, a torsion spring 4).
std::vector<double> grain_work(const Model& model) {
  const Index n = model.node_count();
  std::vector<double> work(static_cast<std::size_t>((n + kNodeGrain - 1) / kNodeGrain), 0.0);
  for (Index i = 0; i < n; ++i) {
    work[static_cast<std::size_t>(i / kNodeGrain)] += 1.0;
  }
  auto add = [&](const std::vector<Index>& spring_nodes, int per_spring, double cost) {
    for (const Index node : spring_nodes) {
      work[static_cast<std::size_t>(node / kNodeGrain)] += cost / per_spring;
    }
  };
  add(model.bar_nodes, 2, 1.0);
  add(model.bend_nodes, 3, 2.7);
  add(model.torsion_nodes, 4, 4.0);
  return work;
}

}  // namespace

WorkSplit split_work(const Model& model, int members) {
  WorkSplit split;
  split.members = members;
  split.shares.resize(static_cast<std::size_t>(members));
  const Index n = model.node_count();
  // Cut the nodes where the running work passes each member's equal part.
  const std::vector<double> work = grain_work(model);
  double total = 0.0;
  for (const double w : work) {
    total += w;
  }
  Index grain = 0;
  double done = 0.0;
  for (int m = 0; m < members; ++m) {
    MemberShare& share = split.shares[static_cast<std::size_t>(m)];
    share.first_node = std::min(n, grain * kNodeGrain);
    const double until = total * (m + 1) / members;
    while (grain < static_cast<Index>(work.size()) &&
           (m + 1 == members || done + 0.5 * work[static_cast<std::size_t>(grain)] < until)) {
      done += work[static_cast<std::size_t>(grain)];
      ++grain;
    }
    share.end_node = std::min(n, grain * kNodeGrain);
  }
  share_springs(model.bar_nodes, 2, &MemberShare::bars, split);
  share_springs(model.bend_nodes, 3, &MemberShare::bends, split);
  share_springs(model.torsion_nodes, 4, &MemberShare::torsions, split);
  return split;
}

}  // namespace dinam
