// Beams and shafts against closed-form mechanics. The lumped model has a discretisation error of
// its own; where it matters the test refines the mesh and checks that the error shrinks.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "dynamics/integrator.hpp"
#include "dynamics/modal_support.hpp"
#include "dynamics/stability.hpp"
#include "model/frequency_bound.hpp"
#include "model/model.hpp"
#include "solver/implicit_integrator.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// A steel-like beam of 1 m with a thick section (radius of gyration 2 cm), so that its bending
// frequencies are not buried under the axial ones: E I = 8000 N·m², ρ A = 0.785 kg/m.
constexpr double kLength = 1.0;
constexpr double kE = 2.0e11;
constexpr double kDensity = 7850.0;
constexpr double kArea = 1.0e-4;
constexpr double kInertia = 4.0e-8;
constexpr double kEI = kE * kInertia;
// Euler–Bernoulli first cantilever frequency, (β₁L)² √(EI / (ρ A L⁴)) with β₁L = 1.8751.
const double kOmega1 = 1.8751 * 1.8751 * std::sqrt(kEI / (kDensity * kArea)) / (kLength * kLength);

// The beam as a scene: `mesh` its mesh map, `pinned` its pinned map; `material_extra` goes at the
// end of the material map (", yield_stress: …"), `object_keys` are further keys of the object
// (whole YAML lines, indented) and `scene_keys` further top-level keys.
std::string beam_scene_yaml(const std::string& mesh, const std::string& pinned,
                            const std::string& material_extra = "",
                            const std::string& object_keys = "",
                            const std::string& scene_keys = "") {
  return fmt::format(R"(version: 1
duration: 1
gravity: [0, 0, 0]
ground: {{contact: false}}
{}
objects:
  - name: beam
    mesh: {}
    material: {{density: {}, youngs_modulus: {}, area: {}, area_moment: {}, polar_moment: {} {}}}
{}    pinned: {}
    torsion: false
)",
                     scene_keys, mesh, kDensity, kE, kArea, kInertia, 2 * kInertia, material_extra,
                     object_keys, pinned);
}

// A cantilever along +x from the origin in `segments` bars. The clamp is two pinned nodes: the
// root and one a thousandth of a segment behind it, so the root's bending spring spans half a
// segment of beam as a clamped end should (k = 2EI / (ε + h) → 2EI / h).
// Node ids: 0 behind, 1 root, segments + 1 tip. `extra` is appended to the material. The short
// bar behind the root is meant: `weld: off` keeps it from being collapsed.
std::string cantilever_yaml(int segments, const std::string& extra, const std::string& scene) {
  const double h = kLength / segments;
  std::string points = fmt::format("[[{}, 0, 0]", -1e-3 * h);
  for (int k = 0; k <= segments; ++k) {
    points += fmt::format(", [{}, 0, 0]", k * h);
  }
  points += "]";
  return beam_scene_yaml(fmt::format("{{polyline: {{points: {}}}, weld: off}}", points),
                         "{indices: [0, 1]}", extra, "", scene);
}

// Runs the model for `duration` at its automatic step, calling `watch(state)` after each step.
template <typename Watch>
void run(const Model& model, double duration, State& state, double dt, Watch&& watch) {
  const auto steps = static_cast<long>(std::ceil(duration / dt));
  for (long s = 0; s < steps; ++s) {
    step(model, dt, {}, state);
    watch(state);
  }
}

double automatic_step(const Model& model) {
  return kAutoTimestepSafety * critical_timestep(model);
}

