#include <algorithm>
#include <limits>
#include <unordered_map>

#include "core/error.hpp"
#include "model/spring_builders.hpp"

namespace dinam {
namespace {

// The bar between two nodes, by a hash of the ordered pair.
class BarLookup {
 public:
  explicit BarLookup(const Model& model) {
    bars_.reserve(static_cast<std::size_t>(model.bar_count()));
    for (Index b = 0; b < model.bar_count(); ++b) {
      bars_.emplace(key(model.bar_nodes[2 * b], model.bar_nodes[2 * b + 1]), b);
    }
  }
  Index find(Index n0, Index n1) const {
    const auto found = bars_.find(key(n0, n1));
    return found == bars_.end() ? -1 : found->second;
  }

 private:
  static std::uint64_t key(Index a, Index b) {
    const auto low = static_cast<std::uint64_t>(std::min(a, b));
    const auto high = static_cast<std::uint64_t>(std::max(a, b));
    return (high << 32) | low;
  }
  std::unordered_map<std::uint64_t, Index> bars_;
};

// The bars of the straight run from node i to node j (a torsion spring's axis that is no bar):
// from i, each step takes the bar that heads most nearly towards j.
std::vector<Index> run_bars(const Model& model, const NodeAdjacency& adjacency, Index offset,
                            Index i, Index j) {
  std::vector<Index> bars;
  Index node = i;
  while (node != j && bars.size() <= static_cast<std::size_t>(adjacency.node_count())) {
    Index best_bar = -1;
    Index best_node = -1;
    double best = -std::numeric_limits<double>::infinity();
    const Vec3 towards = (model.node_initial_x[j] - model.node_initial_x[node]).normalized();
    for (const auto& [other, bar] : adjacency[node - offset]) {
      const double along =
          (model.node_initial_x[other] - model.node_initial_x[node]).normalized().dot(towards);
      if (along > best) {
        best = along;
        best_bar = bar;
        best_node = other;
      }
    }
    bars.push_back(best_bar);
    node = best_node;
  }
  return bars;
}

// Inverts (spring → bars) lists into bar → entries, as offsets and ids.
void invert(const std::vector<std::pair<Index, Index>>& bar_entry, Index bar_count,
            std::vector<Index>& offsets, std::vector<Index>& entries) {
  offsets.assign(static_cast<std::size_t>(bar_count) + 1, 0);
  for (const auto& [bar, entry] : bar_entry) {
    ++offsets[static_cast<std::size_t>(bar) + 1];
  }
  for (std::size_t b = 0; b < static_cast<std::size_t>(bar_count); ++b) {
    offsets[b + 1] += offsets[b];
  }
  entries.resize(bar_entry.size());
  std::vector<Index> next(offsets.begin(), offsets.end() - 1);
  for (const auto& [bar, entry] : bar_entry) {  // in spring order: deterministic
    entries[static_cast<std::size_t>(next[static_cast<std::size_t>(bar)]++)] = entry;
  }
}

}  // namespace

void add_tearing(const std::vector<BarMaterials>& materials, Model& model) {
  bool any = false;
  for (const BarMaterials& object : materials) {
    for (const MaterialDesc* material : object) {
      any = any || material->can_break();
    }
  }
  if (!any) {
    return;
  }
  model.bar_breaking_strain.assign(model.bar_count(), kNoYield);
  model.bar_breaking_force.assign(model.bar_count(), kNoYield);
  for (std::size_t o = 0; o < materials.size(); ++o) {
    const ModelObject& object = model.objects[o];
    for (Index b = 0; b < object.bar_count; ++b) {
      const MaterialDesc& material = *materials[o][static_cast<std::size_t>(b)];
      model.bar_breaking_strain[object.first_bar + b] = material.breaking_strain;
      model.bar_breaking_force[object.first_bar + b] = material.breaking_force;
    }
  }

  // Every spring stands on the bars whose angles or twist it measures.
  const BarLookup lookup(model);
  std::vector<std::pair<Index, Index>> bar_spring;  // (bar, 3 × spring + kind)
  for (Index s = 0; s < model.bend_count(); ++s) {
    const Index* n = &model.bend_nodes[3 * s];
    for (const Index bar : {lookup.find(n[0], n[1]), lookup.find(n[1], n[2])}) {
      bar_spring.emplace_back(bar, 3 * s + kTornBend);
    }
  }
  std::vector<NodeAdjacency> adjacency;
  for (const ModelObject& object : model.objects) {
    adjacency.push_back(node_adjacency(model, object));
  }
  for (Index s = 0; s < model.torsion_count(); ++s) {
    const Index* n = &model.torsion_nodes[4 * s];
    bar_spring.emplace_back(lookup.find(n[0], n[1]), 3 * s + kTornTorsion);
    bar_spring.emplace_back(lookup.find(n[2], n[3]), 3 * s + kTornTorsion);
    if (const Index axis = lookup.find(n[1], n[2]); axis >= 0) {
      bar_spring.emplace_back(axis, 3 * s + kTornTorsion);
    } else {  // a straight run's spring
      const Index object = model.node_object[n[1]];
      for (const Index bar : run_bars(model, adjacency[static_cast<std::size_t>(object)],
                                      model.objects[object].first_node, n[1], n[2])) {
        bar_spring.emplace_back(bar, 3 * s + kTornTorsion);
      }
    }
  }
  for (Index s = 0; s < model.clamp_count(); ++s) {
    bar_spring.emplace_back(lookup.find(model.clamp_nodes[2 * s], model.clamp_nodes[2 * s + 1]),
                            3 * s + kTornClamp);
  }
  for (const auto& [bar, entry] : bar_spring) {
    DINAM_CHECK(bar >= 0);
  }
  invert(bar_spring, model.bar_count(), model.bar_spring_offsets, model.bar_springs);

  std::vector<std::pair<Index, Index>> bar_face;
  for (Index f = 0; f < model.face_count(); ++f) {
    const Index begin = model.face_offsets[f];
    const Index end = model.face_offsets[f + 1];
    for (Index k = begin; k < end; ++k) {
      const Index bar =
          lookup.find(model.face_nodes[k], model.face_nodes[k + 1 < end ? k + 1 : begin]);
      if (bar >= 0) {
        bar_face.emplace_back(bar, f);
      }
    }
  }
  invert(bar_face, model.bar_count(), model.bar_face_offsets, model.bar_faces);
}

}  // namespace dinam
