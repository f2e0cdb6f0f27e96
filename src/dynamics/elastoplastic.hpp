#pragma once
// Perfect elastoplasticity of one spring, shared by the axial, bending and torsion kinds.
#include <cmath>

namespace dinam {

struct ElastoplasticResult {
  double force;        // generalised force (N or N·m): k (d − p), flattened to ±yield
  double plastic_set;  // p after this evaluation (m or rad)
  double energy;       // J, ½ k (d − p)² with the new p: the elastic energy stored
  double dissipated;   // J, yield × |Δp|: the work turned into plastic deformation
};

// d is the deformation (extension or change of angle), p the plastic set so far. When the elastic
// force k (d − p) would exceed the yield value, it is flattened to it and the excess deformation
// moves into the plastic set, which stays after unloading. yield = ∞ keeps the spring elastic.
// Selects rather than branches (every quotient is computed, then chosen), so that the spring loops
// that call it vectorise.
[[gnu::always_inline]] inline ElastoplasticResult elastoplastic(double deformation,
                                                                double plastic_set,
                                                                double stiffness, double yield) {
  const double trial = stiffness * (deformation - plastic_set);
  const bool flows = std::abs(trial) > yield;
  const double force = flows ? std::copysign(yield, trial) : trial;
  const double flattened_elastic = force / stiffness;
  const double elastic = flows ? flattened_elastic : deformation - plastic_set;
  const double new_set = flows ? deformation - flattened_elastic : plastic_set;
  const double dissipated = flows ? yield * std::abs(new_set - plastic_set) : 0.0;
  return {force, new_set, 0.5 * stiffness * elastic * elastic, dissipated};
}

}  // namespace dinam