// Free vibration started in the Euler–Bernoulli first mode shape; the period is read from the
// upward zero crossings of the tip displacement.
double measured_first_frequency(int segments) {
  const Model model = build_model(test::scene_from_yaml(cantilever_yaml(segments, "", "")));
  const double dt = automatic_step(model);
  State state = initial_state(model, dt);
  const double beta = 1.8751 / kLength;
  const double sigma =
      (std::cosh(1.8751) + std::cos(1.8751)) / (std::sinh(1.8751) + std::sin(1.8751));
  for (Index i = 2; i < model.node_count(); ++i) {
    const double x = model.node_initial_x[i].x();
    const double shape = std::cosh(beta * x) - std::cos(beta * x) -
                         sigma * (std::sinh(beta * x) - std::sin(beta * x));
    state.velocity[i] = Vec3(0, 0, 1e-4 * kOmega1 * shape);  // tip amplitude ~ 0.2 mm
  }
  const Index tip = model.node_count() - 1;
  std::vector<double> crossings;
  double previous = 0.0;
  run(model, 6.5 * 2 * std::numbers::pi / kOmega1, state, dt, [&](const State& s) {
    const double z = s.x[tip].z();
    if (previous < 0.0 && z >= 0.0) {
      crossings.push_back(s.time - dt * z / (z - previous));
    }
    previous = z;
  });
  EXPECT_GE(crossings.size(), 5u);
  const auto periods = static_cast<double>(crossings.size() - 1);
  return 2 * std::numbers::pi * periods / (crossings.back() - crossings.front());
}

TEST(Cantilever, FirstFrequencyConvergesToEulerBernoulli) {
  std::vector<double> errors;
  for (const int segments : {20, 40, 80}) {
    errors.push_back(std::abs(measured_first_frequency(segments) / kOmega1 - 1.0));
  }
  // The lumped masses and springs converge at second order: each halving of the segment length
  // must cut the error clearly, and at 80 segments it is well under a percent.
  EXPECT_LT(errors[1], 0.6 * errors[0]);
  EXPECT_LT(errors[2], 0.6 * errors[1]);
  EXPECT_LT(errors[2], 0.005);
  std::printf("first-frequency error at 20/40/80 segments: %.4f %.4f %.4f\n", errors[0], errors[1],
              errors[2]);
}

// The beam as a polyline of `segments` bars along +x, built in at its first vertex by one
// clamped pinned node; `parts` (YAML, indented as a key of the object) may add materials.
std::string clamped_beam_yaml(int segments, const std::string& parts = "") {
  return beam_scene_yaml(
      fmt::format("{{polyline: {{points: [[0, 0, 0], [{}, 0, 0]], segments: {}}}}}", kLength,
                  segments),
      "{indices: [0], clamped: true}", "", parts);
}

// A cantilever built in at one clamped pinned node (docs/scene-format.md, 'clamped'): its natural
// frequencies from a dense eigen-solve of the model's own stiffness converge to Euler–Bernoulli's
// at second order, (β₁L, β₂L) = (1.8751, 4.6941). The lumped model with the ghost-node clamp is the
// beam equation's central difference, whose error is about −0.21 % (first mode) at 20 bars.
TEST(Cantilever, ClampedEndConvergesAtSecondOrder) {
  const double scale = std::sqrt(kEI / (kDensity * kArea)) / (kLength * kLength);
  const double reference[2] = {1.8751040687 * 1.8751040687 * scale,
                               4.6940911330 * 4.6940911330 * scale};
  double errors[3][2] = {};
  const int refinements[3] = {20, 40, 80};
  for (int r = 0; r < 3; ++r) {
    const int segments = refinements[r];
    const Model model = build_model(test::scene_from_yaml(clamped_beam_yaml(segments)));
    ASSERT_EQ(model.clamp_count(), 1);
    const Eigen::VectorXd omega = test::natural_frequencies(model);
    // The automatic step's bound covers the clamp's stiffness too.
    EXPECT_GE(max_frequency_squared_bound(model), omega.maxCoeff() * omega.maxCoeff());
    // Bending in y and in z share each frequency (a round section): modes 0, 1 and then 2, 3.
    EXPECT_NEAR(omega[0], omega[1], 1e-6 * omega[0]);
    for (int mode = 0; mode < 2; ++mode) {
      errors[r][mode] = omega[2 * mode] / reference[mode] - 1.0;
    }
    std::printf("clamped cantilever, %d bars: first %+.5f, second %+.5f\n", segments, errors[r][0],
                errors[r][1]);
  }
  EXPECT_LT(std::abs(errors[1][0]), 0.003);  // within 0.3 % at 40 bars
  for (int mode = 0; mode < 2; ++mode) {
    for (int r = 0; r < 2; ++r) {
      // Second order: each halving of the bars divides the error by about 4.
      const double ratio = errors[r][mode] / errors[r + 1][mode];
      EXPECT_GT(ratio, 3.5) << "mode " << mode + 1 << ", " << refinements[r] << " bars";
      EXPECT_LT(ratio, 4.5) << "mode " << mode + 1 << ", " << refinements[r] << " bars";
    }
  }
}

