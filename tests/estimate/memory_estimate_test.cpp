// The memory estimate against what a run really holds (its peak resident memory, from the
// kernel), and the refusal of a run that would not fit.
#include "estimate/memory_estimate.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <cstdint>
#include <fstream>
#include <regex>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "dynamics/integrator.hpp"
#include "dynamics/state_arrays.hpp"
#include "model/model.hpp"
#include "model/model_arrays.hpp"
#include "test_support.hpp"

extern char** environ;

namespace dinam {
namespace {

// A cloth of cells × cells, 120 frames drawn at width × height.
std::string cloth_scene(int cells, int width = 320, int height = 180,
                        const std::string& look = "") {
  return "version: 1\n"
         "name: cloth\n"
         "duration: 0.5\n"
         "fps: 240\n"
         "timestep: auto\n"
         "gravity: [0, 0, -9.81]\n"
         "camera: {position: [3, -4, 3], look_at: [1, 1, 0], fov: 45}\n"
         "image: {width: " +
         std::to_string(width) + ", height: " + std::to_string(height) + look +
         "}\n"
         "objects:\n"
         "  - name: cloth\n"
         "    mesh:\n"
         "      grid: {width: 2.0, height: 2.0, columns: " +
         std::to_string(cells) + ", rows: " + std::to_string(cells) +
         ", diagonals: one}\n"
         "    material: {density: 1000, youngs_modulus: 1.0e4, radius: 0.001}\n"
         "    pinned: {indices: [0, " +
         std::to_string(cells) + "]}\n";
}

struct PeakRun {
  int exit_code = -1;
  double peak_bytes = 0.0;  // the child's largest resident set
};

// Runs dinam with `arguments` (output to /dev/null) and reads its peak resident memory.
PeakRun run_measured(const std::vector<std::string>& arguments) {
  const test::DinamArgv argv(arguments);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  EXPECT_EQ(posix_spawn(&pid, DINAM_PROGRAM, &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  PeakRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.peak_bytes = static_cast<double>(usage.ru_maxrss) * 1024.0;  // kilobytes on Linux
  return run;
}

// A figure of `dinam info --json`: "memory_render_bytes" ("memory, render   about 366 MB: …") or
// "memory_simulate_bytes".
double estimated_bytes(const std::filesystem::path& scene,
                       const std::string& figure = "memory_render_bytes") {
  const test::CommandResult info =
      test::run_command(std::string(DINAM_PROGRAM) + " info --json '" + scene.string() + "'");
  const std::regex pattern("\"" + figure + "\": (\\d+)");
  std::smatch match;
  EXPECT_TRUE(std::regex_search(info.output, match, pattern)) << info.output;
  return match.empty() ? 0.0 : std::stod(match[1].str());
}

bool sanitized_build() {
#if defined(__SANITIZE_ADDRESS__)
  return true;
#else
  return false;
#endif
}

// A scene with every kind of array: clamps, tearing, yielding, turbulent wind, the ground and
// contact within the cloth.
constexpr const char* kEveryArrayScene = R"(version: 1
duration: 0.1
wind: {velocity: [3, 0, 0], turbulence: {amplitude: 1, scale: 0.3}}
contact: {self: true}
objects:
  - name: cloth
    mesh:
      grid: {width: 1, height: 1, columns: 12, rows: 12, diagonals: one}
      translation: [0, 0, 0.6]
    material: {density: 1200, youngs_modulus: 2.0e7, radius: 0.001, yield_stress: 2.0e5,
               breaking: {strain: 0.5}}
    pinned: {box: {min: [-1, -1, 0], max: [0.001, 2, 1]}, clamped: true}
)";

// Every array the builder made holds what it needs and no more: the list of arrays
// (model_arrays.hpp) reaches all of them, so none keeps the spare capacity of its growth.
TEST(ModelArrays, NoArrayOfABuiltModelKeepsSpareCapacity) {
  const Model model = build_model(test::scene_from_yaml(kEveryArrayScene));
  ASSERT_GT(model.clamp_count(), 0);
  ASSERT_TRUE(model.can_tear());
  ASSERT_TRUE(model.bars_yield);
  ASSERT_TRUE(model.contact.enabled);
  ASSERT_TRUE(model.ground.enabled);
  ASSERT_FALSE(model.wind.faces.empty());
  int arrays = 0;
  for_each_model_array(model, [&](std::string_view name, const auto& array) {
    EXPECT_EQ(array.capacity(), array.size()) << name;
    ++arrays;
  });
  EXPECT_GE(arrays, 50);
}

// The bytes the state make_state allocates for `model` hold, array by array summed, against the
// estimate, with and without the energy ledger.
void expect_state_estimate_holds(const Model& model) {
  for (const bool energy : {false, true}) {
    const State state = make_state(model, energy);
    std::uint64_t held = 0;
    for_each_state_array(
        [&](std::string_view, StateArrayRole, const auto& array) {
          using Element = typename std::decay_t<decltype(array)>::value_type;
          held += array.capacity() * sizeof(Element);
        },
        state);
    EXPECT_EQ(made_state_bytes(model, energy), held) << (energy ? "with" : "without") << " energy";
  }
}

// The estimate of the state's bytes is worked out from the model's counts before the run; the
// state make_state allocates must hold exactly that.
TEST(ModelArrays, StateEstimateIsWhatTheMadeStateHolds) {
  expect_state_estimate_holds(build_model(test::scene_from_yaml(kEveryArrayScene)));
}

// And with the bars held as constraints (`integrator: xpbd`: each bar's multiplier and record),
// on the same scene without contact within an object, which they refuse.
TEST(ModelArrays, StateEstimateIsWhatTheMadeStateHoldsWithTheBarsAsConstraints) {
  const Model model = build_model(test::scene_from_yaml(test::replaced(
      test::replaced(kEveryArrayScene, "contact: {self: true}", "contact: {objects: true}"),
      "version: 1\n", "version: 1\nintegrator: xpbd\n")));
  ASSERT_TRUE(model.bars_are_constraints());
  expect_state_estimate_holds(model);
}

// The implicit schemes step a copy of the model with the ground softened (ImplicitOptions): the
// estimate counts the model twice for them, once without a ground to soften or under central
// differences.
TEST(ModelArrays, TheImplicitSteppersCopyOfTheModelIsCounted) {
  const std::string cloth = R"(version: 1
duration: 1
objects:
  - mesh: {grid: {width: 1, height: 1, columns: 8, rows: 8, diagonals: one}, translation: [0, 0, 0.5]}
    material: {density: 1200, youngs_modulus: 2.0e7, radius: 0.001}
)";
  const auto model_part = [](const std::string& yaml) {
    const SceneDescription scene = test::scene_from_yaml(yaml);
    return estimate_memory(scene, build_model(scene), {}).model;
  };
  const std::uint64_t explicit_model = model_part(cloth);
  EXPECT_EQ(
      model_part(test::replaced(cloth, "duration: 1\n", "duration: 1\nintegrator: implicit\n")),
      2 * explicit_model);
  const std::string no_ground =
      test::replaced(cloth, "duration: 1\n", "duration: 1\nground: {contact: false}\n");
  EXPECT_EQ(
      model_part(test::replaced(no_ground, "duration: 1\n", "duration: 1\nintegrator: implicit\n")),
      model_part(no_ground));
}

class MemoryEstimateTest : public ::testing::Test {
 protected:
  std::filesystem::path write_scene(const std::string& name, const std::string& yaml) const {
    std::filesystem::path path = folder_.path() / name;
    std::ofstream(path) << yaml;
    return path;
  }
  test::TemporaryFolder folder_{"memory"};
};

// The estimate counts the model's arrays as allocated and the frames held exactly; the figures it
// cannot count (the libraries, Mesa's buffers per pixel) were measured on other scenes. What it
// leaves out is allocator slack and the model builder's short-lived maps, a few per cent on these
// runs; 15 % leaves room for another libc or Mesa build while still catching a part forgotten
// (the frames are about half of the first run, the pixels most of the second and third).
TEST_F(MemoryEstimateTest, PeakResidentMemoryOfARunIsWithinFifteenPercentOfTheEstimate) {
  if (sanitized_build()) {
    GTEST_SKIP() << "the sanitizers' shadow memory and quarantine are not part of the estimate";
  }
  const double tolerance = 0.15;
  struct Case {
    std::string what;
    std::filesystem::path scene;
  };
  const std::vector<Case> cases = {
      {"many nodes, 120 frames held", write_scene("nodes.yaml", cloth_scene(200))},
      {"few nodes, many pixels", write_scene("pixels.yaml", cloth_scene(4, 2560, 1440))},
      // The linear targets of ambient occlusion, multisampled and not.
      {"occlusion and soft shadows, many pixels",
       write_scene("final.yaml",
                   cloth_scene(4, 2560, 1440, ", quality: final, motion_blur: false"))},
  };
  for (const Case& c : cases) {
    const double estimate = estimated_bytes(c.scene);
    const PeakRun run =
        run_measured({"render", c.scene.string(), "-o", (folder_.path() / "out").string(), "-q",
                      "--frames", "1-1", "--movie", "none"});
    ASSERT_EQ(run.exit_code, 0) << c.what;
    EXPECT_NEAR(run.peak_bytes / estimate, 1.0, tolerance)
        << c.what << ": peak " << run.peak_bytes << " bytes, estimate " << estimate;
  }
}

// An implicit run holds its Hessian, twice, a chunk of its springs' matrices and the Hessian's
// Cholesky factor, which grows faster than the model: on a cloth of 100 × 100 cells two thirds of
// the run's memory, which an estimate of the state alone left out (77 MB for a run that held 250).
// The estimate counts them from the factor's analysis and a measured 12 bytes a nonzero of it.
TEST_F(MemoryEstimateTest, AnImplicitRunsMatricesAreCounted) {
  if (sanitized_build()) {
    GTEST_SKIP() << "the sanitizers' shadow memory and quarantine are not part of the estimate";
  }
  std::string cloth =
      test::replaced(cloth_scene(100), "duration: 0.5\nfps: 240\n", "duration: 0.1\nfps: 20\n");
  cloth = test::replaced(cloth, "timestep: auto\n", "integrator: implicit\n");
  const std::filesystem::path scene = write_scene("implicit.yaml", cloth);
  const double estimate = estimated_bytes(scene, "memory_simulate_bytes");
  const PeakRun run =
      run_measured({"simulate", scene.string(), "-o", (folder_.path() / "cache").string(), "-q"});
  ASSERT_EQ(run.exit_code, 0);
  EXPECT_NEAR(run.peak_bytes / estimate, 1.0, 0.15)
      << "peak " << run.peak_bytes << " bytes, estimate " << estimate;
  // Central differences' run of the same cloth holds none of it: its estimate is under a third.
  const std::filesystem::path explicit_scene = write_scene(
      "explicit.yaml", test::replaced(cloth, "integrator: implicit\n", "timestep: auto\n"));
  EXPECT_LT(estimated_bytes(explicit_scene, "memory_simulate_bytes"), estimate / 3.0);
  // Where the matrices are what does not fit, the refusal says central differences hold none, and
  // writes nothing.
  const std::filesystem::path refused = folder_.path() / "refused";
  const test::CommandResult result =
      test::run_command("DINAM_MEMORY_LIMIT=150M " + std::string(DINAM_PROGRAM) + " simulate '" +
                        scene.string() + "' -q -o '" + refused.string() + "'");
  EXPECT_EQ(result.exit_code, 2) << result.output;
  for (const char* fragment : {"implicit.yaml: this run needs about", "solver",
                               "'integrator: central_difference', whose steps hold no matrix"}) {
    EXPECT_NE(result.output.find(fragment), std::string::npos)
        << "lacks '" << fragment << "': " << result.output;
  }
  EXPECT_FALSE(std::filesystem::exists(refused));
}

TEST_F(MemoryEstimateTest, RenderThatWouldNotFitIsRefusedUnlessForced) {
  const std::filesystem::path scene = write_scene("small.yaml", cloth_scene(4));
  const std::filesystem::path out = folder_.path() / "refused";
  const std::string command = "DINAM_MEMORY_LIMIT=20M " + std::string(DINAM_PROGRAM) + " render '" +
                              scene.string() + "' -q --movie none --frames 1-1 -o '" +
                              out.string() + "'";
  const test::CommandResult refused = test::run_command(command);
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  for (const char* fragment : {"small.yaml: this run needs about", "frames", "drawing",
                               "more than the 21 MB available (DINAM_MEMORY_LIMIT)", "--force"}) {
    EXPECT_NE(refused.output.find(fragment), std::string::npos)
        << "lacks '" << fragment << "': " << refused.output;
  }
  EXPECT_FALSE(std::filesystem::exists(out)) << "a refused run wrote its output folder";

  const test::CommandResult forced = test::run_command(command + " --force");
  EXPECT_EQ(forced.exit_code, 0) << forced.output;
  EXPECT_TRUE(std::filesystem::exists(out / "frame_0001.png"));

  const test::CommandResult simulate =
      test::run_command("DINAM_MEMORY_LIMIT=20M " + std::string(DINAM_PROGRAM) + " simulate '" +
                        scene.string() + "' -q -o '" + (folder_.path() / "cache").string() + "'");
  EXPECT_EQ(simulate.exit_code, 2) << simulate.output;
  EXPECT_FALSE(std::filesystem::exists(folder_.path() / "cache"));
}

TEST_F(MemoryEstimateTest, UnreadableMemoryLimitIsAUserErrorSayingHowToWriteIt) {
  const std::filesystem::path scene = write_scene("small.yaml", cloth_scene(4));
  for (const char* limit : {"lots", "12Q", "-5G", "1e30"}) {
    const test::CommandResult run =
        test::run_command(std::string("DINAM_MEMORY_LIMIT=") + limit + " " + DINAM_PROGRAM +
                          " info '" + scene.string() + "'");
    EXPECT_EQ(run.exit_code, 2) << limit << ": " << run.output;
    EXPECT_NE(run.output.find("DINAM_MEMORY_LIMIT=8G"), std::string::npos) << run.output;
  }
}

TEST(ByteSize, ThreeSignificantFiguresInDecimalUnits) {
  EXPECT_EQ(byte_size(512), "512 bytes");
  EXPECT_EQ(byte_size(1'234'567), "1.23 MB");
  EXPECT_EQ(byte_size(999'600), "1 MB");
  EXPECT_EQ(byte_size(45'100'000'000ULL), "45.1 GB");
}

}  // namespace
}  // namespace dinam
