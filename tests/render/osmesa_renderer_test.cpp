// Renderer tests that need no golden image: where things appear follows from the camera and the
// light.
#include "render/osmesa_renderer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "core/error.hpp"
#include "render/camera.hpp"
#include "render_test_support.hpp"

namespace dinam {
namespace {

bool is_red(const std::uint8_t* p) {
  return p[0] > 120 && p[1] < 90 && p[2] < 90;
}

// One red bar along x, 2 m long, radius 0.05 m, 4 m in front of the camera, no ground.
DrawList one_bar() {
  DrawList list;
  list.segment_points = {0, 1};
  list.segment_radius = {0.05f};
  list.segment_color = {Vec3f(0.9f, 0.05f, 0.05f)};
  list.point_radius = {0.0f, 0.0f};
  list.point_color = {Vec3f::Zero(), Vec3f::Zero()};
  list.ground_visible = false;
  list.shadows = false;
  list.light_direction = Vec3f(0, -1, 0.3f);  // from the camera's side: the bar is well lit
  return list;
}

RenderCamera front_camera() {
  RenderCamera camera;
  camera.position = Vec3f(0, -4, 1);
  camera.look_at = Vec3f(0, 0, 1);
  camera.fov_degrees = 40.0f;
  return camera;
}

TEST(OsmesaRenderer, BarAppearsWhereTheCameraPutsItWithItsProjectedWidth) {
  const int width = 160;
  const int height = 120;
  OsmesaRenderer renderer({width, height, 4, 0, {}});
  const DrawList list = one_bar();
  const RenderCamera camera = front_camera();
  const std::vector<Vec3f> positions = {Vec3f(-1, 0, 1), Vec3f(1, 0, 1)};
  Image image;
  renderer.render(list, positions, camera, image);
  ASSERT_EQ(image.width, width);
  ASSERT_EQ(image.height, height);

  // The bar's ends project to these pixels; between them, at the centre column, the bar is red.
  const Eigen::Vector2f left = pixel_from_world(camera, width, height, positions[0]);
  const Eigen::Vector2f right = pixel_from_world(camera, width, height, positions[1]);
  const int row = static_cast<int>(std::lround(left.y()));
  EXPECT_TRUE(is_red(image.pixel(width / 2, row)));
  EXPECT_TRUE(is_red(image.pixel(static_cast<int>(left.x()) + 3, row)));
  EXPECT_TRUE(is_red(image.pixel(static_cast<int>(right.x()) - 3, row)));
  EXPECT_FALSE(is_red(image.pixel(static_cast<int>(left.x()) - 4, row)));
  EXPECT_FALSE(is_red(image.pixel(static_cast<int>(right.x()) + 4, row)));

  // Its height in pixels is its diameter seen from 4 m: 2r / (2 · 4 tan 20°) of the image height.
  int red_rows = 0;
  for (int y = 0; y < height; ++y) {
    red_rows += is_red(image.pixel(width / 2, y)) ? 1 : 0;
  }
  const double expected_rows = 0.1 / (2.0 * 4.0 * std::tan(20.0 * M_PI / 180.0)) * height;
  EXPECT_NEAR(red_rows, expected_rows, 2.0);  // ±2 pixels: anti-aliased edges

  // Nothing else is red: the corners show the sky.
  EXPECT_FALSE(is_red(image.pixel(0, 0)));
  EXPECT_FALSE(is_red(image.pixel(width - 1, height - 1)));
}

// A bar 0.4 pixel across (drawn as a line, capsule.vert) shows in every column it spans, on its
// row alone, with the shadow pass on and off.
TEST(OsmesaRenderer, BarNarrowerThanAPixelShowsAlongItsWholeLength) {
  const int width = 160;
  const int height = 120;
  const RenderCamera camera = front_camera();
  // A pixel spans 2 · 4 tan 20° / 120 = 0.0243 m at 4 m. The bar lies half a pixel above the
  // image's middle, along the centres of a row of pixels, and is 0.4 pixel wide.
  const float pixel = 8.0f * std::tan(20.0f * std::numbers::pi_v<float> / 180.0f) / height;
  const std::vector<Vec3f> positions = {Vec3f(-1, 0, 1 + 0.5f * pixel),
                                        Vec3f(1, 0, 1 + 0.5f * pixel)};
  DrawList thin = one_bar();
  thin.segment_radius = {0.0012f};
  for (const int shadow_resolution : {0, 512}) {
    OsmesaRenderer renderer({width, height, 4, shadow_resolution, {}});
    Image with_bar;
    renderer.render(thin, positions, camera, with_bar);
    DrawList empty = thin;
    empty.segment_points.clear();
    empty.segment_radius.clear();
    empty.segment_color.clear();
    Image without_bar;
    renderer.render(empty, positions, camera, without_bar);
    const Eigen::Vector2f left = pixel_from_world(camera, width, height, positions[0]);
    const Eigen::Vector2f right = pixel_from_world(camera, width, height, positions[1]);
    const int row = static_cast<int>(std::lround(left.y()));
    int marked = 0;
    int columns = 0;
    for (int x = static_cast<int>(left.x()) + 2; x <= static_cast<int>(right.x()) - 2; ++x) {
      ++columns;
      bool differs = false;
      for (int y = row - 1; y <= row + 1; ++y) {
        const std::uint8_t* a = with_bar.pixel(x, y);
        const std::uint8_t* b = without_bar.pixel(x, y);
        differs = differs || std::abs(int{a[1]} - int{b[1]}) > 20;  // red takes green away
      }
      marked += differs ? 1 : 0;
    }
    EXPECT_EQ(marked, columns) << "shadow map " << shadow_resolution;
    // Two rows away, nothing changed.
    for (const int y : {row - 2, row + 2}) {
      EXPECT_EQ(test::brightness(with_bar.pixel(width / 2, y)),
                test::brightness(without_bar.pixel(width / 2, y)));
    }
  }
}

// Every pixel of a frame is opaque: the edges of wires, drawn with alpha to coverage, once left
// alpha below 255 in the PNG, so a frame laid over black gave its wires dark fringes.
TEST(OsmesaRenderer, FramesAreOpaqueAlongTheEdgesOfWires) {
  const int width = 160;
  const int height = 120;
  const RenderCamera camera = front_camera();
  DrawList wires = one_bar();
  wires.segment_points = {0, 1, 2, 3};
  wires.segment_radius = {0.0012f, 0.02f};
  wires.segment_color = {Vec3f(0.9f, 0.05f, 0.05f), Vec3f(0.1f, 0.1f, 0.8f)};
  wires.point_radius.assign(4, 0.0f);
  wires.point_color.assign(4, Vec3f::Zero());
  const std::vector<Vec3f> positions = {Vec3f(-1, 0, 1.003f), Vec3f(1, 0.5f, 1.2f),
                                        Vec3f(-0.7f, 0, 0.6f), Vec3f(0.9f, -0.3f, 1.4f)};
  for (const int samples : {1, 4}) {
    OsmesaRenderer renderer({width, height, samples, 512, {}});
    Image image;
    renderer.render(wires, positions, camera, image);
    int translucent = 0;
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        translucent += image.pixel(x, y)[3] != 255 ? 1 : 0;
      }
    }
    EXPECT_EQ(translucent, 0) << samples << " samples";
  }
}