// A rod of two materials (objects[].parts): its first half of E₁, its second of E₂ = E₁ / 5 and
// a tenth of the density. The static response to a tip load, solved with the model's own
// finite-difference stiffness, against closed forms: axially springs in series,
// δ = P (L₁/E₁A + L₂/E₂A); in bending (unit-load method on the stepped cantilever)
// δ = P ((L³ − L₂³) / 3E₁I + L₂³ / 3E₂I).
TEST(MaterialParts, TwoMaterialCantileverFollowsTheSteppedBeam) {
  const int segments = 40;
  const double e2 = kE / 5.0;
  const double half = kLength / 2.0;
  const Model model = build_model(test::scene_from_yaml(clamped_beam_yaml(
      segments, fmt::format("    parts:\n"
                            "      - nodes: {{box: {{min: [{}, -1, -1], max: [2, 1, 1]}}}}\n"
                            "        material: {{density: {}, youngs_modulus: {}, area: {}, "
                            "area_moment: {}, polar_moment: {}}}\n",
                            half, kDensity / 10, e2, kArea, kInertia, 2 * kInertia))));
  EXPECT_NEAR(model.total_mass(), kDensity * kArea * half * (1.0 + 0.1), 1e-12);

  const test::FreeDofs dofs = test::free_dofs(model);
  const Eigen::MatrixXd k = test::finite_difference_stiffness(model, dofs);
  const Index tip = model.node_count() - 1;
  ASSERT_NEAR(model.node_initial_x[tip].x(), kLength, 1e-12);
  const double load = 10.0;  // N
  for (const int axis : {0, 2}) {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs.count);
    f[dofs.dof_of_node[tip] + axis] = load;
    const Eigen::VectorXd u = k.colPivHouseholderQr().solve(f);
    const double tip_displacement = u[dofs.dof_of_node[tip] + axis];
    if (axis == 0) {
      // Exact for a chain of axial springs; the finite differences leave ~1e-10.
      const double expected = load * (half / (kE * kArea) + half / (e2 * kArea));
      EXPECT_NEAR(tip_displacement / expected, 1.0, 1e-8);
    } else {
      // The lumped beam overestimates by O(1/N²): 1/(2N²) for one material (the PL³/3EI test
      // below), and the step in EI at the joint adds a term of the same order; 1/N² bounds both.
      const double l2_cubed = half * half * half;
      const double expected =
          load * ((kLength * kLength * kLength - l2_cubed) / (3 * kE * kInertia) +
                  l2_cubed / (3 * e2 * kInertia));
      EXPECT_NEAR(tip_displacement / expected, 1.0, 1.0 / (segments * segments) + 1e-6)
          << tip_displacement << " m against " << expected << " m";
    }
  }
}

// The tip deflection at rest under a tip load, by dynamic relaxation: the load ramps up over two
// periods with mass-proportional damping (ζ = ½ in the first mode), then everything settles.
double static_tip_deflection(int segments, double load) {
  const std::string force = fmt::format(
      "forces: [{{force: [0, 0, {}], object: beam, nodes: {{indices: [{}]}}, profile: {{type: "
      "ramp, start: 0, end: {}}}}}]",
      -load, segments + 1, 2 * 2 * std::numbers::pi / kOmega1);
  const Model model = build_model(test::scene_from_yaml(
      cantilever_yaml(segments, "", fmt::format("damping: {{global: {}}}\n{}", kOmega1, force))));
  const double dt = automatic_step(model);
  State state = initial_state(model, dt);
  run(model, 9 * 2 * std::numbers::pi / kOmega1, state, dt, [](const State&) {});
  return -state.x[segments + 1].z();
}

