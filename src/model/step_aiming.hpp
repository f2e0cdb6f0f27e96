#pragma once
// Aiming the time step (`timestep: {target}` or `{max_steps}`, and the default's mass scaling):
// mass added where a few short stiff bars would set the step, and where that alone would add more
// than its limit, the shortest bars collapsed, ever longer ones, until what is left can be scaled
// within it.
#include <functional>
#include <optional>

#include "model/model.hpp"
#include "scene/scene_description.hpp"

namespace dinam {

// How this build treats short bars: the least `weld` of every object, and the step that mass
// scaling aims at (none: the default's choice).
struct ShortBarPlan {
  double weld_floor = 0.0;
  std::optional<double> target_step;  // s
};

// Adds mass where the plan (or the default) asks, before the contact penalties are sized from the
// springs' frequency.
void scale_masses(const SceneDescription& scene, const ShortBarPlan& plan, Model& model);

// Builds the model with a plan for its short bars.
using BuildWithPlan = std::function<Model(const ShortBarPlan&)>;

// The model the scene asks for: built once as it is when it aims at no step; else with mass
// scaling aimed at the step, then with ever stronger collapses of short bars, until the added mass
// is within 'max_added_mass'. Throws UserError at the scene's `timestep` when no collapse gets
// there, naming the step that the strongest one allows.
Model build_aiming_at_step(const SceneDescription& scene, const BuildWithPlan& build_once);

}  // namespace dinam
