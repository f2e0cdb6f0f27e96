// The ground and the sky as an artist sets them (`ground: {pattern, color, checker_color, tile}`,
// `sky: {horizon, zenith}`), and a checker that does not alias into moiré towards the horizon
// (shaders/ground.frag filters it over each pixel's footprint). Drawn by the program itself.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <fmt/format.h>

#include "io/png_file.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// A low eye looking across a bare ground to the horizon (a thin post in the middle, 3 m ahead),
// 640 × 360, at the standard quality.
std::string across_the_ground(const std::string& extra) {
  return fmt::format(R"(version: 1
duration: 0.05
fps: 20
image: {{width: 640, height: 360, quality: standard}}
camera: {{position: [0, -3, 0.6], look_at: [0, 20, 0.35], fov: 40}}
movie: none
{}
objects:
  - name: post
    mesh: {{polyline: {{points: [[0, 0, 0], [0, 0, 0.3]], segments: 2}}}}
    material: {{density: 1000, youngs_modulus: 1.0e9, radius: 0.01}}
    pinned: {{all: true}}
)",
                     extra);
}

Image rendered(const test::TemporaryFolder& folder, const std::string& name,
               const std::string& extra) {
  const std::filesystem::path scene = folder.path() / (name + ".yaml");
  std::ofstream(scene) << across_the_ground(extra);
  const test::CommandResult run =
      test::run_dinam({"render", scene.string(), "-o", (folder.path() / name).string(), "-q"});
  EXPECT_EQ(run.exit_code, 0) << run.output;
  return read_png(folder.path() / name / "frame_0001.png");
}

double luminance(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

// The variance of the pixels' luminance (0–255) about each row's mean, over rows [top, bottom) and
// columns from `left` less the post's: the pattern's own variation, not the shading's fall with
// distance.
double band_variance(const Image& image, int top, int bottom, int left = 0) {
  double sum = 0.0;
  int count = 0;
  for (int y = top; y < bottom; ++y) {
    double mean = 0.0;
    int n = 0;
    for (int x = left; x < image.width; ++x) {
      if (x < 290 || x > 350) {
        mean += luminance(image, x, y);
        ++n;
      }
    }
    mean /= n;
    for (int x = left; x < image.width; ++x) {
      if (x < 290 || x > 350) {
        const double d = luminance(image, x, y) - mean;
        sum += d * d;
        ++count;
      }
    }
  }
  return sum / count;
}

TEST(GroundLook, TheCheckerFadesToItsMeanTowardsTheHorizonWithoutMoire) {
  const test::TemporaryFolder folder("ground-look");
  const Image checker = rendered(folder, "checker", "");
  // A flat grey of the checker's mean colour (its two default colours' mean, linear).
  const Image plain =
      rendered(folder, "plain", "ground: {pattern: plain, color: {linear: [0.55, 0.53, 0.495]}}");
  // The horizon is at row 180 (the eye 0.6 m up looking 0.25 m down over 23 m); the far band is
  // the ground's first 30 rows below it, where squares of 6 cm (the scene's automatic size) are a
  // few pixels to a tenth of one.
  for (const auto& [top, bottom] : {std::pair{182, 200}, std::pair{200, 230}}) {
    const double with_checker = band_variance(checker, top, bottom);
    const double flat = band_variance(plain, top, bottom);
    fmt::print("rows {}–{}: variance {:.3f} with the checker, {:.3f} flat\n", top, bottom,
               with_checker, flat);
    // Within half a level² of the flat grey's (a pixel's rounding alone varies by a quarter):
    // the unfiltered checker gave 9.1 and 21 here, its moiré arcs plain to see.
    EXPECT_LT(with_checker, flat + 0.5) << "rows " << top << "–" << bottom;
  }
  // Nearer, where the squares are many pixels wide, the checker is still drawn.
  EXPECT_GT(band_variance(checker, 300, 360), 10.0 * band_variance(plain, 300, 360) + 1.0);
}

double channel(const Image& image, int x, int y, int c) {
  return image.pixel(x, y)[c];
}

TEST(GroundLook, TheGroundsAndTheSkysColoursAndTheSquaresSize) {
  const test::TemporaryFolder folder("ground-keys");
  // A plain red floor under an orange horizon and a deep blue top.
  const Image red = rendered(folder, "red",
                             "ground: {pattern: plain, color: [0.8, 0.1, 0.1]}\n"
                             "sky: {horizon: [1.0, 0.55, 0.1], zenith: [0.05, 0.1, 0.5]}");
  EXPECT_GT(channel(red, 100, 320, 0), 2.0 * channel(red, 100, 320, 1));  // the floor, near
  EXPECT_GT(channel(red, 100, 2, 2), 2.0 * channel(red, 100, 2, 0));      // the top of the sky
  EXPECT_GT(channel(red, 100, 175, 0), 1.5 * channel(red, 100, 175, 2));  // just above the horizon
  // Black and white squares of 0.5 m: near rows vary far more than the default's pale greys; one
  // square of a kilometre covers the view right of the post (x > 0, the squares' edge at x = 0
  // runs through the post), as flat as a plain floor.
  const Image contrast =
      rendered(folder, "contrast",
               "ground: {color: [0.9, 0.9, 0.9], checker_color: [0.05, 0.05, 0.05], "
               "tile: 0.5}");
  const Image one_square = rendered(folder, "one_square", "ground: {tile: 1000}");
  const Image flat = rendered(folder, "flat", "ground: {pattern: plain}");
  EXPECT_GT(band_variance(contrast, 300, 360), 1000.0);
  EXPECT_LT(band_variance(one_square, 240, 360, 360), band_variance(flat, 240, 360, 360) + 0.5);
  EXPECT_GT(band_variance(rendered(folder, "default", ""), 240, 360, 360), 10.0);
}

TEST(GroundLook, LookKeysAreCheckedAtTheirLine) {
  test::expect_user_error(
      [] { test::scene_from_yaml("version: 1\nduration: 1\nground: {tile: 0}\nobjects: []\n"); }, 3,
      {"ground.tile"});
  test::expect_user_error(
      [] {
        test::scene_from_yaml("version: 1\nduration: 1\nsky: {top: [0, 0, 1]}\nobjects: []\n");
      },
      3, {"horizon", "zenith"});
  test::expect_user_error(
      [] {
        test::scene_from_yaml("version: 1\nduration: 1\nground: {color: [2, 0, 0]}\nobjects: []\n");
      },
      3, {"ground.color", "sRGB"});
}

}  // namespace
}  // namespace dinam
