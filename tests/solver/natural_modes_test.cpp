// The natural modes (solver/natural_modes.hpp) against closed forms: a clamped cantilever's first
// three bending frequencies (Euler–Bernoulli), a beaded string's transverse and axial frequencies
// (the discrete string, exactly), a pendulum's √(g/L) from the tension its weight puts in the bar
// (the geometric stiffness), and the mass shares' sum; the Lanczos path against a dense solve.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>

#include "model/model.hpp"
#include "solver/equilibrium.hpp"
#include "solver/natural_modes.hpp"
#include "solver/settle.hpp"
#include "solver/solver_support.hpp"
#include "solver/stiffness_matrix.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// A cantilever of 1 m in `segments` bars, clamped at x = 0, without gravity: E I = 8000 N·m²,
// ρ A = 0.785 kg/m. Modes come in pairs, bending in y and in z alike.
std::vector<NaturalMode> cantilever_modes(int segments, int count) {
  const Model model = test::clamped_cantilever(segments, "gravity: [0, 0, 0]");
  const State state = make_state(model, false);  // at rest, unloaded: an equilibrium
  return natural_modes(model, state, test::static_forces(), count);
}

TEST(NaturalModes, CantileverBendsAtEulerBernoullisFrequencies) {
  const double scale = std::sqrt(8000.0 / 0.785) / test::kTwoPi;  // Hz per (βL)²
  const std::array<double, 3> beta_l = {1.875104, 4.694091, 7.854757};
  std::array<double, 3> coarse_error{};
  for (const int segments : {20, 80}) {
    const std::vector<NaturalMode> modes = cantilever_modes(segments, 6);
    ASSERT_EQ(modes.size(), 6u);
    for (int n = 0; n < 3; ++n) {
      const double expected = beta_l[n] * beta_l[n] * scale;
      // The two bending planes give the same frequency.
      EXPECT_NEAR(modes[2 * n].frequency, modes[2 * n + 1].frequency, 1e-9 * expected);
      const double error = std::abs(modes[2 * n].frequency / expected - 1.0);
      // Lumped masses and springs converge at second order: the error of mode n grows as
      // (n / N)²; 80 bars put the third mode within 0.2 % and every mode at least ten times
      // nearer than 20 bars do.
      if (segments == 20) {
        coarse_error[n] = error;
      } else {
        EXPECT_LT(error, 2e-3) << "mode " << n + 1;
        EXPECT_LT(error, coarse_error[n] / 10.0) << "mode " << n + 1;
      }
    }
  }
}

// N beads on a string between two supports, stretched by ε: each bead has the mass ρ A a0 of the
// string around it, the tension is T = E A ε, and the discrete string's modes are exactly
// ω_k = 2 √(T / (m a)) sin(kπ / 2(N + 1)) across (the tension's geometric stiffness T/a) and
// 2 √(E A / (a0 m)) sin(kπ / 2(N + 1)) along (the bars' own stiffness).
TEST(NaturalModes, BeadedStringIsTheDiscreteString) {
  constexpr int kBeads = 7;
  const Model model = build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
gravity: [0, 0, 0]
ground: {{contact: false}}
objects:
  - name: string
    mesh: {{polyline: {{points: [[0, 0, 1], [1, 0, 1]], segments: {}}}}}
    material: {{density: 1000, youngs_modulus: 1.0e6, area: 1.0e-6}}
    pinned: {{indices: [0, {}]}}
    bending_pairs: none
    torsion: false
)",
                                                                    kBeads + 1, kBeads + 1)));
  constexpr double kStretch = 0.01;
  State state = make_state(model, false);
  for (Vec3& x : state.x) {
    x.x() *= 1.0 + kStretch;  // uniform: still an equilibrium, now under tension
  }
  const double a0 = 1.0 / (kBeads + 1);
  const double a = a0 * (1.0 + kStretch);
  const double tension = 1.0e6 * 1.0e-6 * kStretch;
  const double mass = 1000.0 * 1.0e-6 * a0;
  ASSERT_NEAR(model.node_mass[1], mass, 1e-15);
  const std::vector<NaturalMode> modes =
      natural_modes(model, state, test::static_forces(), 3 * kBeads);
  ASSERT_EQ(modes.size(), 3u * kBeads);
  for (int k = 1; k <= kBeads; ++k) {
    const double sine = std::sin(k * std::numbers::pi / (2.0 * (kBeads + 1)));
    const double across = 2.0 * std::sqrt(tension / (mass * a)) * sine / test::kTwoPi;
    const double along = 2.0 * std::sqrt(1.0e6 * 1.0e-6 / (a0 * mass)) * sine / test::kTwoPi;
    // Across: each a pair (y and z), the lowest 2N modes; along: the rest, far above.
    EXPECT_NEAR(modes[2 * (k - 1)].frequency, across, 1e-9 * across) << k;
    EXPECT_NEAR(modes[2 * (k - 1) + 1].frequency, across, 1e-9 * across) << k;
    EXPECT_NEAR(modes[2 * kBeads + k - 1].frequency, along, 1e-9 * along) << k;
  }
}

