// Renderer tests that need no golden image: where a bar must appear follows from the camera.
#include "render/osmesa_renderer.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "render/camera.hpp"

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
  list.camera.position = Vec3f(0, -4, 1);
  list.camera.look_at = Vec3f(0, 0, 1);
  list.camera.fov_degrees = 40.0f;
  list.light_direction = Vec3f(0, -1, 0.3f);  // from the camera's side: the bar is well lit
  return list;
}

TEST(OsmesaRenderer, BarAppearsWhereTheCameraPutsItWithItsProjectedWidth) {
  const int width = 160;
  const int height = 120;
  OsmesaRenderer renderer(width, height);
  const DrawList list = one_bar();
  const std::vector<Vec3f> positions = {Vec3f(-1, 0, 1), Vec3f(1, 0, 1)};
  Image image;
  renderer.render(list, positions, image);
  ASSERT_EQ(image.width, width);
  ASSERT_EQ(image.height, height);

  // The bar's ends project to these pixels; between them, at the centre column, the bar is red.
  const Eigen::Vector2f left = pixel_from_world(list.camera, width, height, positions[0]);
  const Eigen::Vector2f right = pixel_from_world(list.camera, width, height, positions[1]);
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

TEST(OsmesaRenderer, SameInputGivesTheSamePixels) {
  OsmesaRenderer renderer(96, 64);
  const DrawList list = one_bar();
  const std::vector<Vec3f> positions = {Vec3f(-1, 0, 1.2f), Vec3f(1, 0.5f, 0.8f)};
  Image first;
  Image second;
  renderer.render(list, positions, first);
  renderer.render(list, positions, second);
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