TEST(Cantilever, SmallTipDeflectionIsPLCubedOverThreeEI) {
  const double load = 24.0;  // N: δ = PL³/3EI = 1 mm, small enough to be linear
  const double reference = load * std::pow(kLength, 3) / (3 * kEI);
  std::vector<double> errors;
  for (const int segments : {20, 40, 80}) {
    const double error = std::abs(static_tip_deflection(segments, load) / reference - 1.0);
    // Springs of tributary length h (h/2 at the root) sum to PL³/3EI (1 + 1/(2N²)) exactly;
    // relaxation leaves < 1e-6 and the neglected geometric stiffening ~(δ/L)² = 1e-6.
    EXPECT_LT(error, 1.0 / (2.0 * segments * segments) + 1e-4) << segments;
    errors.push_back(error);
  }
  EXPECT_LT(errors[2], errors[0]);
}

// The elastica of a cantilever under a dead vertical tip load: EI θ'' = P cos θ along the arc,
// θ(0) = 0, θ'(L) = 0. Shooting on θ'(0) with RK4 gives the tip deflection δ/L for α = PL²/EI.
double elastica_tip_deflection(double alpha) {
  auto integrate = [alpha](double curvature0, double* deflection) {
    const int n = 4000;
    const double ds = 1.0 / n;
    double theta = 0.0;
    double omega = curvature0;  // θ'
    double z = 0.0;
    for (int i = 0; i < n; ++i) {
      // State (θ, θ', z); z' = sin θ.
      auto f = [alpha](double t, double w) {
        return std::array<double, 3>{w, alpha * std::cos(t), std::sin(t)};
      };
      const auto k1 = f(theta, omega);
      const auto k2 = f(theta + 0.5 * ds * k1[0], omega + 0.5 * ds * k1[1]);
      const auto k3 = f(theta + 0.5 * ds * k2[0], omega + 0.5 * ds * k2[1]);
      const auto k4 = f(theta + ds * k3[0], omega + ds * k3[1]);
      theta += ds / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]);
      omega += ds / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]);
      z += ds / 6 * (k1[2] + 2 * k2[2] + 2 * k3[2] + k4[2]);
    }
    *deflection = -z;
    return omega;  // θ'(L), to be driven to zero
  };
  double lo = -alpha;  // θ'(0) = −α x_tip/L lies in [−α, 0]
  double hi = 0.0;
  double deflection = 0.0;
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    (integrate(mid, &deflection) > 0.0 ? hi : lo) = mid;  // θ'(L) > 0: start more steeply
  }
  integrate(0.5 * (lo + hi), &deflection);
  return deflection;
}

TEST(Cantilever, LargeDeflectionFollowsTheElastica) {
  const double reference = elastica_tip_deflection(1.0);
  EXPECT_NEAR(reference, 0.3017, 2e-4);           // Bisshopp and Drucker (1945) tabulate 0.3017
  const double load = kEI / (kLength * kLength);  // PL²/EI = 1
  const double deflection = static_tip_deflection(40, load) / kLength;
  // Discretisation ~1/(2N²) and the bar's axial give P/EA = 4e-4 leave it well inside 0.5 %.
  EXPECT_NEAR(deflection / reference, 1.0, 0.005);
}

// A root that yields at My: under a tip load P the root moment is P L, so the root starts to
// flow at P = My / L; below that load the beam stands elastically, above it the root is a hinge
// and the beam folds until the shrinking lever arm balances My.
constexpr double kYieldMoment = 100.0;  // N·m: collapse at 100 N; the elastic tip then sags 4 mm

Model yielding_cantilever(double load, double ramp_time, double damping,
                          const std::string& integrator = "central_difference") {
  const std::string force = fmt::format(
      "forces: [{{force: [0, 0, {}], object: beam, nodes: {{indices: [21]}}, profile: {{type: "
      "ramp, start: 0, end: {}}}}}]",
      -load, ramp_time);
  return build_model(test::scene_from_yaml(cantilever_yaml(
      20, fmt::format(", yield: {{bending: {}}}", kYieldMoment),
      fmt::format("integrator: {}\ndamping: {{global: {}}}\n{}", integrator, damping, force))));
}

