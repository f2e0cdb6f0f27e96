#include <cmath>

#include "model/bar_lookup.hpp"
#include "model/frequency_bound.hpp"
#include "model/model_spring_kinds.hpp"
#include "model/spring_builders.hpp"

namespace dinam {

void add_clamps(const BarMaterials& materials, const ModelObject& object,
                const NodeAdjacency& adjacency, Model& model, Index first_bend) {
  const auto clamped = [&](Index node) {
    return node >= object.first_node && node < object.first_node + object.node_count &&
           model.pinned(node);
  };
  // A clamp holds each bar at the node by itself, so springs between bars there would count the
  // same stiffness twice.
  Index kept = first_bend;
  for (Index s = first_bend; s < model.bend_count(); ++s) {
    if (clamped(model.bend_nodes[3 * s + 1])) {
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      model.bend_nodes[3 * kept + k] = model.bend_nodes[3 * s + k];
    }
    model.bend_rest_angle[kept] = model.bend_rest_angle[s];
    model.bend_stiffness[kept] = model.bend_stiffness[s];
    model.bend_yield_moment[kept] = model.bend_yield_moment[s];
    ++kept;
  }
  model.bend_nodes.resize(3 * static_cast<std::size_t>(kept));
  model.bend_rest_angle.resize(kept);
  model.bend_stiffness.resize(kept);
  model.bend_yield_moment.resize(kept);

  for (Index local = 0; local < object.node_count; ++local) {
    const Index c = object.first_node + local;
    if (!model.pinned(c)) {
      continue;
    }
    for (const auto& [a, bar] : adjacency[local]) {
      if (model.pinned(a)) {
        continue;
      }
      model.clamp_nodes.insert(model.clamp_nodes.end(), {c, a});
      model.clamp_ghost_offset.push_back(model.node_initial_x[c] - model.node_initial_x[a]);
      const MaterialDesc& material = *materials[bar - object.first_bar];
      model.clamp_stiffness.push_back(2.0 * material.youngs_modulus * material.area_moment /
                                      model.bar_rest_length[bar]);
      model.clamp_yield_moment.push_back(material.yield_bending_moment);
    }
  }
}

namespace {

// A bending spring whose other two points are held: |∂θ/∂x_a| = 1/L.
void add_clamp_frequency_terms(const Model& model, GershgorinSums& sums) {
  for (Index s = 0; s < model.clamp_count(); ++s) {
    const Index a = model.clamp_nodes[2 * s + 1];
    const double norm = 1.0 / model.clamp_ghost_offset[s].norm();
    sums.add(model, model.clamp_stiffness[s], &a, &norm, 1);
  }
}

// A clamp stands on the bar it holds.
void add_bars_under_clamps(const Model& model, const BarLookup& lookup,
                           std::vector<BarSpring>& stood_on) {
  for (Index s = 0; s < model.clamp_count(); ++s) {
    stood_on.emplace_back(lookup.find(model.clamp_nodes[2 * s], model.clamp_nodes[2 * s + 1]), s);
  }
}

}  // namespace

const ModelSpringKind kClampModel{
    .name = "clamps",
    .count = [](const Model& model) { return model.clamp_count(); },
    .stiffness = &Model::clamp_stiffness,
    .yield_limit = &Model::clamp_yield_moment,
    .yields = &Model::clamps_yield,
    .add_frequency_terms = add_clamp_frequency_terms,
    .add_bars_stood_on = add_bars_under_clamps,
    .torn_code = kTornClamp,
};

}  // namespace dinam
