#pragma once
// Every kind of spring, in the order a step adds their forces (which is part of the motion's
// bits: each node sums its forces kind by kind in this order, whatever the threads). The step,
// the energy report, tearing, the state's allocation, the memory estimate, the run-time estimate,
// the settle and the tests iterate this list; the model stage's kModelSpringKinds holds each
// entry's `built` half in the same order (spring_kinds_test checks it).
#include <array>
#include <stdexcept>
#include <string>

#include "dynamics/axial_spring.hpp"
#include "dynamics/bending_spring.hpp"
#include "dynamics/clamp_spring.hpp"
#include "dynamics/spring_kind.hpp"
#include "dynamics/torsion_spring.hpp"

namespace dinam {

inline constexpr std::array<const SpringKind*, 4> kSpringKinds{&kAxialSprings, &kBendingSprings,
                                                               &kClampSprings, &kTorsionSprings};

// The kind that Model::bar_springs names by `torn_code` (kTornBend, kTornTorsion, kTornClamp).
inline const SpringKind& spring_kind_torn_as(Index torn_code) {
  for (const SpringKind* kind : kSpringKinds) {
    if (kind->built->torn_code == torn_code) {
      return *kind;
    }
  }
  throw std::logic_error("no kind of spring is torn as code " + std::to_string(torn_code));
}

}  // namespace dinam
