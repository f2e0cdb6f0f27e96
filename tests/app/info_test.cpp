// `dinam info`'s choice of integrator (estimate/integrator_choice.hpp): the implicit integrator
// where its estimate is under half of central differences', even ten times over for a free
// structure, which bench_implicit and bench/estimate_check.py confirm for the scenes used here
// (bench/notes/implicit-integrator.md, "Which integrator").
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "test_support.hpp"

namespace dinam {
namespace {

std::string recommendation(const test::CommandResult& info) {
  const std::string key = "recommended      integrator: ";
  const std::size_t at = info.output.find(key);
  if (at == std::string::npos) {
    return "";
  }
  const std::size_t from = at + key.size();
  return info.output.substr(from, info.output.find_first_of(" \n", from) - from);
}

// A steel cable of 100 bars swinging for 3 s: central differences need 2 million steps of 1.5 µs
// (5.4 s measured), the implicit integrator 288 of 1/96 s, 491 once split (0.48 s). It swings, so
// BDF2: backward Euler keeps 1/√(1 + ω²h²) of a mode's amplitude a step, 32 % a period at 16
// steps a period, and a 2 m cable's swing was damped away (its tip at z = 1.28 m at frame 72
// where central differences have it at 2.15 m), while BDF2 matched within 2 cm (issue 53).
constexpr const char* kSteelCable = R"(version: 1
duration: 3
ground: {contact: false}
objects:
  - name: cable
    mesh: {polyline: {points: [[0, 0, 2], [1, 0, 2]], segments: 100}}
    material: {density: 7850, youngs_modulus: 2.0e11, radius: 0.001}
    pinned: {indices: [0]}
)";

TEST(Info, RecommendsTheImplicitIntegratorForAStiffSteelCable) {
  test::TemporaryFolder folder("info");
  const auto scene = folder.path() / "cable.yaml";
  std::ofstream(scene) << kSteelCable;
  const test::CommandResult info = test::run_dinam({"info", scene.string()});
  ASSERT_EQ(info.exit_code, 0) << info.output;
  EXPECT_EQ(recommendation(info), "implicit_bdf2") << info.output;
  test::expect_contains(info.output, {"central_difference: 1995696 steps", "implicit: 288 steps",
                                      "BDF2 since the structure swings"});
}

// The paper's flag: 12 000 steps of central differences take 0.34 s, its implicit run 6.9 s; the
// bars as constraints would take 3 600 steps of 1.7 ms, but its soft cloth (E = 5 MPa: stretch
// waves of √(E/ρ) = 65 m/s) stretches as it flaps, which rigid bars would not show: central
// differences are kept.
TEST(Info, KeepsCentralDifferencesForThePapersFlag) {
  const test::CommandResult info =
      test::run_dinam({"info", std::string(DINAM_SOURCE_DIR) + "/scenes/flag.yaml"});
  ASSERT_EQ(info.exit_code, 0) << info.output;
  EXPECT_EQ(recommendation(info), "central_difference") << info.output;
  test::expect_contains(info.output, {"central_difference: 12000 steps", "xpbd: 3600 steps",
                                      "object 'flag' stretches visibly"});
}

// The shipped windy flag of cotton (stretch waves of 290 m/s, across it in 6 ms): its bars bound
// central differences' step at 66 µs, the shear springs the constraints' at 0.6 ms, and its run
// takes 0.16 of central differences' time with its mean within 1.1 cm (bench_stiff_threads).
TEST(Info, RecommendsTheBarsAsConstraintsForTheWindyCottonFlag) {
  const test::CommandResult info =
      test::run_dinam({"info", std::string(DINAM_SOURCE_DIR) + "/scenes/windy_flag.yaml"});
  ASSERT_EQ(info.exit_code, 0) << info.output;
  EXPECT_EQ(recommendation(info), "xpbd") << info.output;
  test::expect_contains(info.output, {"central_difference: 91200 steps", "xpbd: 9960 steps"});
}

// Asked for where it does not work, it is refused at the integrator's line: contact within an
// object (the shipped rope heap) kept a heap of rope moving where it should rest.
TEST(Info, RefusesTheBarsAsConstraintsWithContactWithinAnObject) {
  test::TemporaryFolder folder("info");
  const auto scene = folder.path() / "heap.yaml";
  std::ofstream(scene) << R"(version: 1
duration: 1
integrator: xpbd
contact: {self: true}
objects:
  - name: rope
    mesh: {polyline: {points: [[0, 0, 1], [1, 0, 1]], segments: 10}}
    material: {preset: hemp_rope}
)";
  const test::CommandResult info = test::run_dinam({"info", scene.string()});
  EXPECT_EQ(info.exit_code, 2) << info.output;
  test::expect_contains(info.output,
                        {"heap.yaml:3:13: error: 'integrator: xpbd'", "contact within an object"});
}

