// `dinam modes` as solid as `render`: a scene whose settle relaxes settles with a relaxation step
// that suits it whatever its integrator, and motions that nothing resists (a body free to slide
// and turn on frictionless ground) are reported as such, not as an unstable equilibrium.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "test_support.hpp"

namespace dinam {
namespace {

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
