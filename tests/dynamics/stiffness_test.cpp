// The stiffness matrices Newton's method assembles (dynamics/stiffness.hpp): each kernel's K is
// −∂f/∂x by central differences of its own forces, at random configurations and at the awkward
// ones (bending pairs nearly straight, inside and outside the rounded cap of a bent rest; torsion
// references fading into line); and every kind in the list, and the ground, hand the model's
// solver the same K as central differences of the step's forces.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "dynamics/axial_spring.hpp"
#include "dynamics/bending_spring.hpp"
#include "dynamics/contact/ground_contact.hpp"
#include "dynamics/contact/object_contact.hpp"
#include "dynamics/force_kinds.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/perturbed_lattice.hpp"
#include "dynamics/spring_kinds.hpp"
#include "dynamics/stiffness.hpp"
#include "dynamics/torsion_spring.hpp"
#include "model/frequency_bound.hpp"
#include "model/model.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// Central differences of forces that are O(1) N at O(1) m with a step of 1e-6 m: truncation
// O(h² f''') ≈ 1e-12 and rounding O(ε f / h) ≈ 1e-10 of the largest entry, both far below this
// share of it; a wrong term (a missing product-rule part, a sign) is of the entry's own size.
constexpr double kStep = 1e-6;
constexpr double kStiffnessRelative = 1e-6;

// Checks K = −∂f/∂x column by column, f(x) giving the forces on the element's nodes; K is the
// kernel's own, by local_stiffness, unless given.
template <int kNodes, class Forces>
void expect_stiffness_is_minus_force_jacobian(const std::array<Vec3, kNodes>& x,
                                              const Forces& forces, const char* what,
                                              double step = kStep,
                                              const LocalStiffness<kNodes>* given = nullptr) {
  const LocalStiffness<kNodes> k = given != nullptr ? *given : local_stiffness<kNodes>(x, forces);
  const double scale = std::max(1.0, k.cwiseAbs().maxCoeff());
  for (int j = 0; j < kNodes; ++j) {
    for (int a = 0; a < 3; ++a) {
      std::array<Vec3, kNodes> plus = x;
      std::array<Vec3, kNodes> minus = x;
      plus[j][a] += step;
      minus[j][a] -= step;
      const std::array<Vec3, kNodes> f_plus = forces(plus);
      const std::array<Vec3, kNodes> f_minus = forces(minus);
      for (int i = 0; i < kNodes; ++i) {
        for (int b = 0; b < 3; ++b) {
          const double difference = -(f_plus[i][b] - f_minus[i][b]) / (2 * step);
          EXPECT_NEAR(k(3 * i + b, 3 * j + a), difference, kStiffnessRelative * scale)
              << what << ": row " << 3 * i + b << ", column " << 3 * j + a;
        }
      }
    }
  }
}

Vec3 random_point(std::mt19937& rng) {
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  return {coordinate(rng), coordinate(rng), coordinate(rng)};
}

TEST(Stiffness, AxialSpringAtRandomLengthsAndUnderPlasticSet) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 20; ++trial) {
    const std::array<Vec3, 2> x{random_point(rng), random_point(rng)};
    const double rest = 0.3 + 0.1 * trial;  // shorter and longer than the bar: both signs of N
    const double plastic_set = trial % 3 == 0 ? 0.05 : 0.0;
    expect_stiffness_is_minus_force_jacobian<2>(
        x,
        [&](const auto& y) {
          const auto r = axial_spring(y[0], y[1], rest, 50.0, plastic_set);
          return std::array{r.force_on_n0, decltype(r.force_on_n0)(-r.force_on_n0)};
        },
        "axial");
  }
}

TEST(Stiffness, BendingSpringAtRandomAnglesAndNearlyStraight) {
  // Through bending_spring_stiffness, which takes over from the kernel's Jacobian in line.
  auto check = [](const std::array<Vec3, 3>& x, double rest, double plastic_set, const char* what) {
    const LocalStiffness<3> k = bending_spring_stiffness(x, rest, 3.0, plastic_set,
                                                         std::numeric_limits<double>::infinity());
    expect_stiffness_is_minus_force_jacobian<3>(
        x,
        [&](const auto& y) {
          const auto r = bending_spring(y[0], y[1], y[2], rest, 3.0, plastic_set);
          return std::array{r.force_a, r.force_c, r.force_b};
        },
        what, kStep, &k);
  };
  std::mt19937 rng(5);
  for (int trial = 0; trial < 30; ++trial) {
    const double rest = 0.3 + 2.5 * (trial % 10) / 10.0;  // rest angles across (0, π)
    check({random_point(rng), random_point(rng), random_point(rng)}, rest,
          trial % 3 == 0 ? 0.2 : 0.0, "random");
  }
  // In line and nearly so: deflections ψ from 0 to 0.2 rad, for a straight rest (M fades as ψ)
  // and for bent rests of 0.03 and 0.3 rad, whose cone point is rounded within
  // w = min(ψ0, 0.05) of straight (inside the cap, at its edge and beyond it).
  const Vec3 xc(0.1, -0.2, 0.3);
  const Vec3 along = Vec3(1.0, 0.4, -0.2).normalized();
  const Vec3 across = along.cross(Vec3(0.0, 0.0, 1.0)).normalized();
  for (const double rest_deflection : {0.0, 0.03, 0.3}) {
    for (const double psi : {0.0, 1e-4, 1e-3, 0.02, 0.029, 0.031, 0.049, 0.051, 0.2}) {
      const Vec3 xa = xc - 0.7 * along;
      const Vec3 xb = xc + 0.9 * (std::cos(psi) * along + std::sin(psi) * across);
      check({xa, xc, xb}, std::numbers::pi - rest_deflection, 0.0, "nearly straight");
    }
  }
}