TEST(Cantilever, RootStartsToYieldWhenPLReachesMy) {
  const double collapse = kYieldMoment / kLength;
  const double ramp = 40 * 2 * std::numbers::pi / kOmega1;  // slow: 40 periods up to 1.2 My/L
  const Model model = yielding_cantilever(1.2 * collapse, ramp, kOmega1);
  const double dt = automatic_step(model);
  State state = initial_state(model, dt);
  double load_at_yield = -1.0;
  run(model, ramp, state, dt, [&](const State& s) {
    if (load_at_yield < 0.0 && s.bend_plastic_set[0] != 0.0) {  // spring 0 is the root's
      load_at_yield = 1.2 * collapse * s.time / ramp;
    }
  });
  ASSERT_GT(load_at_yield, 0.0) << "the root never yielded";
  // Slow loading leaves a dynamic overshoot of well under 1 %.
  EXPECT_NEAR(load_at_yield / collapse, 1.0, 0.01);
}

// Under `load` ramped over 4 periods and held to 1 s, the tip's deflection (m): central
// differences at their automatic step, or the implicit integrator at 2 ms.
double tip_after_hold(double load, const std::string& integrator) {
  const double ramp = 4 * 2 * std::numbers::pi / kOmega1;
  const Model model = yielding_cantilever(load, ramp, 0.2 * kOmega1, integrator);
  if (model.integrator == IntegratorKind::kImplicit) {
    const double h = 0.002;
    State state = initial_state(model, h);
    ImplicitIntegrator implicit(model);
    implicit.advance(state, h, 500);
    return -state.x[21].z();
  }
  const double dt = automatic_step(model);
  State state = initial_state(model, dt);
  run(model, 1.0, state, dt, [](const State&) {});
  return -state.x[21].z();
}

// Below My/L the beam stands, deflected as the elastic closed form says; above, it folds.
void expect_stands_below_and_collapses_above(const std::string& integrator) {
  const double collapse = kYieldMoment / kLength;
  const double elastic = 0.95 * collapse * std::pow(kLength, 3) / (3 * kEI);
  EXPECT_NEAR(tip_after_hold(0.95 * collapse, integrator) / elastic, 1.0, 0.01);
  EXPECT_GT(tip_after_hold(1.05 * collapse, integrator), 10.0 * elastic);
}

TEST(Cantilever, StandsBelowMyOverLAndCollapsesAboveIt) {
  expect_stands_below_and_collapses_above("central_difference");
}

// The same two with the implicit integrator at steps of 1 and 2 ms (18 and 9 a period, 130 and
// 260 times central differences' bound): a spring that flows within a step is mapped back to its
// yield moment at every Newton iterate (the step minimises the stored energy plus the flow's work).
TEST(Cantilever, ImplicitRootStartsToYieldWhenPLReachesMy) {
  const double collapse = kYieldMoment / kLength;
  const double ramp = 40 * 2 * std::numbers::pi / kOmega1;
  const Model model = yielding_cantilever(1.2 * collapse, ramp, kOmega1, "implicit");
  const double h = 0.001;
  ASSERT_GT(h, 100.0 * automatic_step(yielding_cantilever(1.2 * collapse, ramp, kOmega1)));
  State state = initial_state(model, h);
  ImplicitIntegrator integrator(model);
  double load_at_yield = -1.0;
  while (state.time < ramp && load_at_yield < 0.0) {
    integrator.advance(state, h, 1);
    if (state.bend_plastic_set[0] != 0.0) {
      load_at_yield = 1.2 * collapse * state.time / ramp;
    }
  }
  ASSERT_GT(load_at_yield, 0.0) << "the root never yielded";
  // Late by the damping's lag behind a slow ramp, α/ω² = 1/ω1 (0.48 % of the load), and at most
  // the step the flow is seen in (0.17 %).
  EXPECT_NEAR(load_at_yield / collapse, 1.0, 0.01);
}

TEST(Cantilever, ImplicitStandsBelowMyOverLAndCollapsesAboveIt) {
  expect_stands_below_and_collapses_above("implicit");
}

