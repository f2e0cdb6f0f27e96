// Motion blur from the simulation's own steps (issue 14): a bar flying at constant speed smears
// over the distance the shutter lets it travel, the blur keeps the light it averages (linear
// light), and a still scene is drawn the same with and without blur.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "run/frame_source.hpp"
#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "render/camera.hpp"
#include "render/draw_list.hpp"
#include "render/osmesa_renderer.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"
#include "visual/draw_list_from_model.hpp"
#include "visual/frame_drawing.hpp"

namespace dinam {
namespace {

constexpr int kWidth = 640;
constexpr int kHeight = 360;

// A vertical steel bar 1 m long, 2 cm thick, flying along +x at `speed` in empty space (no
// gravity, no ground), seen from 6 m along +y; 20 frames a second, tone mapping off so that the
// picture is linear light through the display's gamma alone.
std::string flying_bar(double speed, const std::string& blur) {
  return fmt::format(R"(version: 1
duration: 0.2
fps: 20
gravity: [0, 0, 0]
ground: {{visible: false, contact: false}}
camera: {{position: [0.5, -6, 1], look_at: [0.5, 0, 1], fov: 30}}
image: {{width: {}, height: {}, tone_mapping: none, shadows: false{}}}
objects:
  - name: bar
    mesh: {{polyline: {{points: [[0, 0, 0.5], [0, 0, 1.5]], segments: 1}}}}
    material: {{density: 7800, youngs_modulus: 2.0e11, radius: 0.01}}
    initial_velocity: [{}, 0, 0]
    color: [0.9, 0.05, 0.05]
)",
                     kWidth, kHeight, blur, speed);
}

// The frames of a scene, drawn as `dinam render` draws them.
std::vector<Image> render_frames(const std::string& text) {
  const SceneDescription scene = test::scene_from_yaml(text);
  const Model model = build_model(scene);
  const TimeStep timestep = choose_timestep(model, scene.timestep, scene.fps, scene.timestep_loc);
  const SimulatedFrames frames =
      simulate_frames(model, timestep, scene.frame_count(), false, {}, &scene.quality.motion_blur);
  const FrameCameras cameras = frame_cameras(scene, model, frames);
  const DrawList list = make_draw_list(scene, model, frames.motion);
  OsmesaRenderer renderer(render_settings(scene));
  std::vector<Image> images;
  draw_frames(renderer, list, frames, cameras, 1, scene.frame_count(),
              [&](int, const Image& image) { images.push_back(image); });
  return images;
}

// Along the row through the bar's middle: how much the bar takes away from the sky's green, in
// linear light (the display value decoded by its gamma), per pixel. The sky is the mean of the
// row's first and last 100 pixels: the display's dither makes that mean the sky's own value, and
// leaves each pixel's rounding unbiased.
std::vector<double> darkening(const Image& image) {
  const int row = kHeight / 2;
  const auto linear = [&](int x) { return std::pow(image.pixel(x, row)[1] / 255.0, 2.2); };
  double sky = 0.0;
  for (int x = 0; x < 100; ++x) {
    sky += (linear(x) + linear(kWidth - 1 - x)) / 200.0;
  }
  std::vector<double> profile(kWidth);
  for (int x = 0; x < kWidth; ++x) {
    profile[static_cast<std::size_t>(x)] = sky - linear(x);
  }
  return profile;
}

// Width of the profile at half its maximum, pixels, interpolated between pixels.
double full_width_at_half_maximum(const std::vector<double>& profile) {
  const double half = 0.5 * *std::max_element(profile.begin(), profile.end());
  const auto first =
      std::find_if(profile.begin(), profile.end(), [&](double v) { return v > half; });
  const auto last =
      std::find_if(profile.rbegin(), profile.rend(), [&](double v) { return v > half; });
  const auto crossing = [&](std::size_t below, std::size_t above) {
    return static_cast<double>(below) +
           (half - profile[below]) / (profile[above] - profile[below]) *
               (static_cast<double>(above) - static_cast<double>(below));
  };
  const auto i = static_cast<std::size_t>(first - profile.begin());
  const auto j = profile.size() - 1 - static_cast<std::size_t>(last - profile.rbegin());
  return crossing(j + 1, j) - crossing(i - 1, i);
}

double sum(const std::vector<double>& profile) {
  double total = 0.0;
  for (const double v : profile) {
    total += v;
  }
  return total;
}

// The camera maps 1 m at 6 m distance to kHeight / (2 · 6 tan 15°) pixels.
double pixels_per_metre() {
  return kHeight / (2.0 * 6.0 * std::tan(15.0 * M_PI / 180.0));
}

// Darkening-weighted mean column over columns first … last, pixels (a window around the bar, so
// that the dither elsewhere weighs nothing).
double centroid(const std::vector<double>& profile, double first, double last) {
  double moment = 0.0;
  double total = 0.0;
  for (auto x = static_cast<std::size_t>(first); x <= static_cast<std::size_t>(last); ++x) {
    moment += static_cast<double>(x) * profile[x];
    total += profile[x];
  }
  return moment / total;
}

TEST(MotionBlur, BarAtConstantSpeedSmearsOverShutterTimesSpeedOverFps) {
  const double speed = 20.0;  // m/s
  const double shutter = 0.5;
  const std::vector<Image> sharp = render_frames(flying_bar(speed, ""));
  const std::vector<Image> blurred =
      render_frames(flying_bar(speed, ", motion_blur: {shutter: 0.5, samples: 64}"));
  // The same bar under a shutter ten times shorter: nearly sharp, but drawn as blurred frames are
  // (each instant in linear light, moved by a fraction of a pixel).
  const std::vector<Image> brief =
      render_frames(flying_bar(speed, ", motion_blur: {shutter: 0.05, samples: 64}"));
  ASSERT_EQ(sharp.size(), 4u);
  ASSERT_EQ(blurred.size(), 4u);
  ASSERT_EQ(brief.size(), 4u);
  // Frame 3 (t = 0.1 s): the shutter is open from 1/80 s before to 1/80 s after, over which the
  // bar travels shutter × speed / fps = 0.5 m, 56 pixels, eighteen times its 2 cm width. The
  // profile of a thin bar averaged over that travel is a plateau as wide as the travel (to
  // within the bar's width, a pixel or two, and the 64 instants' spacing, under a pixel),
  // centred where the bar is at the frame's time.
  const double travel = shutter * speed / 20.0 * pixels_per_metre();
  const std::vector<double> moving = darkening(blurred[2]);
  EXPECT_NEAR(full_width_at_half_maximum(moving), travel, 2.0);
  EXPECT_LT(full_width_at_half_maximum(darkening(sharp[2])), 6.0);
  const RenderCamera camera{Vec3f(0.5f, -6, 1), Vec3f(0.5f, 0, 1), Vec3f::UnitZ(), 30.0f};
  const double at_frame = pixel_from_world(camera, kWidth, kHeight, Vec3f(2.0f, 0, 1)).x();
  EXPECT_NEAR(centroid(moving, at_frame - travel, at_frame + travel), at_frame, 1.0);
  // In linear light the blur moves the bar's light around and keeps its total: a mean of gamma-
  // encoded values would darken the sky about 1.7 times as much over the long smear (the slope
  // of the display curve at the sky's green, against the straight line to the bar's), and less
  // over the short one. 8 % leaves room for the 8-bit display values of a faint smear.
  EXPECT_NEAR(sum(moving) / sum(darkening(brief[2])), 1.0, 0.08);
  // Frame 1 (t = 0): before the motion starts the bar is where it starts, so half the instants
  // show it there and the other half spread over the half of the travel after t = 0: the mean
  // column lies an eighth of the travel ahead of the start.
  const double start = pixel_from_world(camera, kWidth, kHeight, Vec3f(0, 0, 1)).x();
  EXPECT_NEAR(centroid(darkening(blurred[0]), start - 10.0, start + travel) - start, travel / 8.0,
              1.0);
}

TEST(MotionBlur, StillSceneIsDrawnIdenticallyWithAndWithoutBlur) {
  for (const char* quality : {"standard", "final"}) {
    const std::string look = fmt::format(", quality: {}", quality);
    const std::vector<Image> plain = render_frames(flying_bar(0.0, look + ", motion_blur: false"));
    const std::vector<Image> blurred =
        render_frames(flying_bar(0.0, look + ", motion_blur: {shutter: 1, samples: 16}"));
    ASSERT_EQ(plain.size(), blurred.size());
    for (std::size_t f = 0; f < plain.size(); ++f) {
      EXPECT_EQ(plain[f].rgba, blurred[f].rgba) << quality << ", frame " << f + 1;
    }
  }
}

// Each instant is one the simulation steps through: the offsets are whole steps, spread over the
// shutter and centred on the frame.
TEST(MotionBlur, InstantsAreStepsSpreadEvenlyOverTheShutter) {
  EXPECT_EQ(shutter_offsets({4, 0.5}, 100), (std::vector<int>{-19, -6, 6, 19}));
  EXPECT_EQ(shutter_offsets({2, 1.0}, 10), (std::vector<int>{-3, 3}));  // 2.5 rounds away from 0
  EXPECT_TRUE(shutter_offsets({1, 0.5}, 100).empty());
}

}  // namespace
}  // namespace dinam