// On a transparent background (`image: {background: transparent}`) a wire alone in the picture
// is all there is: alpha 0 and black where nothing is drawn, 255 inside the wire, in between
// along its edges under multisampling, and there its colour is the wire's own (straight alpha),
// not darkened by the coverage: composited over any picture it has no fringe. Both ways a frame
// reaches the display: drawn straight to it, and through the finishing pass (ambient occlusion).
TEST(OsmesaRenderer, ATransparentBackgroundLeavesOnlyWhatIsDrawnWithItsCoverage) {
  const int width = 160;
  const int height = 120;
  DrawList wire = one_bar();
  wire.segment_radius = {0.02f};
  wire.segment_color = {Vec3f(0.1f, 0.1f, 0.8f)};
  const std::vector<Vec3f> positions = {Vec3f(-0.7f, 0, 0.6f), Vec3f(0.9f, -0.3f, 1.4f)};
  for (const bool occlusion : {false, true}) {
    for (const int samples : {1, 4}) {
      LookSettings look;
      look.transparent_background = true;
      look.ambient_occlusion = occlusion;
      OsmesaRenderer renderer({width, height, samples, 0, look});
      Image image;
      renderer.render(wire, positions, front_camera(), image);
      const std::string what = fmt::format("{} samples, occlusion {}", samples, occlusion);
      EXPECT_EQ(image.pixel(0, 0)[3], 0) << what;
      EXPECT_EQ(image.pixel(0, 0)[2], 0) << what;
      int inside = 0;
      int edge = 0;
      double inside_blue = 0.0;
      for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
          const std::uint8_t* p = image.pixel(x, y);
          inside += p[3] == 255 ? 1 : 0;
          inside_blue += p[3] == 255 ? p[2] : 0;
        }
      }
      ASSERT_GT(inside, 50) << what;
      inside_blue /= inside;
      for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
          const std::uint8_t* p = image.pixel(x, y);
          if (p[3] > 0 && p[3] < 255) {
            ++edge;
            // Straight colour: as blue as the wire (its shading spans about ±30 %), whatever
            // the coverage; multiplied by it, a pixel half covered would be half as bright.
            if (p[3] >= 64) {
              EXPECT_GT(p[2], 0.6 * inside_blue) << what << " at " << x << ", " << y;
            }
          }
        }
      }
      EXPECT_EQ(edge > 0, samples > 1) << what;
    }
  }
}

