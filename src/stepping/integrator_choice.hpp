#pragma once
// Which integrator fits a scene (`dinam info`): the steps each would take and an estimate of its
// time, both from counts (stepping/run_estimate.hpp, solver/implicit_cost.hpp), and the one
// recommended: the implicit integrator where its estimate is under half of central differences',
// which are exact and cheap per step, even were the implicit estimate as far short as the worst
// measured for structures that move alike; central differences otherwise.
#include "scene/scene_description.hpp"
#include "stepping/run_estimate.hpp"
#include "stepping/stepper_kind.hpp"

namespace dinam {

struct Model;

// The estimates are of the motion alone: the settling before it is left out of both.
struct IntegratorChoice {
  RunEstimate central_difference;  // at its automatic step (or the scene's), with mass scaling
  RunEstimate implicit;            // at the scene's `timestep` or a quarter of a frame (its
                                   // `implicit` says what a step is made of)
  bool central_difference_unscaled = false;  // estimated without its mass scaling (no room)
  bool contact_envelope = false;             // the implicit steps count contact's speed envelope
  // How many times short the implicit estimate may be (solver/implicit_cost.hpp,
  // estimate_margin): 1 where the structure swings, 10 where it is free to land, fold or tumble.
  double implicit_margin = 1.0;
  const StepperKind* recommended = &kCentralDifferences;
  // Where the implicit integrator is recommended: BDF2 for a structure that swings (backward
  // Euler would damp its swing away: 68 % of a mode's amplitude a period at 16 steps a period,
  // against BDF2's 6.7 %), backward Euler where it lands and folds (its damping settles it).
  ImplicitScheme recommended_scheme = ImplicitScheme::kBackwardEuler;

  bool recommends_implicit() const { return recommended == &kImplicitSchemes; }
};

// `model` is the scene's, built for its own integrator. Central differences' step depends on the
// masses it scales, so for an implicit scene their model is built here when
// `room_for_another_model` (the memory budget allows a second model); an implicit estimate needs
// no model of its own.
IntegratorChoice compare_integrators(const SceneDescription& scene, const Model& model, int threads,
                                     bool room_for_another_model);

// The `integrator` value recommended: central_difference, implicit or implicit_bdf2.
const char* recommended_key(const IntegratorChoice& choice);

// Why `choice.recommended` is recommended, in a few words for `dinam info`.
const char* recommendation_reason(const IntegratorChoice& choice);

}  // namespace dinam
