#include "dynamics/stability.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "dynamics/integrator.hpp"
#include "dynamics/modal_support.hpp"
#include "model/model.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

using test::finite_difference_stiffness;
using test::free_dofs;
using test::FreeDofs;
using test::max_frequency_squared;

// ω_max² of the model at rest, from a dense eigen-solve of M^{-½} K M^{-½} over the free
// degrees of freedom, with K assembled here from k n nᵀ per bar (not from dynamics/).
double exact_max_frequency_squared(const Model& model) {
  const FreeDofs dofs = free_dofs(model);
  Eigen::MatrixXd k_matrix = Eigen::MatrixXd::Zero(dofs.count, dofs.count);
  for (Index b = 0; b < model.bar_count(); ++b) {
    const Index n0 = model.bar_nodes[2 * b];
    const Index n1 = model.bar_nodes[2 * b + 1];
    const Vec3 n = (model.node_initial_x[n1] - model.node_initial_x[n0]).normalized();
    const Mat3 block = model.bar_axial_stiffness[b] * n * n.transpose();
    const int d0 = dofs.dof_of_node[n0];
    const int d1 = dofs.dof_of_node[n1];
    if (d0 >= 0) {
      k_matrix.block<3, 3>(d0, d0) += block;
    }
    if (d1 >= 0) {
      k_matrix.block<3, 3>(d1, d1) += block;
    }
    if (d0 >= 0 && d1 >= 0) {
      k_matrix.block<3, 3>(d0, d1) -= block;
      k_matrix.block<3, 3>(d1, d0) -= block;
    }
  }
  return max_frequency_squared(model, dofs, k_matrix);
}

// Bars alone: no bending, torsion, faces' shear or ground contact, so the bound is the axial one.
Model model_of(const std::string& mesh, const std::string& pinned) {
  return build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
ground: {{contact: false}}
objects:
  - mesh: {}
    material: {{density: 1200, youngs_modulus: 2.0e7, radius: 0.001}}
    pinned: {}
    bending_pairs: none
    torsion: false
    faces: net
)",
                                                       mesh, pinned)));
}

TEST(Stability, BoundIsAboveTheTrueHighestFrequencyAndWithinAFactorTwo) {
  const std::vector<Model> models = {
      model_of("{grid: {width: 1.5, height: 1, columns: 9, rows: 6, diagonals: one}}",
               "{indices: [0, 10, 20]}"),
      model_of("{grid: {width: 1, height: 1, columns: 5, rows: 5, diagonals: both}}",
               "{indices: [0]}"),
      model_of("{file: cube_soup.stl}", "{indices: [0]}"),
      model_of("{polyline: {points: [[0, 0, 0], [1, 0.3, 0]], segments: 12}}", "{indices: [0]}"),
  };
  for (const Model& model : models) {
    const double exact = exact_max_frequency_squared(model);
    const double bound = max_frequency_squared_bound(model);
    EXPECT_GE(bound, exact * (1.0 - 1e-12));
    EXPECT_LE(bound, 2.0 * exact * (1.0 + 1e-12));  // not so loose that auto wastes steps
  }
}

// ω_max² of the full model at rest from a dense eigen-solve, with the stiffness matrix taken by
// central differences of the real forces (every spring kind), not from the bound's formulas.
double finite_difference_max_frequency_squared(const Model& model) {
  const FreeDofs dofs = free_dofs(model);
  return max_frequency_squared(model, dofs, finite_difference_stiffness(model, dofs));
}

TEST(Stability, BoundCoversBendingAndTorsion) {
  for (const std::string& mesh :
       {std::string("{grid: {width: 0.6, height: 0.4, columns: 6, rows: 4, diagonals: one}}"),
        std::string("{file: cube_soup.stl, scale: 0.2}"),
        std::string(
            "{polyline: {points: [[0, 0, 0], [0.3, 0.1, 0], [0.5, 0.4, 0.2]], segments: 5}}")}) {
    // A thick section, so bending and torsion matter next to the axial springs.
    const Model model = build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
ground: {{contact: false}}
objects:
  - mesh: {}
    material: {{density: 1200, youngs_modulus: 2.0e7, area: 1.0e-4, area_moment: 1.0e-8}}
    pinned: {{indices: [0]}}
    bending_pairs: all
)",
                                                                      mesh)));
    ASSERT_GT(model.bend_count(), 0) << mesh;
    const double exact = finite_difference_max_frequency_squared(model);
    const double bound = max_frequency_squared_bound(model);
    EXPECT_GE(bound, exact * (1.0 - 1e-6)) << mesh;
    EXPECT_LE(bound, 4.0 * exact) << mesh;  // within a factor 2 in the step
  }
}

