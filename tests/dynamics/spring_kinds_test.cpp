// What every kind of spring in the list (dynamics/spring_kinds.hpp) must satisfy, checked through
// its entry alone, so that a new kind is checked by adding it to the list: its forces are minus
// the gradient of its energy (central differences, at a configuration where every spring is bent
// or twisted away from rest and none is straight), and the energy report books every kind.
// (stiffness_test.cpp checks every kind's stiffness the same way.)
#include "dynamics/spring_kinds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "dynamics/energy.hpp"
#include "dynamics/force_kinds.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/perturbed_lattice.hpp"
#include "model/model.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

using test::perturbed_lattice;

ForceSwitches only(const SpringKind& kind) {
  return only(force_kind_of(kind));
}

// The model stage lists the same kinds in the same order (the stability bound sums their terms in
// it), and each names its springs in Model::bar_springs by a code of its own.
TEST(SpringKinds, BothStagesListTheSameKindsInOneOrder) {
  ASSERT_EQ(kSpringKinds.size(), kModelSpringKinds.size());
  std::vector<Index> codes;
  for (std::size_t k = 0; k < kSpringKinds.size(); ++k) {
    EXPECT_EQ(kSpringKinds[k]->built, kModelSpringKinds[k]) << kSpringKinds[k]->name();
    const Index code = kModelSpringKinds[k]->torn_code;
    EXPECT_EQ(std::count(codes.begin(), codes.end(), code), 0) << kSpringKinds[k]->name();
    codes.push_back(code);
    if (code >= 0) {
      EXPECT_EQ(&spring_kind_torn_as(code), kSpringKinds[k]);
    }
  }
}

// The forces at p's configuration against central differences of `which` energy, kind by kind
// (plastic sets held as the state has them).
void expect_forces_are_minus_the_gradient(test::PerturbedLattice& p, SpringEnergy which) {
  const Model& model = p.model;
  State& state = p.state;
  constexpr double kStep = 1e-7;  // m: central differences err by O(h²) ≈ 1e-14 of the curvature
  for (const SpringKind* kind : kSpringKinds) {
    SCOPED_TRACE(kind->name());
    ASSERT_GT(kind->count(model), 0);
    compute_forces(model, only(*kind), state, false);
    const std::vector<Vec3> force = state.force;
    double largest = 0.0;
    for (const Vec3& f : force) {
      largest = std::max(largest, f.norm());
    }
    ASSERT_GT(largest, 0.0);
    for (Index i = 0; i < model.node_count(); ++i) {
      if (model.pinned(i)) {
        continue;
      }
      for (int axis = 0; axis < 3; ++axis) {
        const double kept = state.x[i][axis];
        state.x[i][axis] = kept + kStep;
        const double above = kind->energy(model, state, which);
        state.x[i][axis] = kept - kStep;
        const double below = kind->energy(model, state, which);
        state.x[i][axis] = kept;
        // Rounding in the energy (about 1e-16 of the kind's total over 2h) and the O(h²) error,
        // both far below this share of the largest force.
        EXPECT_NEAR(-(above - below) / (2.0 * kStep), force[i][axis], 1e-5 * largest)
            << "node " << i << ", axis " << axis;
      }
    }
  }
}

TEST(SpringKinds, EveryKindsForceIsMinusTheGradientOfItsEnergy) {
  test::PerturbedLattice p = perturbed_lattice();
  expect_forces_are_minus_the_gradient(p, SpringEnergy::kStored);
}

// With springs that yield, the flattened force is minus the gradient of the stored energy plus the
// flow's work from the held plastic sets: the potential an implicit step minimises. Checked where
// springs of every kind flow.
TEST(SpringKinds, AFlowingSpringsForceIsMinusTheGradientOfItsEnergyWithTheFlowsWork) {
  // Yield values at which some springs of every kind flow there and some do not.
  test::PerturbedLattice p =
      perturbed_lattice(", yield: {axial: 50, bending: 0.003, torsion: 0.001}");
  State flowed = p.state;
  compute_forces(p.model, test::nothing_on(), flowed, false);
  for (const SpringKind* kind : kSpringKinds) {
    ForceSwitches switches = only(*kind);
    compute_forces(p.model, switches, flowed, true);
    const std::vector<double>& sets = flowed.*kind->plastic_set;
    const auto flowing = std::count_if(sets.begin(), sets.end(), [](double s) { return s != 0.0; });
    EXPECT_GT(flowing, 0) << kind->name() << ": none flows, so the check would not see the flow";
    EXPECT_LT(flowing, static_cast<long>(sets.size())) << kind->name();
  }
  expect_forces_are_minus_the_gradient(p, SpringEnergy::kWithFlow);
}

TEST(SpringKinds, TheEnergyReportBooksEveryKind) {
  const test::PerturbedLattice p = perturbed_lattice();
  double springs = 0.0;
  for (const SpringKind* kind : kSpringKinds) {
    const double energy = kind->energy(p.model, p.state, SpringEnergy::kStored);
    EXPECT_GT(energy, 0.0) << kind->name();
    springs += energy;
  }
  // The ties (the lattice's cord) are booked with the axial springs.
  Potential ties;
  const PotentialQuery query{p.model.node_initial_x, SpringEnergy::kStored};
  kTies.add_potential(p.model, p.state, query, ties);
  EXPECT_GT(ties.energy, 0.0);
  const EnergyReport report = energy_report(p.model, p.state, p.state.velocity);
  EXPECT_NEAR(report.axial + report.bending + report.torsion, springs + ties.energy,
              1e-12 * springs);
}

}  // namespace
}  // namespace dinam
