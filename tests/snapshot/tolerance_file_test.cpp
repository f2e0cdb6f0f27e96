// The tolerance file beside the goldens: limits per scene and frame over the defaults, regions in
// the golden's pixels or the scene's metres, errors at their line, and --update's record of the
// scenes.
#include "snapshot/tolerance_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "render/camera.hpp"
#include "snapshot/region_weights.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

class ToleranceFileTest : public ::testing::Test {
 protected:
  void write(const std::string& text) {
    std::ofstream(folder_.path() / kToleranceFileName) << text;
  }
  std::string read() const {
    std::ifstream in(folder_.path() / kToleranceFileName);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
  // The UserError's message, or "" when reading succeeds.
  std::string error_of(const std::string& text) {
    write(text);
    try {
      read_tolerance_file(folder_.path());
    } catch (const UserError& e) {
      return e.what();
    }
    return "";
  }
  test::TemporaryFolder folder_{"tolerances"};
};

TEST_F(ToleranceFileTest, AFolderWithoutTheFileTakesTheDefaults) {
  const ToleranceFile file = read_tolerance_file(folder_.path());
  EXPECT_FALSE(file.exists);
  const FrameTolerance t = file.for_frame(ImageTolerance{}, "flag", 1);
  EXPECT_EQ(t.limits.threshold, ImageTolerance{}.threshold);
  EXPECT_EQ(t.limits.min_ssim, ImageTolerance{}.min_ssim);
  EXPECT_TRUE(t.regions.empty());
}

TEST_F(ToleranceFileTest, AFrameTakesItsOwnThenItsScenesThenTheDefaultLimits) {
  write(R"(version: 1
default: {threshold: 30, max_differing: 0.01}
scenes:
  flag:
    max_differing: 0.02
    min_ssim: 0.9
    ignore: [{pixels: [0, 0, 10, 10]}]
    frames:
      120: {min_ssim: 0.8, weigh: [{box: [[0, 0, 0], [1, 1, 1]], weight: 3}]}
  rope:
)");
  const ToleranceFile file = read_tolerance_file(folder_.path());
  ASSERT_TRUE(file.exists);
  const FrameTolerance first = file.for_frame(ImageTolerance{}, "flag", 1);
  EXPECT_EQ(first.limits.threshold, 30);                  // the default's
  EXPECT_EQ(first.limits.max_differing_fraction, 0.02);   // the scene's
  EXPECT_EQ(first.limits.min_ssim, 0.9);                  // the scene's
  EXPECT_EQ(first.limits.shift, ImageTolerance{}.shift);  // nobody's: built in
  ASSERT_EQ(first.regions.size(), 1u);
  EXPECT_EQ(first.regions[0].weight, 0.0f);
  const FrameTolerance last = file.for_frame(ImageTolerance{}, "flag", 120);
  EXPECT_EQ(last.limits.min_ssim, 0.8);
  EXPECT_EQ(last.limits.max_differing_fraction, 0.02);
  ASSERT_EQ(last.regions.size(), 2u);  // the scene's and the frame's
  EXPECT_EQ(last.regions[1].weight, 3.0f);
  EXPECT_FALSE(last.regions[1].pixels.has_value());
  EXPECT_EQ(last.regions[1].box_high, Vec3(1, 1, 1));
  // A scene listed with nothing, and one not listed, take the defaults.
  for (const char* scene : {"rope", "ball"}) {
    const FrameTolerance t = file.for_frame(ImageTolerance{}, scene, 1);
    EXPECT_EQ(t.limits.threshold, 30) << scene;
    EXPECT_EQ(t.limits.max_differing_fraction, 0.01) << scene;
  }
}

TEST_F(ToleranceFileTest, BadKeysAndValuesAreRefusedAtTheirLine) {
  const std::string file = (folder_.path() / kToleranceFileName).string();
  std::string error = error_of("version: 1\ndefault: {max_diferring: 0.01}\n");
  EXPECT_NE(error.find(file + ":2:"), std::string::npos) << error;
  EXPECT_NE(error.find("max_differing"), std::string::npos) << error;  // the near miss named
  error = error_of("version: 1\nscenes:\n  flag: {min_ssim: 2}\n");
  EXPECT_NE(error.find(":3:"), std::string::npos) << error;
  EXPECT_NE(error.find("-1 to 1"), std::string::npos) << error;
  error = error_of("version: 1\nscenes:\n  flag:\n    ignore: [{pixels: [10, 0, 5, 10]}]\n");
  EXPECT_NE(error.find(":4:"), std::string::npos) << error;
  EXPECT_NE(error.find("holds no pixel"), std::string::npos) << error;
  error = error_of("version: 1\nscenes:\n  flag:\n    weigh: [{weight: 2}]\n");
  EXPECT_NE(error.find("'pixels"), std::string::npos) << error;
  EXPECT_NE(error.find("'box"), std::string::npos) << error;
  error = error_of("version: 1\nscenes:\n  flag:\n    frames: {0: {min_ssim: 0.9}}\n");
  EXPECT_NE(error.find("frames count from 1"), std::string::npos) << error;
  error = error_of("version: 2\n");
  EXPECT_NE(error.find("version 2"), std::string::npos) << error;
  error = error_of("version: 1\ndefault:\n\tthreshold: 3\n");
  EXPECT_NE(error.find("tab"), std::string::npos) << error;
}

TEST_F(ToleranceFileTest, UpdateWritesTheFileThenAddsScenesItLacks) {
  const ImageTolerance limits;
  std::string said = record_scenes(folder_.path(), {"flag", "rope heap"}, limits);
  EXPECT_NE(said.find("wrote"), std::string::npos) << said;
  ToleranceFile file = read_tolerance_file(folder_.path());
  ASSERT_TRUE(file.exists);
  EXPECT_EQ(file.scenes.count("flag"), 1u);
  EXPECT_EQ(file.scenes.count("rope heap"), 1u);
  // The default limits are written out, so that the file says what the goldens are held to.
  EXPECT_EQ(*file.defaults.min_ssim, limits.min_ssim);
  EXPECT_EQ(*file.defaults.threshold, limits.threshold);
  // A scene it has is left alone; one it lacks is added below the others, edits kept.
  write(read() + "  # the flag's sky is noisy\n");
  EXPECT_EQ(record_scenes(folder_.path(), {"flag"}, limits), "");
  said = record_scenes(folder_.path(), {"ball"}, limits);
  EXPECT_NE(said.find("added ball"), std::string::npos) << said;
  EXPECT_NE(read().find("# the flag's sky is noisy"), std::string::npos);
  file = read_tolerance_file(folder_.path());
  EXPECT_EQ(file.scenes.size(), 3u);
  // A file written otherwise (its scenes not last) is left as it is.
  write("version: 1\nscenes: {flag: {}}\ndefault: {threshold: 20}\n");
  EXPECT_EQ(record_scenes(folder_.path(), {"rope"}, limits), "");
  EXPECT_EQ(read(), "version: 1\nscenes: {flag: {}}\ndefault: {threshold: 20}\n");
}

// Regions as weights: a rectangle of pixels exactly; a box of the scene where its camera sees it.
TEST(RegionWeights, PixelsAndTheSceneBoxAsTheCameraSeesIt) {
  RenderCamera camera;
  camera.position = Vec3f(0, -5, 1);
  camera.look_at = Vec3f(0, 0, 1);
  camera.fov_degrees = 40.0f;
  EXPECT_TRUE(region_weights({}, 32, 18, camera).empty());
  SnapshotRegion ignore;
  ignore.pixels = std::array<int, 4>{2, 3, 5, 4};
  const std::vector<float> masked = region_weights({ignore}, 32, 18, camera);
  ASSERT_EQ(masked.size(), 32u * 18u);
  int zeros = 0;
  for (const float w : masked) {
    zeros += w == 0.0f ? 1 : 0;
  }
  EXPECT_EQ(zeros, 3);  // x 2..4 of row 3
  EXPECT_EQ(masked[3 * 32 + 2], 0.0f);
  EXPECT_EQ(masked[3 * 32 + 5], 1.0f);
  // A small box at the point looked at covers the picture's centre, not its corners.
  SnapshotRegion box;
  box.box_low = Vec3(-0.1, -0.1, 0.9);
  box.box_high = Vec3(0.1, 0.1, 1.1);
  box.weight = 4.0f;
  const std::vector<float> weighed = region_weights({box}, 320, 180, camera);
  EXPECT_EQ(weighed[90 * 320 + 160], 4.0f);
  EXPECT_EQ(weighed[0], 1.0f);
  const Eigen::Vector2f corner = pixel_from_world(camera, 320, 180, Vec3f(0.1f, -0.1f, 1.1f));
  EXPECT_EQ(
      weighed[static_cast<std::size_t>(corner.y()) * 320 + static_cast<std::size_t>(corner.x())],
      4.0f);
  EXPECT_EQ(weighed[90 * 320 + static_cast<std::size_t>(corner.x()) + 3], 1.0f);
  // Behind the camera: nothing.
  SnapshotRegion behind = box;
  behind.box_low = Vec3(-0.1, -7, 0.9);
  behind.box_high = Vec3(0.1, -6, 1.1);
  for (const float w : region_weights({behind}, 320, 180, camera)) {
    ASSERT_EQ(w, 1.0f);
  }
  // An ignored region wins where it overlaps a weighed one.
  SnapshotRegion centre;
  centre.pixels = std::array<int, 4>{150, 80, 170, 100};
  EXPECT_EQ(region_weights({box, centre}, 320, 180, camera)[90 * 320 + 160], 0.0f);
}

}  // namespace
}  // namespace dinam
