#pragma once
// Selective mass scaling, as explicit crash codes do it: the few nodes whose springs would set a
// much shorter stable step than the rest of the model needs (the ends of short, stiff bars) take
// extra mass, so that no mode is faster than a target step. The low modes, which carry the
// visible motion, hardly move as long as the added mass is a small part of the total; the extra
// mass is real to every force (gravity pulls on it, inertia resists with it), so a free fall or a
// uniform field still moves every node alike.
#include <optional>

#include "core/types.hpp"
#include "model/frequency_bound.hpp"

namespace dinam {

struct Model;

// What was added, for `dinam info` and the run's summary.
struct MassScaling {
  double target_step = 0.0;  // s: the step asked for (0 when nothing was scaled)
  double added_mass = 0.0;   // kg
  double mass_before = 0.0;  // kg, the physical mass of the model's free nodes
  Index nodes = 0;           // nodes that took mass
  double step_gain = 1.0;    // how much longer the springs' stable step became
  bool capped = false;       // the default stopped at its added-mass limit, short of its aim

  double added_fraction() const { return mass_before > 0.0 ? added_mass / mass_before : 0.0; }
};

// The default (`timestep: auto`) gains only when the step grows by at least this factor: a
// smaller gain is not worth changing the physics for.
inline constexpr double kMassScalingMinGain = 1.25;
// The default aims at a step this many times shorter than the median node's springs allow (the
// step a mesh of like bars would take)...
inline constexpr double kMassScalingTypicalRatio = 1.5;
// ...and adds at most kDefaultMaxAddedMass (scene/) of the mass.

// The mass of the free nodes, kg: what moves, and what mass scaling's limit is a fraction of (a
// pinned steel frame of 190 kg must not let a 2 kg ball beside it take 4 kg).
double moving_mass(const Model& model);

// The mass each free node needs so that its row of the frequency bound is at most
// `omega_squared` (its own mass where it already is). Solving row_i(m) = own_i m_i/m +
// coupling_i √(m_i/m) = ω² for m, with the other masses as they are: raising a node's mass only
// lowers its neighbours' rows, so after all nodes are raised at once every row is within ω².
std::vector<double> masses_for_frequency(const Model& model, const NodeFrequencyRows& rows,
                                         double omega_squared);

// Mass added if every node took masses_for_frequency(ω²), kg.
double mass_needed_for(const Model& model, const NodeFrequencyRows& rows, double omega_squared);

// Sets the masses (and inverse masses of the free nodes) to masses_for_frequency(ω²); returns
// what was added. Only the springs count here: build the model's contact after it.
MassScaling scale_masses_to(Model& model, const NodeFrequencyRows& rows, double omega_squared);

// The default's choice of ω² for the springs alone, or none when scaling is not worth it:
// kMassScalingTypicalRatio² × the median free node's row, raised as needed to add at most
// `max_fraction` of the mass, and only when the step then grows by kMassScalingMinGain at least.
struct DefaultScaling {
  double omega_squared = 0.0;  // 1/s²
  bool capped = false;         // raised above the bulk's to stay within max_fraction
};
std::optional<DefaultScaling> default_scaling_frequency(const Model& model,
                                                        const NodeFrequencyRows& rows,
                                                        double max_fraction);

}  // namespace dinam
