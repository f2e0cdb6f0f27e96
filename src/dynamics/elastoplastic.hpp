#pragma once
// Perfect elastoplasticity of one spring, shared by the axial, bending and torsion kinds.
#include <cmath>

namespace dinam {

template <class T>
struct ElastoplasticResultT {
  T force;        // generalised force (N or N·m): k (d − p), flattened to ±yield
  T plastic_set;  // p after this evaluation (m or rad)
  T energy;       // J, ½ k (d − p)² with the new p: the elastic energy stored
  T dissipated;   // J, yield × |Δp|: the work turned into plastic deformation
};
using ElastoplasticResult = ElastoplasticResultT<double>;

// d is the deformation (extension or change of angle), p the plastic set so far. When the elastic
// force k (d − p) would exceed the yield value, it is flattened to it and the excess deformation
// moves into the plastic set, which stays after unloading. yield = ∞ keeps the spring elastic.
// Selects rather than branches (every quotient is computed, then chosen), so that the spring loops
// that call it vectorise.
// (In single precision for the float trial, docs/performance.md.)
template <class T>
[[gnu::always_inline]] inline ElastoplasticResultT<T> elastoplastic(T deformation, T plastic_set,
                                                                    T stiffness, T yield) {
  const T trial = stiffness * (deformation - plastic_set);
  const bool flows = std::abs(trial) > yield;
  const T force = flows ? std::copysign(yield, trial) : trial;
  const T flattened_elastic = force / stiffness;
  const T elastic = flows ? flattened_elastic : deformation - plastic_set;
  const T new_set = flows ? deformation - flattened_elastic : plastic_set;
  const T dissipated = flows ? yield * std::abs(new_set - plastic_set) : T(0);
  return {force, new_set, T(0.5) * stiffness * elastic * elastic, dissipated};
}

}  // namespace dinam
