// The axial springs' stiffness matrices, for Newton's method (solver/), in a file apart from their
// forces as every kind's are (bending_spring_stiffness.cpp says why).
#include "dynamics/axial_spring.hpp"
#include "dynamics/stiffness.hpp"
#include "model/model.hpp"

namespace dinam {

void add_axial_spring_stiffness(const Model& model, const State& state, StiffnessSink& sink) {
  add_spring_stiffness<2>(
      model.bar_count(), model.bar_nodes, state.bar_broken, state.x, sink,
      [&](Index b, const std::array<Vec3, 2>& at) {
        return local_stiffness<2>(at, [&](const auto& x) {
          const auto r = axial_spring(
              x[0], x[1], model.bar_rest_length[b], model.bar_axial_stiffness[b],
              plastic_set_of(state.bar_plastic_set, b), yield_limit(model.bar_yield_force, b));
          return std::array{r.force_on_n0, decltype(r.force_on_n0)(-r.force_on_n0)};
        });
      });
}

}  // namespace dinam
