// `dinam modes` as solid as `render`, read through the table it prints: a scene whose settle
// relaxes settles with a relaxation step that suits it whatever its integrator; real sways are
// printed with their frequencies however stiff the stiffest bar (a hanging chain, the shipped
// tower, a slender steel beam on two hinges), and motions that nothing resists (a free body, a
// body free to slide and turn on frictionless ground) as "0 (free)", never as unstable.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace dinam {
namespace {

// One row of the printed table: its frequency column as printed ("0.59928", "0 (free)",
// "unstable") and its value where it is a number.
struct PrintedMode {
  std::string frequency;
  double hz = 0.0;
  bool free() const { return frequency == "0 (free)"; }
};

// The rows of the table `dinam modes` prints, in order; a test failure where a row is not
// numbered in sequence.
std::vector<PrintedMode> printed_table(const std::string& output) {
  std::vector<PrintedMode> rows;
  std::istringstream lines(output);
  std::string line;
  bool in_table = false;
  while (std::getline(lines, line)) {
    if (line.rfind("mode  frequency (Hz)", 0) == 0) {
      in_table = true;
      continue;
    }
    std::istringstream words(line);
    int number = 0;
    if (!in_table || !(words >> number)) {
      in_table = false;
      continue;
    }
    EXPECT_EQ(number, static_cast<int>(rows.size()) + 1) << line;
    PrintedMode row;
    words >> row.frequency;
    if (row.frequency == "0") {
      std::string rest;
      words >> rest;
      row.frequency += " " + rest;
    } else if (row.frequency != "unstable") {
      row.hz = std::stod(row.frequency);
    }
    rows.push_back(row);
  }
  return rows;
}

std::vector<PrintedMode> modes_of(const test::TemporaryFolder& folder, const std::string& yaml,
                                  int count) {
  const auto scene = folder.path() / "scene.yaml";
  std::ofstream(scene) << yaml;
  const test::CommandResult modes =
      test::run_dinam({"modes", scene.string(), "-o", (folder.path() / "modes").string(), "--count",
                       std::to_string(count)});
  EXPECT_EQ(modes.exit_code, 0) << modes.output;
  std::vector<PrintedMode> rows = printed_table(modes.output);
  EXPECT_EQ(rows.size(), static_cast<std::size_t>(count)) << modes.output;
  rows.resize(static_cast<std::size_t>(count));
  return rows;
}

// A 1 m `chain` hanging from a pin sways as the hanging chain: f_n = (j₀,ₙ / 2) √(g/L) / 2π, each
// twice (in x and in y). 40 links put the third mode within 1 % (the discrete chain's error grows
// as (n/N)², the chain's little bending stiffness adds less); its stiff links (ω_max² near 1e11)
// once pushed every row under the table's round-off and printed it "0 (free)".
TEST(ModesCommand, AHangingChainPrintsTheChainsFrequencies) {
  const test::TemporaryFolder folder("modes");
  const std::vector<PrintedMode> rows = modes_of(folder, R"(version: 1
duration: 0.1
ground: {contact: false, visible: false}
objects:
  - name: chain
    mesh: {polyline: {points: [[0, 0, 2], [0, 0, 1]], segments: 40}}
    material: {preset: chain}
    pinned: {indices: [0]}
)",
                                                 6);
  const std::array<double, 3> zeros = {2.404826, 5.520078, 8.653728};  // of J₀
  for (int n = 0; n < 3; ++n) {
    const double expected = zeros[n] / 2.0 * std::sqrt(9.81 / 1.0) / (2.0 * std::numbers::pi);
    for (const int row : {2 * n, 2 * n + 1}) {
      EXPECT_NEAR(rows[row].hz, expected, 0.01 * expected) << "row " << row + 1;
    }
  }
}

// The shipped tower on its table: its two sways (y, then x) at the frequencies docs/commands.md
// shows, 0.38636 and 0.38718 Hz (its scene drives the table at the second), nothing free: its
// base is pinned at four corners.
TEST(ModesCommand, TheShippedTowerPrintsItsTwoSways) {
  const test::TemporaryFolder folder("modes");
  const test::CommandResult modes = test::run_dinam(
      {"modes", (std::filesystem::path(DINAM_SOURCE_DIR) / "scenes/shaken_tower.yaml").string(),
       "-o", (folder.path() / "modes").string(), "--count", "3"});
  ASSERT_EQ(modes.exit_code, 0) << modes.output;
  const std::vector<PrintedMode> rows = printed_table(modes.output);
  ASSERT_EQ(rows.size(), 3u) << modes.output;
  EXPECT_EQ(rows[0].frequency, "0.38636") << modes.output;
  EXPECT_EQ(rows[1].frequency, "0.38718") << modes.output;
}

