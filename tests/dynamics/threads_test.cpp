// The motion does not depend on the number of threads: each node receives its forces in one fixed
// order (kind by kind, springs in id order) whichever thread computes them (dynamics/
// work_split.hpp), so 1, 2 and 3 threads give the same state bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <fstream>
#include <string_view>
#include <type_traits>

#include "core/thread_team.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/parallel_loops.hpp"
#include "dynamics/stability.hpp"
#include "dynamics/state_arrays.hpp"
#include "dynamics/work_split.hpp"
#include "model/model.hpp"
#include "scene/scene_description.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// `steps` steps of the model at 0.8 × its limit on `threads` threads, the energy tracked; checks
// that the team's worker threads took part in every step (so that a comparison with one thread
// compares something).
State run_on_threads(const Model& model, int threads, int steps) {
  const int before = thread_count();
  set_thread_count(threads);
  EXPECT_EQ(thread_team().size(), threads);
  const double dt = 0.8 * critical_timestep(model);
  State state = initial_state(model, dt, {}, true);
  const std::uint64_t jobs_before = thread_team().worker_jobs();
  for (int s = 0; s < steps; ++s) {
    step(model, dt, {}, state);
  }
  EXPECT_GE(thread_team().worker_jobs() - jobs_before,
            static_cast<std::uint64_t>(steps) * static_cast<std::uint64_t>(threads - 1));
  set_thread_count(before);
  return state;
}