TEST(Stiffness, TorsionSpringAtRandomAndWithReferencesFadingIntoLine) {
  auto check = [](const std::array<Vec3, 4>& x, double rest, double plastic_set, const char* what,
                  double step = kStep) {
    expect_stiffness_is_minus_force_jacobian<4>(
        x,
        [&](const auto& y) {
          const auto r = torsion_spring(y[0], y[1], y[2], y[3], rest, 2.0, plastic_set);
          return std::array{r.force_a, r.force_i, r.force_j, r.force_b};
        },
        what, step);
  };
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> twist(-3.0, 3.0);
  for (int trial = 0; trial < 30; ++trial) {
    check({random_point(rng), random_point(rng), random_point(rng), random_point(rng)}, twist(rng),
          trial % 2 == 0 ? 0.3 : 0.0, "random");
  }
  // Reference a at angle θ from the bar's line, from 20° down to 0.05° where its weight
  // sin²θ ≈ 1e-6 has all but faded; b a well-placed reference. The forces vary over the
  // reference's offset from the line (0.6 mm at 0.05°), so the difference steps a ten-thousandth
  // of it: truncation 1e-8 of the entries.
  const Vec3 xi(0.1, -0.2, 0.05);
  const Vec3 xj(1.1, 0.1, -0.1);
  const Vec3 axis = (xj - xi).normalized();
  const Vec3 across = axis.cross(Vec3(0.3, 0.2, 1.0)).normalized();
  for (const double degrees : {0.05, 0.5, 2.0, 5.0, 11.5, 20.0}) {
    const double theta = degrees * std::numbers::pi / 180.0;
    const Vec3 xa = xi - 0.7 * (std::cos(theta) * axis + std::sin(theta) * across);
    const Vec3 xb = xj + 0.6 * axis.cross(across) + 0.2 * axis;
    check({xa, xi, xj, xb}, twist(rng), 0.0, "fading reference",
          std::min(kStep, 1e-4 * 0.7 * std::sin(theta)));
  }
}

// Collects the elements' matrices into one dense K over every node (pinned ones included).
class DenseSink final : public StiffnessSink {
 public:
  explicit DenseSink(Index nodes) : k(Eigen::MatrixXd::Zero(3 * nodes, 3 * nodes)) {}
  void prepare(int /*node_count*/, double* /*stiffness*/) const override {}
  void add_prepared(const Index* nodes, int node_count, const double* stiffness) override {
    const int size = 3 * node_count;
    const Eigen::Map<const Eigen::MatrixXd> local(stiffness, size, size);
    for (int i = 0; i < node_count; ++i) {
      for (int j = 0; j < node_count; ++j) {
        k.block<3, 3>(3 * nodes[i], 3 * nodes[j]) += local.block<3, 3>(3 * i, 3 * j);
      }
    }
  }
  Eigen::MatrixXd k;
};

using test::nothing_on;
using test::perturbed_lattice;

// Checks the free nodes' rows and columns of `k` against central differences of the forces
// `switches` leave on.
void expect_model_stiffness(const Model& model, State state, const ForceSwitches& switches,
                            const Eigen::MatrixXd& k, const char* what) {
  const double scale = k.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0.0) << what;
  for (Index j = 0; j < model.node_count(); ++j) {
    if (model.pinned(j)) {
      continue;
    }
    for (int a = 0; a < 3; ++a) {
      const double kept = state.x[j][a];
      state.x[j][a] = kept + kStep;
      compute_static_forces(model, switches, state);
      const std::vector<Vec3> plus = state.force;
      state.x[j][a] = kept - kStep;
      compute_static_forces(model, switches, state);
      state.x[j][a] = kept;
      for (Index i = 0; i < model.node_count(); ++i) {
        if (model.pinned(i)) {
          continue;
        }
        for (int b = 0; b < 3; ++b) {
          const double difference = -(plus[i][b] - state.force[i][b]) / (2 * kStep);
          ASSERT_NEAR(k(3 * i + b, 3 * j + a), difference, kStiffnessRelative * scale)
              << what << ": node " << i << " axis " << b << ", node " << j << " axis " << a;
        }
      }
    }
  }
}

