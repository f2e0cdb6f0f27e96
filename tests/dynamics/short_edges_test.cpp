// Short edges in a mesh: the default treatment (collapse below a tenth of the median bar, then a
// little mass on the nodes that are still too fast) keeps the step near that of the same mesh
// without them, and leaves the low natural frequencies, which carry the visible motion, within 1 %.
// The frequencies come from a dense eigen-solve of the real forces' stiffness (modal_support).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "dynamics/modal_support.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

constexpr int kCells = 16;     // a kCells × kCells plate of triangles, 1 m across
constexpr double kSide = 1.0;  // m
constexpr int kModesCompared = 6;

// An OBJ plate: a grid of triangles; in each cell of `split` the first triangle (a, b, c) gets an
// extra corner s inside it at `offset` × the cell size from a, so the face is (a, s, b, c) and
// a–s is a short bar.
std::filesystem::path write_plate(const std::filesystem::path& folder,
                                  const std::vector<std::pair<int, int>>& split, double offset) {
  const std::filesystem::path path = folder / "plate.obj";
  std::ofstream obj(path);
  const double h = kSide / kCells;
  auto id = [](int i, int j) { return j * (kCells + 1) + i + 1; };  // OBJ ids start at 1
  for (int j = 0; j <= kCells; ++j) {
    for (int i = 0; i <= kCells; ++i) {
      obj << "v " << i * h << ' ' << j * h << " 0\n";
    }
  }
  int next = (kCells + 1) * (kCells + 1) + 1;
  for (const auto& [i, j] : split) {
    // Inside the triangle (a, b, c) = ((i, j), (i+1, j), (i+1, j+1)), along its bisector at a.
    obj << "v " << (i + offset * 0.92388) * h << ' ' << (j + offset * 0.38268) * h << " 0\n";
  }
  for (int j = 0; j < kCells; ++j) {
    for (int i = 0; i < kCells; ++i) {
      const auto at = std::find(split.begin(), split.end(), std::pair{i, j});
      if (at != split.end()) {
        obj << "f " << id(i, j) << ' ' << next + (at - split.begin()) << ' ' << id(i + 1, j) << ' '
            << id(i + 1, j + 1) << '\n';
      } else {
        obj << "f " << id(i, j) << ' ' << id(i + 1, j) << ' ' << id(i + 1, j + 1) << '\n';
      }
      obj << "f " << id(i, j) << ' ' << id(i + 1, j + 1) << ' ' << id(i, j + 1) << '\n';
    }
  }
  return path;
}

// The plate held along its edge y = 0, without gravity or ground: a cantilevered sheet of stiff
// rubber. `mesh_keys` and `timestep` go into the scene as they are.
Model plate_model(const std::filesystem::path& obj, const std::string& mesh_keys,
                  const std::string& timestep) {
  return build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
gravity: [0, 0, 0]
ground: {{contact: false}}
timestep: {}
objects:
  - mesh: {{file: "{}"{}}}
    material: {{density: 1100, youngs_modulus: 5.0e7, radius: 0.004}}
    pinned: {{box: {{min: [-1, -1, -1], max: [2, 0.001, 1]}}}}
)",
                                                       timestep, obj.string(), mesh_keys)));
}

double stable_step(const Model& model) {
  return critical_timestep(model);
}

// The lowest `count` natural frequencies, rad/s.
std::vector<double> low_frequencies(const Model& model, int count) {
  const test::FreeDofs dofs = test::free_dofs(model);
  const Eigen::VectorXd squared =
      test::squared_frequencies(model, dofs, test::finite_difference_stiffness(model, dofs));
  std::vector<double> omega;
  for (int k = 0; k < count; ++k) {
    omega.push_back(std::sqrt(std::max(0.0, squared[k])));
  }
  return omega;
}

// Checks each frequency and records the largest relative change (in the XML report).
void expect_within(const std::vector<double>& actual, const std::vector<double>& expected,
                   double relative) {
  ASSERT_EQ(actual.size(), expected.size());
  double largest = 0.0;
  for (std::size_t k = 0; k < actual.size(); ++k) {
    EXPECT_NEAR(actual[k], expected[k], relative * expected[k]) << "mode " << k + 1;
    largest = std::max(largest, std::abs(actual[k] / expected[k] - 1.0));
  }
  testing::Test::RecordProperty("largest_frequency_change", fmt::format("{:.3g}", largest));
}

// Records a step against the reference's, for the report.
void record_step_ratio(const char* name, const Model& model, const Model& reference) {
  testing::Test::RecordProperty(
      name, fmt::format("{:.3g}", critical_timestep(model) / critical_timestep(reference)));
}

const std::vector<std::pair<int, int>> kSplitCells = {{3, 5}, {11, 9}, {7, 13}, {12, 3}};