// A falling, yielding cloth held at one edge, of 120 × 120 cells (about 43 000 bars, more bending
// and torsion springs), big enough that every spring loop runs in parallel, with turbulent wind
// on its faces and on a rope's bars, global damping and ground contact (it falls 5 mm onto the
// ground in the first 30 steps or so).
// `integrator` is a top-level line to add ("integrator: xpbd").
Model falling_cloth(const std::string& breaking = "", const std::string& integrator = "") {
  Model model = build_model(test::scene_from_yaml(std::string(R"(version: 1
duration: 1
)") + integrator + R"(
wind: {velocity: [3, 0, 0], gust: {amplitude: 1}, turbulence: {amplitude: 1, scale: 0.3}}
ground: {height: 0.595}
damping: {global: 0.05}
objects:
  - name: cloth
    mesh:
      grid: {width: 1.2, height: 1.2, columns: 120, rows: 120, diagonals: one}
      translation: [0, 0, 0.6]
    material: {density: 1200, youngs_modulus: 2.0e7, radius: 0.001, yield_stress: 2.0e5)" +
                                                  breaking + R"(}
    pinned: {box: {min: [-1, -1, 0], max: [0.001, 2, 1]}}
    damping: {axial_ratio: 0.05}
    initial_velocity: [0, 0, -3]
  - name: rope
    mesh:
      polyline: {points: [[0, 0, 1.5], [1, 0, 1.5]], segments: 10}
    material: {density: 1200, youngs_modulus: 2.0e7, radius: 0.002)" +
                                                  breaking + R"(}
    pinned: {indices: [0]}
)"));
  EXPECT_GE(model.bar_count(), kMinParallelItems);
  EXPECT_GE(static_cast<Index>(model.wind.faces.size()), kMinParallelItems);
  EXPECT_EQ(model.wind.bars.size(), 10u);
  EXPECT_GE(model.bend_count(), kMinParallelItems);
  EXPECT_GE(model.torsion_count(), kMinParallelItems);
  return model;
}

State run_cloth(int threads, int steps, const std::string& breaking = "",
                const std::string& integrator = "") {
  return run_on_threads(falling_cloth(breaking, integrator), threads, steps);
}

// The element types of the state's arrays that same_value_bits compares.
template <class T>
constexpr bool kComparable =
    std::is_arithmetic_v<T> || std::is_base_of_v<Eigen::MatrixBase<T>, T> ||
    std::is_same_v<T, Box> || std::is_same_v<T, ContactCandidate> ||
    std::is_same_v<T, ContactPoint> || std::is_same_v<T, BarProjection>;

// Two values with the same bits, member by member for the structures the state holds (whose
// padding must not be read), doubles by their bits.
template <class T>
bool same_value_bits(const T& a, const T& b) {
  if constexpr (std::is_floating_point_v<T>) {
    return std::bit_cast<std::uint64_t>(static_cast<double>(a)) ==
           std::bit_cast<std::uint64_t>(static_cast<double>(b));
  } else if constexpr (std::is_arithmetic_v<T>) {
    return a == b;
  } else if constexpr (std::is_base_of_v<Eigen::MatrixBase<T>, T>) {
    for (Eigen::Index k = 0; k < a.size(); ++k) {
      if (!same_value_bits(a.data()[k], b.data()[k])) {
        return false;
      }
    }
    return true;
  } else if constexpr (std::is_same_v<T, Box>) {
    return same_value_bits(a.min, b.min) && same_value_bits(a.max, b.max);
  } else if constexpr (std::is_same_v<T, ContactCandidate>) {
    return a.key == b.key && a.nodes == b.nodes;
  } else if constexpr (std::is_same_v<T, BarProjection>) {
    return a.bar == b.bar && a.i == b.i && a.j == b.j && same_value_bits(a.wi, b.wi) &&
           same_value_bits(a.wj, b.wj) && same_value_bits(a.rest, b.rest) &&
           same_value_bits(a.compliance, b.compliance) && same_value_bits(a.gamma, b.gamma) &&
           same_value_bits(a.denominator, b.denominator);
  } else {
    static_assert(std::is_same_v<T, ContactPoint>);
    return a.features == b.features && a.key == b.key && a.nodes == b.nodes &&
           std::equal(a.weights.begin(), a.weights.end(), b.weights.begin(),
                      [](double p, double q) { return same_value_bits(p, q); }) &&
           same_value_bits(a.separation, b.separation) && same_value_bits(a.slip, b.slip) &&
           same_value_bits(a.energy, b.energy) && a.sliding == b.sliding;
  }
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(),
                    [](const T& p, const T& q) { return same_value_bits(p, q); });
}

// Every array of the state (state_arrays.hpp) but how the work was shared, and every energy
// account, bit for bit.
void expect_same_state(const State& a, const State& b) {
  int compared = 0;
  for_each_state_array(
      [&](std::string_view name, StateArrayRole role, const auto& in_a, const auto& in_b) {
        using Element = typename std::decay_t<decltype(in_a)>::value_type;
        if constexpr (kComparable<Element>) {
          if (role != StateArrayRole::kSharing) {
            EXPECT_TRUE(same_bits(in_a, in_b)) << name;
            ++compared;
          }
        } else {  // how the work was shared; any other array must be compared
          EXPECT_EQ(role, StateArrayRole::kSharing) << name << " holds elements not compared";
        }
      },
      a, b);
  EXPECT_GT(compared, 30);
  EXPECT_EQ(a.energy_workspace.last.total, b.energy_workspace.last.total);
  EXPECT_EQ(a.energy.wind_work, b.energy.wind_work);
  EXPECT_EQ(a.energy.field_work, b.energy.field_work);
  EXPECT_EQ(a.energy.plastic_dissipation, b.energy.plastic_dissipation);
}

TEST(Threads, OneAndTwoThreadsGiveTheSameStateBitForBit) {
  const State one = run_cloth(1, 60);
  const State two = run_cloth(2, 60);
  expect_same_state(one, two);
  // It did something: it moved, some springs flowed, the wind worked and the ground held.
  EXPECT_GT(one.energy.plastic_dissipation, 0.0);
  EXPECT_NE(one.energy.wind_work, 0.0);
  EXPECT_LT(one.energy.friction_work + one.energy.contact_damping_work, 0.0);
}

// Tearing too: which bars break, in which order, and everything after, is the same with 1 and 2
// threads (the check runs serially over the bars, and the forces it reads are bit-identical).
TEST(Threads, TearingIsTheSameForAnyThreadCount) {
  const std::string breaking = ", breaking: {force: 0.3}";
  const State one = run_cloth(1, 60, breaking);
  const State two = run_cloth(2, 60, breaking);
  EXPECT_GT(one.broken_bars.size(), 10u);                        // it tore
  EXPECT_LT(one.broken_bars.size(), one.bar_broken.size() / 2);  // but not to shreds
  expect_same_state(one, two);
}

// The bars held as constraints (`integrator: xpbd`): the leader projects them alone, so with the
// same cloth and rope, yielding (the bars inside the projection, the other springs explicit),
// tearing by the projection's tension and the energy ledger, 1 and 2 threads give the same bits.
TEST(Threads, TheBarsAsConstraintsAreTheSameForAnyThreadCount) {
  const std::string breaking = ", breaking: {force: 0.3}";
  const State one = run_cloth(1, 60, breaking, "integrator: xpbd\n");
  const State two = run_cloth(2, 60, breaking, "integrator: xpbd\n");
  EXPECT_GT(one.broken_bars.size(), 10u);  // it tore, by the projection's tension
  EXPECT_GT(one.energy.plastic_dissipation, 0.0);
  EXPECT_NE(one.energy.numerical_dissipation, 0.0);  // the projection's share, booked
  expect_same_state(one, two);
}

// A run's thread count may change between any two runs of steps (core/thread_governor.hpp, as
// the machine's load comes and goes): the state is the one of a single thread throughout, with
// tearing, and with the bars held as constraints.
TEST(Threads, ACountChangedBetweenRunsOfStepsLeavesTheSameState) {
  for (const std::string integrator : {"", "integrator: xpbd\n"}) {
    const Model model = falling_cloth(", breaking: {force: 0.3}", integrator);
    const State one = run_on_threads(model, 1, 60);
    EXPECT_GT(one.broken_bars.size(), 10u) << integrator;  // it tore
    const int before = thread_count();
    const double dt = 0.8 * critical_timestep(model);
    State changing = initial_state(model, dt, {}, true);
    const int counts[] = {2, 3, 1, 2, 1, 3};
    const int steps[] = {7, 13, 1, 20, 4, 15};  // 60 in all
    for (int run = 0; run < 6; ++run) {
      set_thread_count(counts[run]);
      advance_steps(model, dt, {}, changing, steps[run]);
    }
    set_thread_count(before);
    EXPECT_EQ(changing.step, 60);
    expect_same_state(one, changing);
  }
}

// Every kind that a worker evaluates for its own nodes only: clamps at a clamped support, a field
// on some nodes, a support shaken along a path, bending and torsion on a wire lattice, yielding,
// axial dampers and the energy ledger; on 3 threads, whose node ranges cut the lattice twice.
State run_clamped_lattice(int threads, int steps) {
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
forces:
  - {acceleration: [3, 0, 0], object: lattice, nodes: {box: {min: [-1, -1, 1.0], max: [2, 1, 2]}},
     profile: {type: ramp, start: 0, end: 0.01}}
objects:
  - name: lattice
    mesh:
      grid: {width: 1.0, height: 1.0, columns: 60, rows: 60, diagonals: none}
      rotation: [90, 0, 0]
      translation: [0, 0, 0.5]
    material: {density: 7850, youngs_modulus: 2.0e9, radius: 0.002, yield_stress: 2.0e6}
    damping: {axial_ratio: 0.02}
    pinned: {box: {min: [-1, -1, 0.499], max: [1, 1, 0.501]}, clamped: true}
    pin_motion: {displacement: [0.01, 0, 0], profile: {type: sine, frequency: 20}}
)"));
  EXPECT_GE(model.bar_count() + model.bend_count() + model.torsion_count(), kMinParallelItems);
  EXPECT_GT(model.clamp_count(), 0);
  EXPECT_GT(model.torsion_count(), 0);
  EXPECT_FALSE(model.pin_motions.empty());
  return run_on_threads(model, threads, steps);
}