TEST(Stiffness, EveryKindInTheListGivesTheJacobianOfItsForces) {
  const test::PerturbedLattice p = perturbed_lattice();
  for (const SpringKind* kind : kSpringKinds) {
    SCOPED_TRACE(kind->name());
    ASSERT_GT(kind->count(p.model), 0);
    DenseSink sink(p.model.node_count());
    kind->add_stiffness(p.model, p.state, sink);
    expect_model_stiffness(p.model, p.state, only(force_kind_of(*kind)), sink.k, kind->name());
  }
}

// The stable step rests on each kind's terms of the Gershgorin bound (the model stage's half of
// its entry, model/frequency_bound.hpp): at rest, every kind's highest ω² by itself, the largest
// eigenvalue of M^{-½} K M^{-½} from the stiffness the step's forces have, lies under the bound
// its terms alone give. A kind whose terms fell short would let `timestep: auto` go unstable.
TEST(Stiffness, EveryKindsStabilityTermsBoundItsHighestFrequencyAtRest) {
  const test::PerturbedLattice p = perturbed_lattice();
  const Model& model = p.model;
  const State rest = make_state(model, false);
  const Index n = model.node_count();
  Eigen::VectorXd root_inverse_mass(3 * n);
  for (Index i = 0; i < n; ++i) {
    root_inverse_mass.segment<3>(3 * i).setConstant(std::sqrt(model.node_inv_mass[i]));
  }
  for (const SpringKind* kind : kSpringKinds) {
    SCOPED_TRACE(kind->name());
    DenseSink sink(n);
    kind->add_stiffness(model, rest, sink);
    const Eigen::MatrixXd scaled =
        root_inverse_mass.asDiagonal() * sink.k * root_inverse_mass.asDiagonal();
    const double highest =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(scaled, Eigen::EigenvaluesOnly)
            .eigenvalues()
            .maxCoeff();
    GershgorinSums sums(n);
    kind->built->add_frequency_terms(model, sums);
    double bound = 0.0;
    for (Index i = 0; i < n; ++i) {
      if (!model.pinned(i)) {
        const double own =
            Eigen::SelfAdjointEigenSolver<Mat3>(sums.diagonal[i]).eigenvalues().maxCoeff();
        bound = std::max(bound, own * model.node_inv_mass[i] + sums.coupling[i]);
      }
    }
    EXPECT_GT(highest, 0.0);
    EXPECT_LE(highest, bound * (1.0 + 1e-12));  // rounding of the two sums' order
  }
}

TEST(Stiffness, GroundGivesItsNormalPenaltyOnTheNodesBelowIt) {
  const test::PerturbedLattice p = perturbed_lattice();
  Index below = 0;
  for (const Vec3& x : p.state.x) {
    below += x.z() < -0.3 ? 1 : 0;
  }
  ASSERT_GT(below, 0);
  DenseSink sink(p.model.node_count());
  add_ground_contact_stiffness(p.model, p.state, sink);
  ForceSwitches only = nothing_on();
  only.ground = true;
  expect_model_stiffness(p.model, p.state, only, sink.k, "ground");
}

// A rod pressed into a sheet: node–triangle and bar–bar pairs, each with its closest points moving
// with the nodes. The stiffness is taken at the pairs the last force evaluation found.
TEST(Stiffness, ContactBetweenObjectsGivesTheJacobianOfItsNormalPenalty) {
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
ground: {contact: false}
contact: {objects: true}
objects:
  - name: sheet
    mesh: {grid: {width: 1.0, height: 1.0, columns: 3, rows: 3, diagonals: one}}
    material: {density: 1000, youngs_modulus: 1.0e6, radius: 0.004}
    pinned: {all: true}
  - name: rod
    mesh: {polyline: {points: [[0.21, 0.28, 0.1], [0.83, 0.52, 0.1]], segments: 3}}
    material: {density: 1000, youngs_modulus: 1.0e6, radius: 0.01}
)"));
  State state = make_state(model, false);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> offset(-0.002, 0.002);
  for (Index i = 0; i < model.node_count(); ++i) {
    if (!model.pinned(i)) {  // the rod, 7 to 11 mm deep into the sheet's 14 mm reach
      state.x[i] += Vec3(offset(random), offset(random), -0.095 + offset(random));
    }
  }
  ForceSwitches only = nothing_on();
  only.object_contact = true;
  compute_static_forces(model, only, state);
  int node_triangle = 0;
  int bar_bar = 0;
  for (const ContactPoint& point : state.object_contact.touching) {
    ((point.key >> 63) == 0 ? bar_bar : node_triangle) += 1;
  }
  ASSERT_GT(node_triangle, 0);
  ASSERT_GT(bar_bar, 0);
  DenseSink sink(model.node_count());
  add_object_contact_stiffness(model, state, sink);
  expect_model_stiffness(model, state, only, sink.k, "contact between objects");
}

}  // namespace
}  // namespace dinam