TEST(ShortEdges, TinyEdgesAreCollapsedSoTheStepAndLowFrequenciesAreThoseOfTheCleanMesh) {
  const test::TemporaryFolder folder("tiny-edges");
  const std::filesystem::path clean = write_plate(folder.path(), {}, 0.0);
  const Model reference = plate_model(clean, "", "auto");
  const test::TemporaryFolder tiny_folder("tiny-edges-2");
  const std::filesystem::path tiny = write_plate(tiny_folder.path(), kSplitCells, 0.004);
  const Model treated = plate_model(tiny, "", "auto");
  const Model untreated = plate_model(tiny, ", weld: off", "{mass_scaling: false}");

  record_step_ratio("untreated_step_ratio", untreated, reference);
  record_step_ratio("treated_step_ratio", treated, reference);
  // Without treatment the four tiny edges set a step hundreds of times shorter.
  EXPECT_LT(stable_step(untreated), 0.01 * stable_step(reference));
  // With it: within 2× of the clean mesh's step, and its low frequencies within 1 %.
  EXPECT_GT(stable_step(treated), 0.5 * stable_step(reference));
  EXPECT_EQ(treated.mass_scaling.nodes, 0);
  expect_within(low_frequencies(treated, kModesCompared),
                low_frequencies(reference, kModesCompared), 0.01);
}

TEST(ShortEdges, ShortEdgesAboveTheCollapseTakeALittleMassAndKeepTheirLowFrequencies) {
  const test::TemporaryFolder folder("short-edges");
  const std::filesystem::path clean = write_plate(folder.path(), {}, 0.0);
  const Model reference = plate_model(clean, "", "auto");
  const test::TemporaryFolder short_folder("short-edges-2");
  const std::filesystem::path with_short = write_plate(short_folder.path(), kSplitCells, 0.3);
  const Model scaled = plate_model(with_short, "", "auto");
  const Model unscaled = plate_model(with_short, "", "{mass_scaling: false}");

  record_step_ratio("unscaled_step_ratio", unscaled, reference);
  record_step_ratio("scaled_step_ratio", scaled, reference);
  testing::Test::RecordProperty("added_mass_fraction",
                                fmt::format("{:.3g}", scaled.mass_scaling.added_fraction()));
  // The short bars (0.3 of a cell, above the collapse's tenth) are kept, and they shorten the
  // step; the default mass scaling takes it back to within 2× of the clean mesh's...
  EXPECT_LT(stable_step(unscaled), 0.5 * stable_step(reference));
  EXPECT_GT(stable_step(scaled), 0.5 * stable_step(reference));
  // ...adding at most its 2 % of the mass, on a few nodes only...
  EXPECT_GT(scaled.mass_scaling.nodes, 0);
  EXPECT_LE(scaled.mass_scaling.added_fraction(), kDefaultMaxAddedMass + 1e-12);
  EXPECT_LE(scaled.mass_scaling.nodes, 4 * static_cast<Index>(kSplitCells.size()));
  // ...so the low frequencies move by less than 1 %.
  expect_within(low_frequencies(scaled, kModesCompared), low_frequencies(unscaled, kModesCompared),
                0.01);
}

// The plate with short bars (0.15 of a cell) aimed at `max_steps` over its 1 s at 10 fps.
Model aimed_plate(const std::filesystem::path& obj, double max_steps) {
  return build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
fps: 10
gravity: [0, 0, 0]
ground: {{contact: false}}
timestep: {{max_steps: {}}}
objects:
  - mesh: {{file: "{}"}}
    material: {{density: 1100, youngs_modulus: 5.0e7, radius: 0.004}}
    pinned: {{box: {{min: [-1, -1, -1], max: [2, 0.001, 1]}}}}
)",
                                                       max_steps, obj.string())));
}

bool collapsed_some(const Model& model) {
  return std::any_of(model.warnings.begin(), model.warnings.end(),
                     [](const std::string& w) { return w.find("collapsed") != std::string::npos; });
}

TEST(ShortEdges, MaxStepsIsMetByMassScalingOrElseByCollapsingWithinTheLimit) {
  const test::TemporaryFolder folder("max-steps");
  const std::filesystem::path with_short = write_plate(folder.path(), kSplitCells, 0.15);
  const Model unaided = plate_model(with_short, "", "{mass_scaling: false}");
  const double unaided_steps = 10.0 * std::ceil(0.1 / (kAutoTimestepSafety * stable_step(unaided)));
  for (const double fewer : {1.5, 3.0}) {
    SCOPED_TRACE(fmt::format("{}× fewer steps", fewer));
    const double max_steps = std::floor(unaided_steps / fewer);
    const Model aimed = aimed_plate(with_short, max_steps);
    const TimeStep step = choose_timestep(aimed, std::nullopt, 10.0, {});
    EXPECT_LE(10.0 * step.steps_per_frame, max_steps);
    EXPECT_LE(aimed.mass_scaling.added_fraction(), kDefaultMaxAddedMass + 1e-12);
    // A modest aim is met by mass alone; three times fewer steps would take more than 2 % of
    // the mass, so the short bars are collapsed first.
    EXPECT_EQ(collapsed_some(aimed), fewer > 2.0);
  }
}

}  // namespace
}  // namespace dinam