TEST(Threads, ClampsFieldsShakenSupportsAndTorsionAreTheSameOnThreeThreads) {
  const State one = run_clamped_lattice(1, 80);
  const State three = run_clamped_lattice(3, 80);
  expect_same_state(one, three);
  // It did something: the shaken, pushed lattice yielded and the field worked on it.
  EXPECT_GT(one.energy.plastic_dissipation, 0.0);
  EXPECT_NE(one.energy.field_work, 0.0);
}

// advance_steps takes many steps in one job of the team: the same bits as one step at a time.
TEST(Threads, StepsTakenTogetherAreTheSameAsOneByOne) {
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
objects:
  - name: cloth
    mesh: {grid: {width: 1, height: 1, columns: 50, rows: 50, diagonals: one}, translation: [0, 0, 1]}
    material: {density: 1200, youngs_modulus: 2.0e7, radius: 0.001}
    pinned: {box: {min: [-1, -1, 0], max: [0.001, 2, 2]}}
)"));
  const int before = thread_count();
  set_thread_count(2);
  const double dt = 0.8 * critical_timestep(model);
  State together = initial_state(model, dt);
  State one_by_one = together;
  advance_steps(model, dt, {}, together, 37);
  for (int s = 0; s < 37; ++s) {
    step(model, dt, {}, one_by_one);
  }
  set_thread_count(before);
  EXPECT_EQ(together.step, 37);
  EXPECT_EQ(together.time, one_by_one.time);
  expect_same_state(together, one_by_one);
}