// A 1 m square facing the camera, textured with a red left half and a blue right half: each half
// shows where the camera puts it, lit from either side.
TEST(OsmesaRenderer, TexturedSurfaceShowsItsPictureWhereTheCameraPutsIt) {
  const int width = 160;
  const int height = 120;
  OsmesaRenderer renderer({width, height, 4, 0, {}});
  DrawList list = one_bar();
  list.segment_points.clear();
  list.segment_radius.clear();
  list.segment_color.clear();
  list.point_radius.assign(4, 0.0f);
  list.point_color.assign(4, Vec3f(0.5f, 0.5f, 0.5f));
  list.point_uv = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};  // v from the top of the picture
  Image texture(2, 1);
  texture.rgba = {230, 20, 20, 255, 20, 20, 230, 255};
  list.textures.push_back(texture);
  list.surfaces.push_back({{0, 1, 2, 0, 2, 3}, 0});
  const std::vector<Vec3f> positions = {Vec3f(-0.5f, 0, 0.5f), Vec3f(0.5f, 0, 0.5f),
                                        Vec3f(0.5f, 0, 1.5f), Vec3f(-0.5f, 0, 1.5f)};
  const RenderCamera camera = front_camera();
  for (const Vec3f& light : {Vec3f(0, -1, 0.3f), Vec3f(0, 1, 0.3f)}) {  // front-lit, back-lit
    list.light_direction = light;
    Image image;
    renderer.render(list, positions, camera, image);
    const Eigen::Vector2f left = pixel_from_world(camera, width, height, Vec3f(-0.25f, 0, 1));
    const Eigen::Vector2f right = pixel_from_world(camera, width, height, Vec3f(0.25f, 0, 1));
    const std::uint8_t* l = image.pixel(static_cast<int>(left.x()), static_cast<int>(left.y()));
    const std::uint8_t* r = image.pixel(static_cast<int>(right.x()), static_cast<int>(right.y()));
    EXPECT_GT(l[0], l[2] + 40) << "left half is red";
    EXPECT_GT(r[2], r[0] + 40) << "right half is blue";
  }
}

// A cloth lying on the ground, as contact leaves it (a micrometre into it): the ground never
// hides it, in a frame of one instant and in one averaged over several (motion blur), where the
// depths are drawn in a pass of their own. Before the ground yielded its depths, the cloth showed
// as speckle or not at all.
TEST(OsmesaRenderer, GroundNeverHidesASurfaceLyingOnIt) {
  const int width = 160;
  const int height = 120;
  DrawList list = one_bar();
  list.segment_points.clear();
  list.segment_radius.clear();
  list.segment_color.clear();
  list.ground_visible = true;
  list.point_radius.assign(4, 0.0f);
  list.point_color.assign(4, Vec3f(0.5f, 0.5f, 0.5f));
  list.point_uv = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  Image red(1, 1);
  red.rgba = {230, 20, 20, 255};
  list.textures.push_back(red);
  list.surfaces.push_back({{0, 1, 2, 0, 2, 3}, 0});
  list.light_direction = Vec3f(0.3f, -0.4f, 1.0f);
  const float below = -1.13e-6f;  // m, where contact's penalty holds a resting node
  const std::vector<Vec3f> positions = {Vec3f(-1, -1, below), Vec3f(1, -1, below),
                                        Vec3f(1, 1, below), Vec3f(-1, 1, below)};
  RenderCamera camera;
  camera.position = Vec3f(0, -5, 1.2f);  // low: the ground is seen at a grazing angle
  camera.look_at = Vec3f(0, 0, 0);
  camera.fov_degrees = 40.0f;
  for (const int instants : {1, 3}) {
    OsmesaRenderer renderer({width, height, 4, 512, {}});
    const std::vector<FrameSample> samples(static_cast<std::size_t>(instants),
                                           FrameSample{&positions, camera});
    Image image;
    renderer.render(list, samples, image);
    int points = 0;
    int hidden = 0;
    for (float x = -0.8f; x <= 0.8f; x += 0.1f) {
      for (float y = -0.8f; y <= 0.8f; y += 0.1f) {
        const Eigen::Vector2f pixel = pixel_from_world(camera, width, height, Vec3f(x, y, 0));
        const std::uint8_t* p =
            image.pixel(static_cast<int>(pixel.x()), static_cast<int>(pixel.y()));
        ++points;
        hidden += p[0] > p[1] + 40 ? 0 : 1;  // the red cloth, or the grey ground
      }
    }
    EXPECT_EQ(hidden, 0) << "of " << points << " points, " << instants << " instants";
  }
}

