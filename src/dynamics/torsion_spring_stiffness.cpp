// The torsion springs' stiffness matrices, for Newton's method (solver/), apart from their forces
// for the reason bending_spring_stiffness.cpp gives.
#include "dynamics/stiffness.hpp"
#include "dynamics/torsion_spring.hpp"
#include "model/model.hpp"

namespace dinam {

void add_torsion_spring_stiffness(const Model& model, const State& state, StiffnessSink& sink) {
  add_spring_stiffness<4>(model.torsion_count(), model.torsion_nodes, state.torsion_broken, state.x,
                          sink, [&](Index s, const std::array<Vec3, 4>& at) {
                            return local_stiffness<4>(at, [&](const auto& x) {
                              const auto r = torsion_spring(
                                  x[0], x[1], x[2], x[3], model.torsion_rest_angle[s],
                                  model.torsion_stiffness[s],
                                  plastic_set_of(state.torsion_plastic_set, s),
                                  yield_limit(model.torsion_yield_moment, s));
                              return std::array{r.force_a, r.force_i, r.force_j, r.force_b};
                            });
                          });
}

}  // namespace dinam
