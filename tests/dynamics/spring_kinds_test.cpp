// What every kind of spring in the list (dynamics/spring_kinds.hpp) must satisfy, checked through
// its entry alone, so that a new kind is checked by adding it to the list: its forces are minus
// the gradient of its energy (central differences, at a configuration where every spring is bent
// or twisted away from rest and none is straight), and the energy report books every kind.
#include "dynamics/spring_kinds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dynamics/energy.hpp"
#include "dynamics/integrator.hpp"
#include "model/model.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// A wire lattice standing on a clamped edge (so clamps exist beside axial, bending and torsion
// springs), every free node moved by up to 3 mm at random from its rest place (bars 0.2 m).
struct Perturbed {
  Model model;
  State state;
};

Perturbed perturbed_lattice() {
  Perturbed p{build_model(test::scene_from_yaml(R"(version: 1
duration: 1
objects:
  - name: lattice
    mesh:
      grid: {width: 1.0, height: 1.0, columns: 5, rows: 5, diagonals: none}
      rotation: [90, 0, 0]
      translation: [0, 0, 0.5]
    material: {density: 7850, youngs_modulus: 2.0e9, radius: 0.002}
    pinned: {box: {min: [-1, -1, 0.499], max: [1, 1, 0.501]}, clamped: true}
)")),
              {}};
  p.state = make_state(p.model, false);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> offset(-0.003, 0.003);
  for (Index i = 0; i < p.model.node_count(); ++i) {
    if (!p.model.pinned(i)) {
      p.state.x[i] += Vec3(offset(random), offset(random), offset(random));
    }
  }
  return p;
}

ForceSwitches only(const SpringKind& kind) {
  ForceSwitches switches;
  switches.gravity = switches.fields = switches.axial_springs = switches.axial_dampers = false;
  switches.bending = switches.torsion = switches.clamps = switches.global_damping = false;
  switches.wind = switches.ground = switches.object_contact = false;
  switches.*kind.switched = true;
  return switches;
}

TEST(SpringKinds, EveryKindsForceIsMinusTheGradientOfItsEnergy) {
  Perturbed p = perturbed_lattice();
  const Model& model = p.model;
  State& state = p.state;
  constexpr double kStep = 1e-7;  // m: central differences err by O(h²) ≈ 1e-14 of the curvature
  for (const SpringKind* kind : kSpringKinds) {
    SCOPED_TRACE(kind->name);
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
        const double above = kind->energy(model, state);
        state.x[i][axis] = kept - kStep;
        const double below = kind->energy(model, state);
        state.x[i][axis] = kept;
        // Rounding in the energy (about 1e-16 of the kind's total over 2h) and the O(h²) error,
        // both far below this share of the largest force.
        EXPECT_NEAR(-(above - below) / (2.0 * kStep), force[i][axis], 1e-5 * largest)
            << "node " << i << ", axis " << axis;
      }
    }
  }
}

TEST(SpringKinds, TheEnergyReportBooksEveryKind) {
  const Perturbed p = perturbed_lattice();
  double springs = 0.0;
  for (const SpringKind* kind : kSpringKinds) {
    const double energy = kind->energy(p.model, p.state);
    EXPECT_GT(energy, 0.0) << kind->name;
    springs += energy;
  }
  const EnergyReport report = energy_report(p.model, p.state, p.state.v_half);
  EXPECT_NEAR(report.axial + report.bending + report.torsion, springs, 1e-12 * springs);
}

}  // namespace
}  // namespace dinam
