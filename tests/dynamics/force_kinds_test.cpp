// What every kind of force in the list (dynamics/force_kinds.hpp) must satisfy, checked through
// its entry alone, so that a new kind is checked by adding it to the list: one switch of its own,
// hooks that fit its role (what stores energy reports it, what does work books it on a ledger
// line), and, for a potential, forces that are minus the gradient of the potential it adds.
// (spring_kinds_test.cpp checks the springs' own half.)
#include "dynamics/force_kinds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "dynamics/integrator.hpp"
#include "dynamics/perturbed_lattice.hpp"
#include "solver/potential.hpp"

namespace dinam {
namespace {

using test::perturbed_lattice;

// The switches that are on, by their place in ForceSwitches (a struct of bools alone).
std::set<std::size_t> switched_on(const ForceSwitches& switches) {
  const auto* flags = reinterpret_cast<const bool*>(&switches);
  std::set<std::size_t> on;
  for (std::size_t k = 0; k < sizeof(ForceSwitches) / sizeof(bool); ++k) {
    if (flags[k]) {
      on.insert(k);
    }
  }
  return on;
}

// Every switch belongs to one kind, and every kind has one: switching a kind off leaves exactly
// it out of every loop, and no force acts that no switch controls.
TEST(ForceKinds, EverySwitchBelongsToExactlyOneKind) {
  static_assert(sizeof(ForceSwitches) == 12 * sizeof(bool), "a switch was added: list its kind");
  EXPECT_TRUE(switched_on(ForceSwitches::none()).empty());
  std::set<std::size_t> seen;
  for (const ForceKind* kind : kForceKinds) {
    SCOPED_TRACE(kind->name());
    const std::set<std::size_t> on = switched_on(only(*kind));
    ASSERT_EQ(on.size(), 1u);
    EXPECT_TRUE(seen.insert(*on.begin()).second) << "its switch is another kind's too";
  }
  EXPECT_EQ(seen, switched_on(ForceSwitches{}));
}

// A kind's hooks fit its role, so the energy report, its ledger and the implicit step take it
// whole: what stores energy reports it, what drives or dissipates books its work, and the
// implicit step treats it as its role needs.
TEST(ForceKinds, EachKindsHooksFitItsRole) {
  for (const ForceKind* kind : kForceKinds) {
    SCOPED_TRACE(kind->name());
    EXPECT_NE(kind->name(), nullptr);
    EXPECT_TRUE((kind->add_forces != nullptr) != (kind->add_forces_after_team != nullptr))
        << "a kind adds its forces in one place of the step";
    const bool stores = kind->role == ForceRole::kPotential || kind->role == ForceRole::kContact;
    const bool works = kind->role != ForceRole::kPotential;
    EXPECT_EQ(kind->report_energy != nullptr, stores);
    EXPECT_EQ(kind->ledger[0].force != nullptr, works);
    for (const LedgerLine& line : kind->ledger) {
      EXPECT_EQ(line.force == nullptr, line.work == nullptr);
    }
    const ImplicitDamper& damper = kind->damper;
    const bool damps = damper.mass_rate != nullptr || damper.add_hessian != nullptr;
    EXPECT_EQ(damps, kind->implicit == ImplicitTreatment::kDamper)
        << "a damper gives the implicit step its dissipation; nothing else does";
    if (damper.add_support_pull != nullptr) {
      EXPECT_NE(damper.add_hessian, nullptr) << "a support's pull is its Hessian's cross term";
    }
    switch (kind->implicit) {
      case ImplicitTreatment::kInPotential:
        EXPECT_TRUE(stores);
        EXPECT_NE(kind->add_potential, nullptr);
        break;
      case ImplicitTreatment::kLoadAtEnd:  // of the time alone: nothing else is
        EXPECT_EQ(kind->role, ForceRole::kLoad);
        break;
      case ImplicitTreatment::kLoadAtStart:  // a load, or a weak drag lagged by a step
        EXPECT_TRUE(kind->role == ForceRole::kLoad || kind->role == ForceRole::kDissipation);
        break;
      case ImplicitTreatment::kDamper:
        EXPECT_EQ(kind->role, ForceRole::kDissipation);
        break;
      case ImplicitTreatment::kOwnContact:
        EXPECT_EQ(kind->role, ForceRole::kContact);
        break;
    }
    if (kind->spring != nullptr) {
      EXPECT_EQ(&force_kind_of(*kind->spring), kind);
    }
  }
  for (const SpringKind* spring : kSpringKinds) {  // every spring kind is a force kind
    EXPECT_EQ(force_kind_of(*spring).spring, spring);
  }
}

// The forces of every kind with a potential, alone, against central differences of the potential
// it adds, on a lattice that bends, twists and dips into the ground: what Newton's method
// minimises is what the step's forces derive from.
TEST(ForceKinds, EveryPotentialsForceIsMinusItsGradient) {
  test::PerturbedLattice p = perturbed_lattice();
  const Model& model = p.model;
  State& state = p.state;
  const std::vector<Vec3> origin = model.node_initial_x;
  constexpr double kProbe = 1e-7;  // m: central differences err by O(h²) ≈ 1e-14 of the curvature
  int checked = 0;
  for (const ForceKind* kind : kForceKinds) {
    if (kind->add_potential == nullptr) {
      continue;
    }
    SCOPED_TRACE(kind->name());
    const ForceSwitches switches = only(*kind);
    compute_static_forces(model, switches, state);
    const std::vector<Vec3> force = state.force;
    double largest = 0.0;
    for (Index i = 0; i < model.node_count(); ++i) {
      largest = model.pinned(i) ? largest : std::max(largest, force[i].norm());
    }
    ASSERT_GT(largest, 0.0) << "the lattice gives the kind nothing to check";
    for (Index i = 0; i < model.node_count(); ++i) {
      if (model.pinned(i)) {
        continue;
      }
      for (int axis = 0; axis < 3; ++axis) {
        const double kept = state.x[i][axis];
        state.x[i][axis] = kept + kProbe;
        const double above = potential_energy(model, state, switches, origin).energy;
        state.x[i][axis] = kept - kProbe;
        const double below = potential_energy(model, state, switches, origin).energy;
        state.x[i][axis] = kept;
        // Rounding in the energy (about 1e-16 of its magnitude over 2h) and the O(h²) error, far
        // below this share of the largest force.
        EXPECT_NEAR(-(above - below) / (2.0 * kProbe), force[i][axis], 1e-5 * largest)
            << "node " << i << ", axis " << axis;
      }
    }
    ++checked;
  }
  EXPECT_EQ(checked, 7);  // gravity, four kinds of spring, the ties and the ground
}

}  // namespace
}  // namespace dinam

