#pragma once
// Which integrator fits a scene (`dinam info`): the steps each would take and an estimate of its
// time, both from counts (estimate/run_estimate.hpp, estimate/implicit_cost.hpp), and the one
// recommended. Central differences are exact and cheap per step, so another is recommended only
// where its estimate is under half of theirs: the bars as constraints (`xpbd`) where the bars
// bound central differences' step (real cloth, rope and cable: its estimate is of explicit
// steps, as theirs); the implicit integrator where its estimate is under half of the better of
// those two even were it as far short as the worst measured for structures that move alike.
#include <string>

#include "estimate/run_estimate.hpp"
#include "scene/scene_description.hpp"
#include "stepping/stepper_kind.hpp"

namespace dinam {

struct Model;

// The estimates are of the motion alone: the settling before it is left out of both.
struct IntegratorChoice {
  RunEstimate central_difference;  // at its automatic step (or the scene's), with mass scaling
  RunEstimate implicit;            // at the scene's `timestep` or a quarter of a frame (its
                                   // `implicit` says what a step is made of)
  RunEstimate xpbd;                // the bars as constraints, at its automatic step
  bool central_difference_unscaled = false;  // estimated without its mass scaling (no room)
  bool contact_envelope = false;             // the implicit steps count contact's speed envelope
  // How many times short the implicit estimate may be (estimate/implicit_cost.hpp,
  // estimate_margin): 1 where the structure swings, 10 where it is free to land, fold or tumble.
  double implicit_margin = 1.0;
  // Why the bars as constraints are not recommended whatever their estimate: empty where they may
  // be ("contact within an object", "its bars' stretch shows").
  std::string xpbd_unfit;
  const StepperKind* recommended = &kCentralDifferences;
  // Where the implicit integrator is recommended: BDF2 for a structure that swings (backward
  // Euler would damp its swing away: 68 % of a mode's amplitude a period at 16 steps a period,
  // against BDF2's 6.7 %), backward Euler where it lands and folds (its damping settles it).
  ImplicitScheme recommended_scheme = ImplicitScheme::kBackwardEuler;

  bool recommends_implicit() const { return recommended == &kImplicitSchemes; }
  bool recommends_xpbd() const { return recommended == &kBarConstraints; }
};

// `model` is the scene's, built for its own integrator. Central differences' step depends on the
// masses it scales, so for an implicit scene their model is built here when
// `room_for_another_model` (the memory budget allows a second model); an implicit estimate needs
// no model of its own.
IntegratorChoice compare_integrators(const SceneDescription& scene, const Model& model, int threads,
                                     bool room_for_another_model);

// The `integrator` value recommended: central_difference, xpbd, implicit or implicit_bdf2.
const char* recommended_key(const IntegratorChoice& choice);

// Why `choice.recommended` is recommended, in a few words for `dinam info`.
std::string recommendation_reason(const IntegratorChoice& choice);

}  // namespace dinam