// A bar hanging from a support under gravity is a pendulum: its free end swings at √(g/L) in
// both directions, with L the length the weight has stretched it to (the stiffness across is
// the tension over the length, m g / L), and bounces along the bar at √(k/m). The equilibrium is
// the settle's (Newton's method, from the bar held out level).
TEST(NaturalModes, HangingBarIsAPendulum) {
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
gravity: [0, 0, -9.81]
ground: {contact: false}
settle: {residual: 1.0e-12}
objects:
  - name: bar
    mesh: {polyline: {points: [[0, 0, 2], [0.5, 0, 2]]}}
    material: {density: 1000, youngs_modulus: 1.0e6, area: 1.0e-4}
    pinned: {indices: [0]}
)"));
  State state = make_state(model, false);
  settle_under_gravity(model, 1e-4, {}, state);
  ASSERT_TRUE(state.settled.by_newton);
  const double length = (state.x[1] - state.x[0]).norm();
  const double mass = model.node_mass[1];
  const std::vector<NaturalMode> modes = natural_modes(model, state, test::static_forces(), 3);
  ASSERT_EQ(modes.size(), 3u);
  const double swing = std::sqrt(9.81 / length) / test::kTwoPi;
  const double bounce = std::sqrt(1.0e6 * 1.0e-4 / 0.5 / mass) / test::kTwoPi;
  EXPECT_NEAR(modes[0].frequency, swing, 1e-9 * swing);
  EXPECT_NEAR(modes[1].frequency, swing, 1e-9 * swing);
  EXPECT_NEAR(modes[2].frequency, bounce, 1e-9 * bounce);
  // The bounce moves all of the free mass up and down, the swings none of it.
  EXPECT_NEAR(modes[2].mass_share.z(), 1.0, 1e-9);
  EXPECT_NEAR(modes[0].mass_share.z(), 0.0, 1e-9);
}

// Over all its modes a structure's mass shares add up to the whole free mass in each direction.
TEST(NaturalModes, MassSharesOfAllModesSumToOne) {
  const std::vector<NaturalMode> modes = cantilever_modes(6, 1000);
  ASSERT_EQ(modes.size(), 18u);  // 6 free nodes
  Vec3 sum = Vec3::Zero();
  for (const NaturalMode& mode : modes) {
    sum += mode.mass_share;
  }
  EXPECT_NEAR((sum - Vec3::Ones()).norm(), 0.0, 1e-9);
}