// Self-contact too: one object of two 46 × 46 sheets 5 mm apart, with contact radii of 3 mm, so
// that every node of one touches the other from the first step, pressed together. The sheets
// have more bars, nodes and candidate pairs than kMinParallelItems, so the search and the check
// run on both threads, each into its own list, joined in order; the pairs are summed serially in
// their features' order, so 1 and 2 threads give the same bits.
State run_two_sheets(int threads, int steps) {
  test::TemporaryFolder folder("sheets");
  constexpr int kCells = 46;
  std::string obj;
  for (int sheet = 0; sheet < 2; ++sheet) {
    for (int j = 0; j <= kCells; ++j) {
      for (int i = 0; i <= kCells; ++i) {
        obj += fmt::format("v {} {} {}\n", 0.01 * i, 0.01 * j, 0.5 + 0.005 * sheet);
      }
    }
  }
  const int per_sheet = (kCells + 1) * (kCells + 1);
  for (int sheet = 0; sheet < 2; ++sheet) {
    for (int j = 0; j < kCells; ++j) {
      for (int i = 0; i < kCells; ++i) {
        const int a = sheet * per_sheet + j * (kCells + 1) + i + 1;  // OBJ counts from 1
        obj += fmt::format("f {} {} {}\nf {} {} {}\n", a, a + 1, a + kCells + 2, a, a + kCells + 2,
                           a + kCells + 1);
      }
    }
  }
  std::ofstream(folder.path() / "sheets.obj") << obj;
  const Model model = build_model(read_scene_text(R"(version: 1
duration: 1
gravity: [0, 0, 0]
contact: {self: true}
objects:
  - name: sheets
    mesh: {file: sheets.obj}
    material: {density: 1200, youngs_modulus: 2.0e7, radius: 0.001}
    contact: {radius: 0.003}
    velocity_groups:
      - {nodes: {box: {min: [-1, -1, 0], max: [1, 1, 0.502]}}, velocity: [0.1, 0, 1]}
      - {nodes: {box: {min: [-1, -1, 0.503], max: [1, 1, 1]}}, velocity: [-0.1, 0, -1]}
)",
                                                  folder.path() / "sheets.yaml"));
  EXPECT_GE(model.bar_count(), kMinParallelItems);
  return run_on_threads(model, threads, steps);
}

TEST(Threads, SelfContactIsTheSameForAnyThreadCount) {
  const State one = run_two_sheets(1, 15);
  const State two = run_two_sheets(2, 15);
  // The sheets did touch, hard: the contacts' dampers took energy.
  EXPECT_LT(one.energy.contact_damping_work, -1e-3 * one.energy_workspace.last.kinetic);
  EXPECT_FALSE(one.object_contact.candidates.empty());  // compared below with the rest
  expect_same_state(one, two);
}

}  // namespace
}  // namespace dinam