// A bar held above the ground under a light from straight above darkens the ground beneath it
// (compared with the same pixel drawn without shadows), and only there.
TEST(OsmesaRenderer, BarCastsAShadowOnTheGround) {
  const int width = 160;
  const int height = 120;
  DrawList list = one_bar();
  list.ground_visible = true;
  list.ground_tile = 100.0f;  // one checker colour over the whole view
  list.ground_half_size = 50.0f;
  list.light_direction = Vec3f(0, 0, 1);
  list.shadow_bounds_min = Vec3f(-1, -1, 0);
  list.shadow_bounds_max = Vec3f(1, 1, 1);
  const std::vector<Vec3f> positions = {Vec3f(-0.6f, 0, 0.5f), Vec3f(0.6f, 0, 0.5f)};
  RenderCamera camera;
  camera.position = Vec3f(0, -2.5f, 2.5f);
  camera.look_at = Vec3f(0, 0, 0);
  const Eigen::Vector2f under = pixel_from_world(camera, width, height, Vec3f(0, 0, 0));
  const Eigen::Vector2f beside = pixel_from_world(camera, width, height, Vec3f(0, 0.5f, 0));
  auto ground_brightness = [&](bool shadows, const Eigen::Vector2f& at) {
    list.shadows = shadows;
    OsmesaRenderer renderer({width, height, 1, shadows ? 1024 : 0, {}});
    Image image;
    renderer.render(list, positions, camera, image);
    return test::brightness(image.pixel(static_cast<int>(at.x()), static_cast<int>(at.y())));
  };
  EXPECT_LT(ground_brightness(true, under), 0.8 * ground_brightness(false, under));
  EXPECT_NEAR(ground_brightness(true, beside), ground_brightness(false, beside), 2.0);
}

// Light from +x at 45°: a bar at height 0.5 above x = 0 shadows the ground at x = −0.5, not at
// x = +0.5 (a mirrored shadow map would do the opposite).
TEST(OsmesaRenderer, ShadowFallsAwayFromTheLight) {
  const int width = 160;
  const int height = 120;
  DrawList list = one_bar();
  list.ground_visible = true;
  list.ground_tile = 100.0f;
  list.ground_half_size = 50.0f;
  list.light_direction = Vec3f(1, 0, 1);
  list.shadow_bounds_min = Vec3f(-1, -1, 0);
  list.shadow_bounds_max = Vec3f(1, 1, 1);
  const std::vector<Vec3f> positions = {Vec3f(0, -0.6f, 0.5f), Vec3f(0, 0.6f, 0.5f)};
  RenderCamera camera;
  camera.position = Vec3f(0, -2.5f, 2.5f);
  camera.look_at = Vec3f(0, 0, 0);
  auto brightness_at = [&](bool shadows, const Vec3f& world) {
    list.shadows = shadows;
    OsmesaRenderer renderer({width, height, 1, shadows ? 1024 : 0, {}});
    Image image;
    renderer.render(list, positions, camera, image);
    const Eigen::Vector2f at = pixel_from_world(camera, width, height, world);
    return test::brightness(image.pixel(static_cast<int>(at.x()), static_cast<int>(at.y())));
  };
  const Vec3f away(-0.5f, 0, 0);
  const Vec3f towards(0.5f, 0, 0);
  EXPECT_LT(brightness_at(true, away), 0.8 * brightness_at(false, away));
  EXPECT_NEAR(brightness_at(true, towards), brightness_at(false, towards), 2.0);
}

TEST(OsmesaRenderer, SameInputGivesTheSamePixels) {
  OsmesaRenderer renderer({96, 64, 4, 512, {}});
  DrawList list = one_bar();
  list.ground_visible = true;
  list.shadows = true;
  const std::vector<Vec3f> positions = {Vec3f(-1, 0, 1.2f), Vec3f(1, 0.5f, 0.8f)};
  Image first;
  Image second;
  renderer.render(list, positions, front_camera(), first);
  renderer.render(list, positions, front_camera(), second);
  EXPECT_EQ(first.rgba, second.rgba);
}

TEST(ShaderProgram, MissingShaderNamesEveryFolderTried) {
  try {
    find_shader("no_such_shader.vert");
    FAIL() << "a missing shader was found";
  } catch (const RuntimeError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("no_such_shader.vert"), std::string::npos);
    EXPECT_NE(message.find(DINAM_SOURCE_DIR "/shaders/no_such_shader.vert"), std::string::npos)
        << message;
    EXPECT_NE(message.find("DINAM_SHADER_DIR"), std::string::npos);
  }
}

}  // namespace
}  // namespace dinam
