// A step allocates nothing: every array it needs exists from initial_state on. Counted through
// the global operator new, which this test program (and only it) replaces.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "dynamics/integrator.hpp"
#include "dynamics/parallel_loops.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "stepping/implicit_stepper.hpp"
#include "stepping/stepper_kind.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"

namespace {
std::atomic<long> allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* memory = std::malloc(size == 0 ? 1 : size)) {
    return memory;
  }
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
  return operator new(size);
}
void operator delete(void* memory) noexcept {
  std::free(memory);
}
void operator delete[](void* memory) noexcept {
  std::free(memory);
}
void operator delete(void* memory, std::size_t) noexcept {
  std::free(memory);
}
void operator delete[](void* memory, std::size_t) noexcept {
  std::free(memory);
}

namespace dinam {
namespace {

// Allocations made by `steps` steps after a few to warm up (OpenMP's thread pool starts then).
long allocations_in_steps(const Model& model, bool track_energy, int steps) {
  const double dt = 0.8 * critical_timestep(model);
  State state = initial_state(model, dt, {}, track_energy);
  for (int s = 0; s < 5; ++s) {
    step(model, dt, {}, state);
  }
  const long before = allocations.load();
  for (int s = 0; s < steps; ++s) {
    step(model, dt, {}, state);
  }
  return allocations.load() - before;
}

// Every kind of force at once: fields, wind on faces and bars, yielding axial, bending and
// torsion springs, dampers, global damping and the ground; small (serial loops) and large
// (parallel loops), with and without the energy report.
// `integrator` a top-level line ("integrator: xpbd").
Model every_force(int cells, const std::string& integrator = "") {
  return build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
{1}
damping: {{global: 0.1}}
wind: {{velocity: [3, 0, 0], turbulence: {{amplitude: 1}}}}
ground: {{height: 0.5}}
forces:
  - {{acceleration: [0, 2, 0], object: cloth, profile: {{type: ramp, start: 0, end: 1}}}}
objects:
  - name: cloth
    mesh:
      grid: {{width: 1.2, height: 1.2, columns: {0}, rows: {0}, diagonals: one}}
      translation: [0, 0, 0.6]
    material: {{density: 1200, youngs_modulus: 2.0e7, radius: 0.001, yield_stress: 2.0e5}}
    pinned: {{box: {{min: [-1, -1, 0], max: [0.001, 2, 1]}}}}
    damping: {{axial_ratio: 0.05}}
    initial_velocity: [0, 0, -3]
  - name: rope
    mesh:
      polyline: {{points: [[0, 0, 1.5], [1, 0, 1.5]], segments: 10}}
    material: {{density: 1200, youngs_modulus: 2.0e7, radius: 0.002}}
    pinned: {{indices: [0]}}
)",
                                                       cells, integrator)));
}

TEST(StepAllocation, AStepAllocatesNothing) {
  const Model small = every_force(10);
  EXPECT_EQ(allocations_in_steps(small, false, 50), 0);
  EXPECT_EQ(allocations_in_steps(small, true, 50), 0);
  const Model large = every_force(80);
  ASSERT_GE(large.bend_count(), kMinParallelItems);  // its spring loops run in parallel
  EXPECT_EQ(allocations_in_steps(large, false, 5), 0);
  EXPECT_EQ(allocations_in_steps(large, true, 5), 0);
}

// The same with the bars held as constraints: the projection's records are made with the state
// and filled in place, its sweeps and the energy its work is booked as allocate nothing.
TEST(StepAllocation, AStepWithTheBarsAsConstraintsAllocatesNothing) {
  const Model small = every_force(10, "integrator: xpbd");
  ASSERT_TRUE(small.bars_are_constraints());
  EXPECT_EQ(allocations_in_steps(small, false, 50), 0);
  EXPECT_EQ(allocations_in_steps(small, true, 50), 0);
  const Model large = every_force(80, "integrator: xpbd");
  EXPECT_EQ(allocations_in_steps(large, false, 5), 0);
  EXPECT_EQ(allocations_in_steps(large, true, 5), 0);
}