// A shaft between two lever arms; the far lever is turned by a couple T = F r. The twist at rest
// is φ = T L / (G J). Bending is made very stiff so only torsion gives way. The shaft is one bar,
// or a straight wire cut into four, which has no references inside and gets one spring over its
// whole length.
class Shaft : public ::testing::TestWithParam<int> {};

TEST_P(Shaft, TwistIsTorqueTimesLengthOverGJ) {
  test::TemporaryFolder folder("shaft");
  const double length = 1.0;
  const double arm = 0.1;
  const int bars = GetParam();
  // Vertices 1 and 2: the near lever's tip and the shaft's start; the shaft runs from 2 through
  // 3 … to its end, the far lever's tip beyond.
  std::string obj = fmt::format("v -0.1 0 0\nv 0 0 0\nv 0 {} 0\n", arm);
  for (int k = 1; k <= bars; ++k) {
    obj += fmt::format("v {} 0 0\n", length * k / bars);
  }
  obj += fmt::format("v {} {} 0\nl 1 2\nl 2 3\n", length, arm);
  for (int k = 0; k < bars; ++k) {
    obj += fmt::format("l {} {}\n", k == 0 ? 2 : 3 + k, 4 + k);
  }
  obj += fmt::format("l {} {}\n", 3 + bars, 4 + bars);
  std::ofstream(folder.path() / "shaft.obj") << obj;
  const double g = 8.0e10;
  const double j = 1.0e-9;   // GJ = 80 N·m²
  const double force = 8.0;  // T = 0.8 N·m: φ = 0.01 rad
  const std::string scene = fmt::format(
      R"(version: 1
duration: 1
gravity: [0, 0, 0]
ground: {{contact: false}}
damping: {{global: 450}}
objects:
  - name: shaft
    mesh: {{file: shaft.obj}}
    material: {{density: 7850, youngs_modulus: 2.0e11, shear_modulus: {}, area: 1.0e-4,
                area_moment: 1.0e-6, polar_moment: {}}}
    pinned: {{box: {{min: [-0.2, -0.01, -0.01], max: [0.01, 0.11, 0.01]}}}}
forces:
  - {{force: [0, 0, {}], object: shaft, nodes: {{box: {b}}}, profile: {{type: ramp, end: 0.02}}}}
  - {{force: [0, 0, {}], object: shaft, nodes: {{box: {j}}}, profile: {{type: ramp, end: 0.02}}}}
)",
      g, j, force, -force, fmt::arg("b", "{min: [0.99, 0.09, -0.01], max: [1.01, 0.11, 0.01]}"),
      fmt::arg("j", "{min: [0.99, -0.01, -0.01], max: [1.01, 0.01, 0.01]}"));
  const Model model = build_model(read_scene_text(scene, folder.path() / "shaft.yaml"));
  ASSERT_EQ(model.torsion_count(), 1);       // only the shaft has references at both ends
  ASSERT_EQ(model.bars_without_torsion, 3);  // the stub and the two levers, which end free
  const double dt = automatic_step(model);
  State state = initial_state(model, dt);
  run(model, 0.15, state, dt, [](const State&) {});
  // The lever's turn about the shaft, read from positions alone. (assimp reads coordinates in
  // single precision, so nodes are found within 1e-6 m.)
  auto node_at = [&](const Vec3& p) {
    for (Index i = 0; i < model.node_count(); ++i) {
      if ((model.node_initial_x[i] - p).norm() < 1e-6) {
        return i;
      }
    }
    ADD_FAILURE() << "no node at " << p.transpose();
    return Index{0};
  };
  const Vec3 lever = state.x[node_at(Vec3(length, arm, 0))] - state.x[node_at(Vec3(length, 0, 0))];
  const double twist = std::atan2(lever.z(), lever.y());
  const double reference = force * arm * length / (g * j);
  // Small-angle theory; the dead load's arm shrinks as cos φ (5e-5) and the stiff shaft's bending
  // gives way by ~1e-4 of the twist: 0.5 % is ample and still catches a factor like 2 or 1/L.
  EXPECT_NEAR(twist / reference, 1.0, 0.005);
}

INSTANTIATE_TEST_SUITE_P(OneBarAndAWireOfFour, Shaft, ::testing::Values(1, 4));

}  // namespace
}  // namespace dinam