TEST(Stability, DampingShortensTheLimit) {
  const std::string scene = R"(version: 1
duration: 1
ground: {{contact: false}}
damping: {{global: {}}}
objects:
  - mesh: {{polyline: {{points: [[0, 0, 0], [0, 0.6, 0.8]]}}}}
    material: {{density: 1200, youngs_modulus: 2.0e7, radius: 0.001}}
    pinned: {{indices: [0]}}
)";
  const Model undamped = build_model(test::scene_from_yaml(fmt::format(fmt::runtime(scene), 0)));
  const double omega = std::sqrt(2.0 * 2.0e7 / 1200.0);
  const double gamma = 0.5 * omega;  // ζ = ¼
  const Model damped = build_model(test::scene_from_yaml(fmt::format(fmt::runtime(scene), gamma)));
  const double zeta = gamma / (2 * omega);
  EXPECT_NEAR(critical_timestep(damped) / critical_timestep(undamped),
              std::sqrt(1 + zeta * zeta) - zeta, 1e-12);
}

TEST(Stability, LimitOfOneMassOnASpringIsExactlyTwoOverOmega) {
  // A pinned node and a free one: ω² = k/m = (EA/L) / (ρAL/2) = 2E/(ρL²) = 2 × 2e7 / 1200.
  const Model model =
      model_of("{polyline: {points: [[0, 0, 0], [0, 0.6, 0.8]]}}", "{indices: [0]}");
  const double omega = std::sqrt(2.0 * 2.0e7 / 1200.0);
  EXPECT_NEAR(critical_timestep(model) * omega, 2.0, 1e-12);
}

TEST(Stability, ExplicitStepAboveTheLimitIsRefusedWithBothNumbers) {
  const Model model =
      model_of("{polyline: {points: [[0, 0, 0], [1, 0, 0]], segments: 10}}", "{indices: [0]}");
  const double limit = critical_timestep(model);
  const FileLoc where{"scene.yaml", 5, 11};
  try {
    choose_timestep(model, 1.5 * limit, 20.0, where);
    FAIL() << "an unstable step was accepted";
  } catch (const UserError& e) {
    EXPECT_EQ(e.loc().line, 5);
    const std::string message = e.what();
    EXPECT_NE(message.find(fmt::format("{:.6g} s is above", 1.5 * limit)), std::string::npos)
        << message;
    EXPECT_NE(message.find(fmt::format("stability limit {:.6g} s", limit)), std::string::npos)
        << message;
  }
}

// A step given so short that a frame would take over 10⁸ of them is refused as the scene's own
// choice, with the shortest step that a run can take; nothing to stiffen (the implicit integrator
// takes any step).
TEST(Stability, AStepTooShortForAnyRunNamesTheStepGiven) {
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
integrator: implicit
timestep: 1.0e-300
objects:
  - mesh: {polyline: {points: [[0, 0, 1], [1, 0, 1]], segments: 4}}
    material: {density: 1000, youngs_modulus: 1.0e6, radius: 0.005}
)"));
  test::expect_user_error(
      [&] {
        choose_timestep(model, 1.0e-300, 20.0, {"scene.yaml", 4, 11});
      },
      4, {"the time step 1e-300 s would take", "at least 5e-10 s", "'timestep: auto'"});
}

TEST(Stability, ChosenStepFitsWholeStepsIntoEachFrame) {
  const Model model =
      model_of("{polyline: {points: [[0, 0, 0], [1, 0, 0]], segments: 10}}", "{indices: [0]}");
  const double limit = critical_timestep(model);
  const TimeStep automatic = choose_timestep(model, std::nullopt, 20.0, {});
  EXPECT_TRUE(automatic.automatic);
  EXPECT_LE(automatic.dt, kAutoTimestepSafety * limit);
  EXPECT_NEAR(automatic.dt * automatic.steps_per_frame, 1.0 / 20.0, 1e-15);

  // 0.05 s / 0.0005 s is 100 steps despite the rounding of both numbers.
  const Model soft =
      model_of("{polyline: {points: [[0, 0, 0], [1, 0, 0]], segments: 2}}", "{indices: [0]}");
  ASSERT_GT(critical_timestep(soft), 0.0005);
  const TimeStep explicit_step = choose_timestep(soft, 0.0005, 20.0, {});
  EXPECT_EQ(explicit_step.steps_per_frame, 100);
  EXPECT_DOUBLE_EQ(explicit_step.dt, 0.0005);
}

}  // namespace
}  // namespace dinam