// Above 600 free degrees of freedom the lowest modes come from shift-invert Lanczos: the same as
// a dense solve of M^{-½} K M^{-½}.
TEST(NaturalModes, LanczosFindsTheLowestModesOfADenseSolve) {
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
gravity: [0, 0, 0]
ground: {contact: false}
objects:
  - name: net
    mesh:
      grid: {width: 1.0, height: 1.0, columns: 14, rows: 14, diagonals: none}
    material: {density: 7850, youngs_modulus: 2.0e9, radius: 0.003}
    pinned: {box: {min: [-2, -0.01, -1], max: [2, 0.01, 1]}, clamped: true}
)"));
  const State state = make_state(model, false);
  const FreeDofs dofs = free_dofs(model);
  ASSERT_GT(dofs.count, 600);
  const std::vector<NaturalMode> modes = natural_modes(model, state, test::static_forces(), 8);
  StiffnessAssembly assembly;
  const Eigen::MatrixXd k = Eigen::MatrixXd(
      assembly.assemble(model, state, test::static_forces(), dofs, Definiteness::kExact));
  const Eigen::VectorXd root = free_masses(model, dofs).cwiseSqrt().cwiseInverse();
  const Eigen::VectorXd dense =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(root.asDiagonal() * k * root.asDiagonal(),
                                                     Eigen::EigenvaluesOnly)
          .eigenvalues();
  ASSERT_EQ(modes.size(), 8u);
  for (int m = 0; m < 8; ++m) {
    EXPECT_NEAR(modes[m].omega_squared, dense[m], 1e-8 * dense[7]) << m;
  }
}

// A rope or a chain hanging from one end sways as the hanging chain: ω_n = (j₀,ₙ / 2) √(g / L),
// j₀,ₙ the zeros of the Bessel function J₀ (Bernoulli and Euler), where its bending matters
// little: a chain's links hinge, so its first three modes are within 1 % on a 1 m chain; a fibre
// rope bends a little (its bending length (EI/w)^⅓ is 8–10 cm), so its first two modes are
// within 1 % on a 3 m rope and its second 2–3.4 % above on a 1 m one, as a real rope's are. (A
// solid rod of the rope's diameter and modulus swung at 8.25 Hz for the chain's 1.38.)
std::vector<NaturalMode> hanging_modes(const std::string& preset, double length) {
  const Model model = build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
ground: {{contact: false}}
objects:
  - name: rope
    mesh: {{polyline: {{points: [[0, 0, 4], [0, 0, {}]], segments: 60}}}}
    material: {{preset: {}}}
    pinned: {{indices: [0]}}
)",
                                                                    4.0 - length, preset)));
  State state = make_state(model, false);
  // The chain's links are steel (E A = 1e7 N over 17 mm): its axial forces round to about
  // 2e-6 of a node's weight.
  const EquilibriumOutcome outcome =
      find_equilibrium(model, test::static_forces(), {1e-5, 100, false}, state);
  EXPECT_TRUE(outcome.converged) << outcome.failure;
  return natural_modes(model, state, test::static_forces(), 6);
}

TEST(NaturalModes, HangingRopeAndChainPresetsSwayAsTheHangingChain) {
  constexpr std::array<double, 3> kBesselZeros = {2.404826, 5.520078, 8.653728};
  const auto chain_frequency = [&](int n, double length) {
    return kBesselZeros[n] / 2.0 * std::sqrt(9.81 / length) / test::kTwoPi;
  };
  const std::vector<NaturalMode> chain = hanging_modes("chain", 1.0);
  ASSERT_EQ(chain.size(), 6u);
  for (int n = 0; n < 3; ++n) {
    // Swaying in x and in y alike, each within 1 %.
    EXPECT_NEAR(chain[2 * n].frequency / chain_frequency(n, 1.0), 1.0, 0.01) << n + 1;
    EXPECT_NEAR(chain[2 * n + 1].frequency / chain_frequency(n, 1.0), 1.0, 0.01) << n + 1;
  }
  for (const char* rope : {"hemp_rope", "nylon_rope"}) {
    const std::vector<NaturalMode> long_rope = hanging_modes(rope, 3.0);
    ASSERT_EQ(long_rope.size(), 6u);
    for (int n = 0; n < 2; ++n) {
      EXPECT_NEAR(long_rope[2 * n].frequency / chain_frequency(n, 3.0), 1.0, 0.01)
          << rope << " mode " << n + 1;
    }
    const std::vector<NaturalMode> short_rope = hanging_modes(rope, 1.0);
    EXPECT_NEAR(short_rope[0].frequency / chain_frequency(0, 1.0), 1.0, 0.01) << rope;
    const double second = short_rope[2].frequency / chain_frequency(1, 1.0);
    EXPECT_GT(second, 1.01) << rope;  // its bending shows
    EXPECT_LT(second, 1.05) << rope;
  }
}

}  // namespace
}  // namespace dinam
