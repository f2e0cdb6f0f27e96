#pragma once
// Perfect elastoplasticity of one spring, shared by the axial, bending and torsion kinds.
#include <cmath>

#include "core/dual.hpp"

namespace dinam {

template <class T>
struct ElastoplasticResult {
  T force;            // generalised force (N or N·m): k (d − p), flattened to ±yield
  T plastic_set;      // p after this evaluation (m or rad)
  T energy;           // J, ½ k (d − p)² with the new p: the elastic energy stored
  double dissipated;  // J, yield × |Δp|: the work turned into plastic deformation
};

// d is the deformation (extension or change of angle), p the plastic set so far. When the elastic
// force k (d − p) would exceed the yield value, it is flattened to it and the excess deformation
// moves into the plastic set, which stays after unloading. yield = ∞ keeps the spring elastic.
// Selects rather than branches (every quotient is computed, then chosen), so that the spring loops
// that call it vectorise. T is double, or Dual for the derivatives (core/dual.hpp): a spring that
// flows has the perfectly plastic tangent, zero.
template <class T, class Yield>
[[gnu::always_inline]] inline ElastoplasticResult<T> elastoplastic(const T& deformation,
                                                                   double plastic_set,
                                                                   double stiffness,
                                                                   const Yield& yield) {
  using std::abs;
  using std::copysign;
  const T trial = stiffness * (deformation - plastic_set);
  const bool flows = abs(trial) > yield;
  const T force = flows ? T(copysign(T(yield), trial)) : trial;
  const T flattened_elastic = force / stiffness;
  const T elastic = flows ? flattened_elastic : T(deformation - plastic_set);
  const T new_set = flows ? T(deformation - flattened_elastic) : T(plastic_set);
  const double dissipated =
      flows ? value_of(yield) * std::abs(value_of(new_set) - plastic_set) : 0.0;
  return {force, new_set, 0.5 * stiffness * elastic * elastic, dissipated};
}

}  // namespace dinam