namespace dinam {
namespace {

// The implicit step's gradient (compute_potential_forces) is −∇V alone: whatever the velocities
// and the ground's friction history say, the forces are the static ones of a state with neither,
// and the state is left as it was but for its forces.
TEST(ForceKinds, PotentialForcesReadNoVelocityNorFrictionHistory) {
  test::PerturbedLattice p = perturbed_lattice();
  const Model& model = p.model;
  const ForceSwitches potential = switches_treated_as(ImplicitTreatment::kInPotential);
  State quiet = p.state;  // at rest, nothing touching: the static forces
  std::fill(quiet.contact_touching.begin(), quiet.contact_touching.end(), 0);
  compute_static_forces(model, potential, quiet);

  State moving = p.state;
  int below = 0;
  for (Index i = 0; i < model.node_count(); ++i) {
    moving.velocity[i] = Vec3(0.3 * i, -0.2, 0.1 * (i % 3));
    if (model.ground.clearance(i, moving.x[i]) < 0.0 && !model.pinned(i)) {
      below += 1;
      moving.contact_touching[i] = 1;  // anchored away from its foot: a stretched stick spring
      moving.contact_anchor[i] = model.ground.foot(moving.x[i]) + Vec3(0.01, 0.02, 0.0);
    }
  }
  ASSERT_GT(below, 0) << "the lattice dips into the ground";
  const State before = moving;
  compute_potential_forces(model, potential, moving);
  for (Index i = 0; i < model.node_count(); ++i) {
    EXPECT_EQ(moving.force[i], quiet.force[i]) << "node " << i;
    EXPECT_EQ(moving.velocity[i], before.velocity[i]);
    EXPECT_EQ(moving.contact_touching[i], before.contact_touching[i]);
    EXPECT_EQ(moving.contact_anchor[i], before.contact_anchor[i]);
  }
  EXPECT_EQ(moving.dt, before.dt);
}

}  // namespace
}  // namespace dinam