// Contact between objects and within one: once the pair buffers have grown (in the warm-up
// steps), steps that keep finding the same pairs allocate nothing. Two wires pressed across each
// other in a cloth with self-contact, resting on a pinned sheet.
TEST(StepAllocation, ContactAllocatesNothingOnceItsBuffersHaveGrown) {
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
gravity: [0, 0, -9.81]
contact: {objects: true, self: true}
objects:
  - name: table
    mesh: {grid: {width: 1, height: 1, columns: 4, rows: 4}}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.003}
    pinned: {all: true}
  - name: sticks
    mesh: {polyline: {points: [[0.2, 0.3, 0.0055], [0.7, 0.3, 0.0055]], segments: 5}}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.0025}
)"));
  for (const bool track_energy : {false, true}) {
    EXPECT_EQ(allocations_in_steps(model, track_energy, 50), 0);
  }
  // It did touch: the sticks rest on the table rather than falling through it.
  const double dt = 0.8 * critical_timestep(model);
  State state = initial_state(model, dt);
  for (int s = 0; s < 50; ++s) {
    step(model, dt, {}, state);
  }
  EXPECT_GT(state.object_contact.previous.size(), 3u);
}

// The implicit schemes: once the first steps have sized the workspace, factorised the Hessian
// and met the ground, a step allocates nothing either, its refactorisations included (they refill
// the pattern the first one built). Every scheme, with and without the energy report, on a cloth
// that flaps in the wind with every force kind, and on one that lies on the ground (its friction
// springs the same from step to step: a node that lands or leaves grows them, as a new pair does
// contact's buffers).
struct ImplicitSteps {
  long allocations = 0;
  std::int64_t factorizations = 0;  // of the Hessian, within the steps counted
  long on_ground = 0;               // nodes touching the ground at their end
};

ImplicitSteps implicit_steps(const std::string& yaml, ImplicitScheme scheme, bool track_energy) {
  SceneDescription scene = test::scene_from_yaml(yaml);
  scene.integrator = IntegratorKind::kImplicit;
  scene.implicit_scheme = scheme;
  const Model model = build_model(scene);
  const TimeStep timestep = choose_timestep(model, std::nullopt, scene.fps, {});
  const std::unique_ptr<Stepper> stepper = stepper_kind(model).make_stepper(model, timestep);
  const auto& implicit = dynamic_cast<const ImplicitStepper&>(*stepper);
  State state = stepper->start(track_energy);
  stepper->advance(state, 5);
  const std::int64_t factorizations = implicit.stats().factorizations;
  const long before = allocations.load();
  stepper->advance(state, 20);
  ImplicitSteps steps;
  steps.allocations = allocations.load() - before;
  steps.factorizations = implicit.stats().factorizations - factorizations;
  steps.on_ground = std::count(state.contact_touching.begin(), state.contact_touching.end(), 1);
  return steps;
}

TEST(StepAllocation, AnImplicitStepAllocatesNothing) {
  const std::string flapping = R"(version: 1
duration: 2
fps: 20
damping: {global: 0.1}
wind: {velocity: [3, 0, 0], turbulence: {amplitude: 1}}
ground: {height: -5}
forces:
  - {acceleration: [0, 2, 0], object: cloth, profile: {type: ramp, start: 0, end: 1}}
objects:
  - name: cloth
    mesh:
      grid: {width: 1.2, height: 1.2, columns: 12, rows: 12, diagonals: one}
      rotation: [90, 0, 0]
    material: {density: 1200, youngs_modulus: 2.0e7, radius: 0.001, yield_stress: 2.0e5}
    pinned: {box: {min: [-1, -1, -1], max: [0.001, 2, 1]}}
    damping: {axial_ratio: 0.05}
)";
  const std::string lying = R"(version: 1
duration: 2
fps: 20
objects:
  - name: cloth
    mesh:
      grid: {width: 1.2, height: 1.2, columns: 12, rows: 12, diagonals: one}
      translation: [0, 0, 0.001]
    material: {density: 1200, youngs_modulus: 2.0e7, radius: 0.001}
    damping: {axial_ratio: 0.05}
)";
  for (const ImplicitScheme scheme : {ImplicitScheme::kBackwardEuler, ImplicitScheme::kBdf2}) {
    for (const bool track_energy : {false, true}) {
      const std::string what =
          fmt::format("scheme {}, energy {}", static_cast<int>(scheme), track_energy);
      const ImplicitSteps flapped = implicit_steps(flapping, scheme, track_energy);
      EXPECT_EQ(flapped.allocations, 0) << what;
      EXPECT_GT(flapped.factorizations, 0) << what;  // refactorisations were counted too
      const ImplicitSteps lay = implicit_steps(lying, scheme, track_energy);
      EXPECT_EQ(lay.allocations, 0) << what;
      EXPECT_EQ(lay.on_ground, 13 * 13) << what;  // every node held by its friction springs
    }
  }
}

// The counter itself works: a vector that grows is seen.
TEST(StepAllocation, TheCounterSeesAnAllocation) {
  const long before = allocations.load();
  std::vector<double> grown(100);
  EXPECT_GT(allocations.load(), before);
}

}  // namespace
}  // namespace dinam
