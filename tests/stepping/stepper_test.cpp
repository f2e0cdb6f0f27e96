// The steppers behind their one interface (stepping/stepper.hpp, stepper_kind.hpp): each kind
// builds its own stepper, and the velocity each reports between steps is the motion's own.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "dynamics/integrator.hpp"
#include "model/model.hpp"
#include "solver/implicit_newton.hpp"
#include "stepping/central_difference_stepper.hpp"
#include "stepping/implicit_stepper.hpp"
#include "stepping/stepper_kind.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

Model with_integrator(const std::string& integrator, const std::string& rest) {
  return build_model(
      test::scene_from_yaml(fmt::format("version: 1\nintegrator: {}\n{}", integrator, rest)));
}

// A wire falling freely (no ground, no damping), thrown sideways: a uniform translation that
// strains no spring, so every node's velocity is v_0 + g t at every step. Leapfrog is exact for a
// constant acceleration, and so are backward Euler (v_{n+1} = v_n + h g) and BDF2 (exact for
// polynomials of degree 2 in x); what is left is rounding and, for the implicit schemes, what
// Newton's method leaves: it stops once no node is out of balance by more than
// kConvergedAcceleration, a velocity error of at most h × that a step.
constexpr const char* kFreeFall = R"(duration: 1
fps: 20
ground: {contact: false, visible: false}
objects:
  - name: wire
    mesh: {polyline: {points: [[0, 0, 1], [1, 0, 1]], segments: 8}}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.002}
    initial_velocity: [0.5, 0, 2]
)";

TEST(Stepper, TheVelocityNowIsTheFreeFallsOwnForEveryIntegrator) {
  for (const std::string integrator : {"central_difference", "implicit", "implicit_bdf2"}) {
    SCOPED_TRACE(integrator);
    const Model model = with_integrator(integrator, kFreeFall);
    const TimeStep timestep = choose_timestep(model, std::nullopt, 20.0, {});
    const std::unique_ptr<Stepper> stepper = stepper_kind(model).make_stepper(model, timestep);
    const bool implicit = &stepper_kind(model) == &kImplicitSchemes;
    State state = stepper->start(false, Settling::kSkip);
    std::vector<Vec3> v;
    for (int frame = 0; frame < 10; ++frame) {
      stepper->velocity_now(state, v);
      const Vec3 expected = Vec3(0.5, 0, 2) + state.time * Vec3(0, 0, -9.81);
      ASSERT_EQ(v.size(), model.node_count());
      // Central differences: 1e-9 m/s, far above rounding over a thousand steps (1e-13), far
      // below half a step's change of velocity (g Δt / 2 ≥ 1e-4 m/s here). The implicit schemes:
      // Newton's tolerance summed over the steps taken (at most 5e-3 m/s), still well below half
      // a step's change (0.06 m/s), so a velocity half a step off fails either way.
      const double tolerance = implicit ? kConvergedAcceleration * state.time + 1e-9 : 1e-9;
      for (const Vec3& node : v) {
        EXPECT_LT((node - expected).norm(), tolerance) << "at t = " << state.time;
      }
      stepper->advance(state, timestep.steps_per_frame);
    }
    EXPECT_NEAR(state.time, 0.5, 1e-12);
  }
}

// Central differences find v_n from the forces at x_n; asking for it between steps changes
// nothing of the motion that follows (bit for bit), with every force kind, contact between
// objects and tearing at once.
TEST(Stepper, AskingTheVelocityLeavesCentralDifferencesMotionAsItWas) {
  const Model model = with_integrator("central_difference", R"(duration: 1
damping: {global: 0.1}
wind: {velocity: [3, 0, 0], turbulence: {amplitude: 1}}
ground: {height: 0.2}
contact: {objects: true, self: true}
forces:
  - {acceleration: [0, 2, 0], object: cloth, profile: {type: ramp, start: 0, end: 1}}
objects:
  - name: cloth
    mesh:
      grid: {width: 1.0, height: 1.0, columns: 8, rows: 8, diagonals: one}
      translation: [0, 0, 0.5]
    material: {density: 1200, youngs_modulus: 2.0e7, radius: 0.002, yield_stress: 2.0e5,
               breaking: {strain: 0.02}}
    pinned: {box: {min: [-1, -1, 0], max: [0.001, 2, 1]}}
    damping: {axial_ratio: 0.05}
    initial_velocity: [0, 0, -3]
  - name: rope
    mesh:
      polyline: {points: [[0.2, 0.3, 0.53], [0.9, 0.3, 0.53]], segments: 10}
    material: {density: 1200, youngs_modulus: 2.0e7, radius: 0.004}
)");
  const TimeStep timestep = choose_timestep(model, std::nullopt, 24.0, {});
  const std::unique_ptr<Stepper> plain = stepper_kind(model).make_stepper(model, timestep);
  const std::unique_ptr<Stepper> asked = stepper_kind(model).make_stepper(model, timestep);
  State a = plain->start(true);
  State b = asked->start(true);
  std::vector<Vec3> v;
  for (int k = 0; k < 40; ++k) {
    plain->advance(a, 25);
    asked->velocity_now(b, v);
    asked->advance(b, 25);
  }
  ASSERT_EQ(a.x.size(), b.x.size());
  for (std::size_t i = 0; i < a.x.size(); ++i) {
    ASSERT_EQ(a.x[i], b.x[i]) << "node " << i;
    ASSERT_EQ(a.velocity[i], b.velocity[i]) << "node " << i;
  }
  EXPECT_EQ(a.energy_workspace.last.total, b.energy_workspace.last.total);
  // The scene did what it is here for: the cloth met the rope and the ground.
  EXPECT_FALSE(b.object_contact.previous.empty());
}

// Each kind builds its own stepper, and the scene's `integrator` picks the kind.
TEST(Stepper, EachIntegratorBuildsItsOwnStepper) {
  const Model explicit_model = with_integrator("central_difference", kFreeFall);
  const Model implicit_model = with_integrator("implicit_bdf2", kFreeFall);
  EXPECT_EQ(&stepper_kind(explicit_model), &kCentralDifferences);
  EXPECT_EQ(&stepper_kind(implicit_model), &kImplicitSchemes);
  const TimeStep step = choose_timestep(implicit_model, std::nullopt, 20.0, {});
  EXPECT_NE(
      dynamic_cast<ImplicitStepper*>(kImplicitSchemes.make_stepper(implicit_model, step).get()),
      nullptr);
  EXPECT_NE(dynamic_cast<CentralDifferenceStepper*>(
                kCentralDifferences.make_stepper(explicit_model, step).get()),
            nullptr);
  // A quarter of a frame for the implicit schemes; central differences' own bound otherwise.
  EXPECT_DOUBLE_EQ(step.dt, 1.0 / 80.0);
  EXPECT_LE(choose_timestep(explicit_model, std::nullopt, 20.0, {}).dt,
            critical_timestep(explicit_model));
}

}  // namespace
}  // namespace dinam
