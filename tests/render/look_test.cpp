// The look's features, each checked against what it must do to the picture: soft shadows widen
// with the distance from the occluder as the sun's size says, ambient occlusion darkens the
// ground beside what lies on it and nowhere else, exposure doubles the light per stop.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render/camera.hpp"
#include "render/osmesa_renderer.hpp"
#include "render_test_support.hpp"

namespace dinam {
namespace {

constexpr int kWidth = 640;
constexpr int kHeight = 360;

// A camera 3 m above the ground looking straight down, +y up in the picture: 1 m is
// kHeight / (2 · 3 tan 20°) pixels.
RenderCamera camera_above(float x) {
  RenderCamera camera;
  camera.position = Vec3f(x, 0, 3);
  camera.look_at = Vec3f(x, 0, 0);
  camera.up = Vec3f::UnitY();
  camera.fov_degrees = 40.0f;
  return camera;
}

double pixels_per_metre() {
  return kHeight / (2.0 * 3.0 * std::tan(20.0 * std::numbers::pi / 180.0));
}

// A plain ground and a 2 × 2 m square roof at `height`, from x = 0 to 2, lit by a sun 30° from
// the zenith towards +x, of apparent diameter `sun_degrees`.
DrawList roof(float height, float sun_degrees) {
  DrawList list;
  list.point_radius.assign(4, 0.0f);
  list.point_color.assign(4, Vec3f(0.6f, 0.6f, 0.6f));
  list.surfaces.push_back({{0, 1, 2, 0, 2, 3}, -1});
  list.ground_tile = 100.0f;  // one checker colour over the whole view
  list.ground_half_size = 50.0f;
  list.light_direction = Vec3f(0.5f, 0, 0.866f);
  list.light_size_degrees = sun_degrees;
  list.shadow_bounds_min = Vec3f(-1.5f, -1.2f, 0);
  list.shadow_bounds_max = Vec3f(2.1f, 1.2f, height + 0.1f);
  return list;
}

std::vector<Vec3f> roof_corners(float height) {
  return {Vec3f(0, -1, height), Vec3f(2, -1, height), Vec3f(2, 1, height), Vec3f(0, 1, height)};
}

// The ground's brightness across the shadow's edge, each column the mean of 100 rows (the soft
// shadow's rotated taps are noise that averages out), and the width in metres over which it goes
// from 10 % to 90 % of the way from the shadow to the light.
double edge_width(float height, float sun_degrees) {
  LookSettings look;
  look.soft_shadows = true;
  look.sky_light = false;
  look.tone_mapping = false;
  OsmesaRenderer renderer({kWidth, kHeight, 1, 4096, look});
  const RenderCamera camera = camera_above(-0.4f);
  Image image;
  renderer.render(roof(height, sun_degrees), roof_corners(height), camera, image);
  const int first_column =
      static_cast<int>(pixel_from_world(camera, kWidth, kHeight, Vec3f(-1.2f, 0, 0)).x());
  const int last_column =
      static_cast<int>(pixel_from_world(camera, kWidth, kHeight, Vec3f(-0.02f, 0, 0)).x());
  std::vector<double> profile;
  for (int x = first_column; x <= last_column; ++x) {
    double sum = 0.0;
    for (int y = kHeight / 2 - 50; y < kHeight / 2 + 50; ++y) {
      sum += test::brightness(image.pixel(x, y));
    }
    profile.push_back(sum / 100.0);
  }
  const double lit = profile.front();
  const double shadow = profile.back();
  EXPECT_LT(shadow, 0.8 * lit) << "the roof shades the ground under its edge";
  const auto crossing = [&](double fraction) {
    const double level = shadow + fraction * (lit - shadow);
    for (std::size_t i = profile.size() - 1; i > 0; --i) {  // from the shadow outwards
      if (profile[i - 1] >= level) {
        return static_cast<double>(i - 1) +
               (profile[i - 1] - level) / (profile[i - 1] - profile[i]);
      }
    }
    return 0.0;
  };
  return (crossing(0.1) - crossing(0.9)) / pixels_per_metre();
}

// Percentage-closer soft shadows: an occluder edge at height h under a sun of apparent diameter
// θ, 30° from the zenith, spreads its shadow's edge over 2 (h / cos 30°) tan(θ/2) across the
// light, 1/cos 30° wider on the ground. A disc filter of that diameter goes from 10 % to 90 % over
// 0.69 of it (the circular segments of a straight edge); the 16 taps and the blocker estimate are
// approximate, hence ±35 %. Twice the height, twice the width (±20 %).
TEST(Look, SoftShadowEdgeWidensWithTheHeightOfTheOccluderAsTheSunsSizeSays) {
  const float sun = 8.0f;
  const double cos30 = std::cos(std::numbers::pi / 6.0);
  const auto expected = [&](double h) {
    return 0.69 * 2.0 * (h / cos30) * std::tan(0.5 * sun * std::numbers::pi / 180.0) / cos30;
  };
  const double low = edge_width(0.5f, sun);
  const double high = edge_width(1.0f, sun);
  EXPECT_NEAR(low / expected(0.5), 1.0, 0.35) << low << " m";
  EXPECT_NEAR(high / expected(1.0), 1.0, 0.35) << high << " m";
  EXPECT_NEAR(high / low, 2.0, 0.4);
}

// A bar lying on the ground: with ambient occlusion the ground right beside it is darker, the
// ground far from it is not.
TEST(Look, AmbientOcclusionDarkensTheGroundBesideABarLyingOnIt) {
  DrawList list;
  list.segment_points = {0, 1};
  list.segment_radius = {0.05f};
  list.segment_color = {Vec3f(0.7f, 0.7f, 0.7f)};
  list.point_radius = {0.05f, 0.05f};
  list.point_color.assign(2, Vec3f(0.7f, 0.7f, 0.7f));
  list.ground_tile = 100.0f;
  list.ground_half_size = 50.0f;
  list.shadows = false;
  list.occlusion_radius = 0.15f;
  const std::vector<Vec3f> positions = {Vec3f(-1, 0, 0.05f), Vec3f(1, 0, 0.05f)};
  const RenderCamera camera = camera_above(0.0f);
  const auto ground_at = [&](bool occlusion, float y) {
    LookSettings look;
    look.ambient_occlusion = occlusion;
    OsmesaRenderer renderer({kWidth, kHeight, 1, 0, look});
    Image image;
    renderer.render(list, positions, camera, image);
    const Eigen::Vector2f p = pixel_from_world(camera, kWidth, kHeight, Vec3f(0, y, 0));
    return test::brightness(image.pixel(static_cast<int>(p.x()), static_cast<int>(p.y())));
  };
  EXPECT_LT(ground_at(true, 0.07f), 0.9 * ground_at(false, 0.07f)) << "beside the bar";
  EXPECT_NEAR(ground_at(true, 0.6f), ground_at(false, 0.6f), 2.0) << "far from it";
}

// +1 stop doubles the linear light: with tone mapping off, a mid-grey ground's display value
// decoded by the display's gamma doubles (within the 8-bit rounding).
TEST(Look, OneStopOfExposureDoublesTheLight) {
  DrawList list;
  list.ground_tile = 100.0f;
  list.ground_half_size = 50.0f;
  list.shadows = false;
  const RenderCamera camera = camera_above(0.0f);
  const auto linear_ground = [&](float exposure) {
    LookSettings look;
    look.tone_mapping = false;
    look.exposure = exposure;
    OsmesaRenderer renderer({kWidth, kHeight, 1, 0, look});
    Image image;
    renderer.render(list, {}, camera, image);
    const std::uint8_t green = image.pixel(kWidth / 2, kHeight / 2)[1];
    return std::pow(static_cast<double>(green) / 255.0, 2.2);
  };
  const double base = linear_ground(-1.5f);
  EXPECT_NEAR(linear_ground(-0.5f) / base, 2.0, 0.05);
}

}  // namespace
}  // namespace dinam
