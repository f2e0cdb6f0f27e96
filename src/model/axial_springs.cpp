// The bars' own axial springs as the model stage knows them (model_spring_kind.hpp); the bars
// themselves, and their stiffness E·A/L₀, are built with the object's mesh (model_builder.cpp).
#include <cmath>

#include "model/frequency_bound.hpp"
#include "model/model.hpp"
#include "model/model_spring_kinds.hpp"

namespace dinam {
namespace {

// g = (−n, n): the exact blocks k n nᵀ, and the coupling of the two ends when both are free.
void add_axial_frequency_terms(const Model& model, GershgorinSums& sums) {
  if (sums.bars_held) {
    return;  // projected, not stepped: no frequency of theirs bounds the step
  }
  const auto& x = model.node_initial_x;
  for (Index b = 0; b < model.bar_count(); ++b) {
    const Index n0 = model.bar_nodes[2 * b];
    const Index n1 = model.bar_nodes[2 * b + 1];
    const double k = model.bar_axial_stiffness[b];
    const Vec3 direction = (x[n1] - x[n0]).normalized();
    sums.diagonal[n0] += k * direction * direction.transpose();
    sums.diagonal[n1] += k * direction * direction.transpose();
    if (!model.pinned(n0) && !model.pinned(n1)) {
      const double c = k * std::sqrt(model.node_inv_mass[n0] * model.node_inv_mass[n1]);
      sums.coupling[n0] += c;
      sums.coupling[n1] += c;
    }
  }
}

}  // namespace

const ModelSpringKind kAxialSpringModel{
    .name = "axial springs",
    .count = [](const Model& model) { return model.bar_count(); },
    .stiffness = &Model::bar_axial_stiffness,
    .yield_limit = &Model::bar_yield_force,
    .yields = &Model::bars_yield,
    .add_frequency_terms = add_axial_frequency_terms,
    .add_bars_stood_on = nullptr,
    .torn_code = -1,
};

}  // namespace dinam