// A slender steel beam on a hinge at each end (2 m, 5 mm radius, 80 bars): its first mode first,
// at Euler–Bernoulli's f₁ = (π / 2L²) √(EI / ρA) = 4.95 Hz, then f₂ = 4 f₁. Nothing is free: the
// turn about its own line moves none of its nodes. With ω_max² near 1.6e11 the old round-off
// (1e-7 of it) took the first mode (ω² 968) for a free motion and printed the second first.
TEST(ModesCommand, AHingedBeamPrintsItsFirstModeFirst) {
  const test::TemporaryFolder folder("modes");
  const std::vector<PrintedMode> rows = modes_of(folder, R"(version: 1
duration: 0.1
gravity: [0, 0, 0]
ground: {contact: false, visible: false}
objects:
  - name: beam
    mesh: {polyline: {points: [[0, 0, 1], [2, 0, 1]], segments: 80}}
    material: {density: 7850, youngs_modulus: 2.0e11, radius: 0.005}
    pinned: {indices: [0, 80]}
)",
                                                 4);
  const double radius = 0.005;
  const double ei = 2.0e11 * std::numbers::pi * std::pow(radius, 4) / 4.0;
  const double rho_a = 7850.0 * std::numbers::pi * radius * radius;
  const double f1 = std::numbers::pi / (2.0 * 2.0 * 2.0) * std::sqrt(ei / rho_a);
  // Lumped masses and springs: second order, (π/80)² ≈ 0.15 % for the first mode, 0.6 % for
  // the second; 1 % holds both.
  for (const int row : {0, 1}) {
    EXPECT_FALSE(rows[row].free()) << "row " << row + 1;
    EXPECT_NEAR(rows[row].hz, f1, 0.01 * f1) << "row " << row + 1;
  }
  for (const int row : {2, 3}) {
    EXPECT_NEAR(rows[row].hz, 4.0 * f1, 0.01 * 4.0 * f1) << "row " << row + 1;
  }
}

// A tetrahedron of bars floating without gravity: six free motions (three slides, three turns),
// then its real vibrations, the lowest well above zero.
TEST(ModesCommand, AFreeBodyHasSixFreeMotions) {
  const test::TemporaryFolder folder("modes");
  const std::vector<PrintedMode> rows = modes_of(
      folder,
      "version: 1\nduration: 1\ngravity: [0, 0, 0]\nground: {contact: false}\nobjects:\n  - "
      "name: frame\n    mesh: {file: " +
          (test::data_dir() / "tetra.ply").string() +
          "}\n    material: {density: 7850, youngs_modulus: 2.0e11, radius: 0.01}\n",
      8);
  for (int row = 0; row < 6; ++row) {
    EXPECT_TRUE(rows[row].free()) << "row " << row + 1 << ": " << rows[row].frequency;
  }
  for (int row = 6; row < 8; ++row) {
    EXPECT_FALSE(rows[row].free()) << "row " << row + 1;
    EXPECT_GT(rows[row].hz, 1.0) << "row " << row + 1;
  }
}

// A clamped cantilever that settles by relaxation, under the implicit integrator (whose quarter
// frame the relaxation once took, and diverged with).
TEST(ModesCommand, AnImplicitSceneThatRelaxesSettles) {
  const test::TemporaryFolder folder("modes");
  const auto scene = folder.path() / "cantilever.yaml";
  std::ofstream(scene) << R"(version: 1
duration: 1
integrator: implicit
settle: {method: relax}
ground: {contact: false}
objects:
  - name: cantilever
    mesh: {polyline: {points: [[0, 0, 1], [0.5, 0, 1]], segments: 10}}
    material: {density: 1000, youngs_modulus: 1.0e8, radius: 0.005}
    pinned: {indices: [0], clamped: true}
)";
  const test::CommandResult modes = test::run_dinam(
      {"modes", scene.string(), "-o", (folder.path() / "modes").string(), "--count", "4"});
  ASSERT_EQ(modes.exit_code, 0) << modes.output;
  test::expect_contains(modes.output, {"settled under gravity", "mode  frequency (Hz)"});
}

// A tetrahedron of bars on ground without friction: it can slide in x and y and turn about z
// (three motions of ω² = 0, within round-off), and its bars hold its shape.
TEST(ModesCommand, MotionsNothingResistsAreFreeNotUnstable) {
  const test::TemporaryFolder folder("modes");
  const auto scene = folder.path() / "tetra.yaml";
  std::ofstream(scene) << "version: 1\nduration: 1\nground: {friction: {static: 0, kinetic: "
                          "0}}\nobjects:\n  - name: frame\n    mesh: {file: "
                       << (test::data_dir() / "tetra.ply").string()
                       << "}\n    material: {density: 1000, youngs_modulus: 1.0e7, radius: "
                          "0.01}\n";
  const test::CommandResult modes = test::run_dinam(
      {"modes", scene.string(), "-o", (folder.path() / "modes").string(), "--count", "6"});
  ASSERT_EQ(modes.exit_code, 0) << modes.output;
  EXPECT_EQ(modes.output.find("unstable"), std::string::npos) << modes.output;
  int free_motions = 0;
  for (std::size_t at = modes.output.find("0 (free)"); at != std::string::npos;
       at = modes.output.find("0 (free)", at + 1)) {
    ++free_motions;
  }
  EXPECT_EQ(free_motions, 3) << modes.output;
}

}  // namespace
}  // namespace dinam

namespace dinam {
namespace {

// A structure with nothing free to vibrate (a collider alone) is told at the scene file, exit 2,
// with what to change.
TEST(ModesCommand, NothingFreeIsToldAtTheSceneFile) {
  const test::TemporaryFolder folder("modes");
  const auto scene = folder.path() / "post.yaml";
  std::ofstream(scene) << R"(version: 1
duration: 1
objects:
  - name: post
    mesh: {polyline: {points: [[0, 0, 0], [0, 0, 1]], segments: 4}}
    role: collider
)";
  const test::CommandResult modes =
      test::run_dinam({"modes", scene.string(), "-o", (folder.path() / "modes").string()});
  EXPECT_EQ(modes.exit_code, 2) << modes.output;
  test::expect_contains(modes.output,
                        {scene.string() + ": error: every node is pinned", "'pinned'"});
}

}  // namespace
}  // namespace dinam
