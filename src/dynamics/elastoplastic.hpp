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
inline ElastoplasticResult elastoplastic(double deformation, double plastic_set, double stiffness,
                                         double yield) {
  const double trial = stiffness * (deformation - plastic_set);
  if (std::abs(trial) <= yield) {
    const double elastic = deformation - plastic_set;
    return {trial, plastic_set, 0.5 * stiffness * elastic * elastic, 0.0};
  }
  const double force = std::copysign(yield, trial);
  const double new_set = deformation - force / stiffness;
  const double elastic = force / stiffness;
  return {force, new_set, 0.5 * stiffness * elastic * elastic,
          yield * std::abs(new_set - plastic_set)};
}

}  // namespace dinam