// The paper's ball thrown into the trampoline's net, contact between objects: the implicit
// integrator's steps count its speed envelope (thrown at 3.2 m/s, then a fall of 1.6 m: 8.8 m/s
// at most, where no node may move more than 2 mm a step: 17 668 steps at most, 5 844 taken in
// 17.5 s, against central differences' 6 s), so it is not recommended (the bars as constraints
// are: the net's rubber cords bound central differences' step).
TEST(Info, CountsTheContactsSpeedEnvelopeInTheImplicitEstimate) {
  const test::CommandResult info =
      test::run_dinam({"info", std::string(DINAM_SOURCE_DIR) + "/scenes/ball_in_net.yaml"});
  ASSERT_EQ(info.exit_code, 0) << info.output;
  EXPECT_EQ(recommendation(info).rfind("implicit", 0), std::string::npos) << info.output;
  test::expect_contains(info.output, {"contact between objects moves no node more than half"});
}

// And a 1 mm steel cable let fall onto a pinned steel bar, contact between objects too: central
// differences need some 814 700 steps of 1.2 µs (2.1 s measured), the implicit integrator 779 (0.24
// s; bench/notes/implicit-integrator.md). But nothing holds the cable: it lands and folds over the
// bar, and a free structure's implicit run may take ten times its estimate (the real-mesh sweep's
// did), which would lose here: central differences are recommended, the estimates still shown.
// The bars as constraints would be faster (78 288 steps), but where nothing holds a structure its
// landing on a ground softened for their step goes otherwise.
TEST(Info, KeepsCentralDifferencesForAFoldingCableOnABar) {
  test::TemporaryFolder folder("info");
  const auto scene = folder.path() / "drape.yaml";
  std::ofstream(scene) << R"(version: 1
duration: 1
contact: {objects: true}
ground: {contact: false}
objects:
  - name: bar
    mesh: {polyline: {points: [[0, -0.3, 0.5], [0, 0.3, 0.5]], segments: 6}}
    material: {density: 7850, youngs_modulus: 2.0e11, radius: 0.005}
    pinned: {all: true}
  - name: cable
    mesh: {polyline: {points: [[-0.5, 0, 0.511], [0.5, 0, 0.511]], segments: 100}}
    material: {density: 7850, youngs_modulus: 2.0e11, radius: 0.001}
)";
  const test::CommandResult info = test::run_dinam({"info", scene.string()});
  ASSERT_EQ(info.exit_code, 0) << info.output;
  EXPECT_EQ(recommendation(info), "central_difference") << info.output;
  test::expect_contains(info.output, {"central_difference: 814728 steps", "xpbd: 78288 steps",
                                      "implicit: ", "nothing holds the structure",
                                      "ten times their estimate", "'xpbd' would be faster"});
}

// `info` is the cheap command users run first: on a cloth of 190 000 bars it stays within an
// address space of 1 GB (it took 2 GB when it assembled the whole Hessian to size its factor;
// bench_info_cost has the figures at 10⁴ to 10⁶ bars). Not under the sanitizers, whose shadow
// memory no such limit admits.
TEST(Info, ALargeClothFitsInAGigabyte) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "the address sanitizer reserves terabytes of address space";
#endif
  test::TemporaryFolder folder("info-large");
  const auto scene = folder.path() / "cloth.yaml";
  std::ofstream(scene) << R"(version: 1
duration: 1
objects:
  - name: cloth
    mesh: {grid: {width: 1, height: 1, columns: 250, rows: 250, diagonals: one}}
    material: {density: 1200, youngs_modulus: 2.0e7, radius: 0.001}
    pinned: {box: {min: [-0.001, 0.999, -1], max: [1.001, 1.001, 1]}}
)";
  const test::CommandResult info = test::run_command(
      "ulimit -v 1000000 && " + test::dinam_command("info " + test::shell_quoted(scene)));
  ASSERT_EQ(info.exit_code, 0) << info.output;
  test::expect_contains(info.output, {"bars             188000", "integrators      "});
}

// info allocates beyond the model only within the memory budget: with too little for a run, no
// step is measured and no second model (central differences', for an implicit scene) is built;
// the estimates are still given, from counts.
TEST(Info, AllocatesNothingBeyondTheModelWhenTheBudgetHasNoRoom) {
  test::TemporaryFolder folder("info-budget");
  const auto scene = folder.path() / "cable.yaml";
  const std::string cable = kSteelCable;
  std::ofstream(scene) << cable;
  const test::CommandResult explicit_info =
      test::run_dinam({"info", scene.string()}, {"DINAM_MEMORY_LIMIT=1M"});
  ASSERT_EQ(explicit_info.exit_code, 0) << explicit_info.output;
  test::expect_contains(explicit_info.output,
                        {"measured now     not measured", "central_difference: 1995696 steps",
                         "implicit: 288 steps"});
  std::ofstream(scene) << test::replaced(cable, "duration: 3\n",
                                         "duration: 3\nintegrator: implicit\n");
  const test::CommandResult implicit_info =
      test::run_dinam({"info", scene.string()}, {"DINAM_MEMORY_LIMIT=1M"});
  ASSERT_EQ(implicit_info.exit_code, 0) << implicit_info.output;
  test::expect_contains(implicit_info.output,
                        {"(without the mass scaling that would lengthen them: no memory for its "
                         "model)",
                         "implicit: 288 steps"});
  // With room, the same scene's central differences are those of their own model.
  const test::CommandResult roomy = test::run_dinam({"info", scene.string()});
  ASSERT_EQ(roomy.exit_code, 0) << roomy.output;
  EXPECT_EQ(roomy.output.find("without the mass scaling"), std::string::npos) << roomy.output;
}

}  // namespace
}  // namespace dinam
