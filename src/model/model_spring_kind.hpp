#pragma once
// A kind of spring as the model stage knows it, described once beside its builder
// (bending_springs.cpp, clamps.cpp, …): what the stability bound, the derived-value checks, the
// yield bookkeeping and tearing need of it. model_spring_kinds.hpp lists the kinds; the dynamics
// stage's SpringKind (dynamics/spring_kind.hpp) adds the kernels and points back here.
#include <utility>
#include <vector>

#include "core/types.hpp"

namespace dinam {

struct Model;
class BarLookup;
struct GershgorinSums;

// (bar, spring id): a spring standing on a bar, so it breaks when the bar tears.
using BarSpring = std::pair<Index, Index>;

struct ModelSpringKind {
  const char* name;                       // "bending springs": in reports and the run-time estimate
  Index (*count)(const Model&);           // how many the model has
  std::vector<double> Model::*stiffness;  // (count) N/m or N·m/rad, checked finite and ≥ 0
  std::vector<double> Model::*yield_limit;  // (count, or empty when none yields) ∞: elastic
  bool Model::*yields;                      // whether some can flow plastically
  // Its terms of the Gershgorin bound on ω² at rest (frequency_bound.hpp).
  void (*add_frequency_terms)(const Model&, GershgorinSums&);
  // Tearing: the bars each spring stands on (none for the bar's own axial spring).
  void (*add_bars_stood_on)(const Model&, const BarLookup&, std::vector<BarSpring>&);
  Index torn_code;  // how Model::bar_springs names it (kTornBend, …); −1 for the bar's own spring
};

}  // namespace dinam
