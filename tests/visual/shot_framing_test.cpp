// The framing rule's measure against a pinhole camera worked by hand, and its verdicts: a shot
// that cuts its subject, one where it is too small, one behind the camera, and the torn parts
// that no longer count.
#include "visual/shot_framing.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace dinam {
namespace {

// Looking along +y from the origin with a 90° vertical field: at depth 10 the picture spans
// z in [−10, 10] and, at aspect 2, x in [−20, 20].
RenderCamera square_on() {
  RenderCamera camera;
  camera.position = Vec3f::Zero();
  camera.look_at = Vec3f(0.0f, 10.0f, 0.0f);
  camera.up = Vec3f::UnitZ();
  camera.fov_degrees = 90.0f;
  return camera;
}

// One wire of `radius` from a to b.
DrawList wire(float radius) {
  DrawList list;
  list.segment_points = {0, 1};
  list.segment_radius = {radius};
  list.point_radius = {0.0f, 0.0f};
  return list;
}

TEST(ShotFraming, ExtentIsThePinholeProjectionOfTheWireAndItsRadius) {
  const std::vector<Vec3f> ends = {{-5.0f, 10.0f, 2.0f}, {8.0f, 10.0f, -4.0f}};
  const PictureExtent bare = picture_extent(wire(0.0f), ends, square_on(), 2.0f);
  // A torn wire (radius 0) is not drawn: nothing to frame.
  EXPECT_TRUE(bare.empty);
  const PictureExtent extent = picture_extent(wire(1.0f), ends, square_on(), 2.0f);
  ASSERT_FALSE(extent.empty);
  // x/20 maps to [−1, 1] across, z/10 up; a radius of 1 at depth 10 is 0.05 of the height and
  // 0.025 of the width.
  EXPECT_NEAR(extent.left, 0.5f + 0.5f * (-5.0f / 20.0f) - 0.025f, 1e-6f);
  EXPECT_NEAR(extent.right, 0.5f + 0.5f * (8.0f / 20.0f) + 0.025f, 1e-6f);
  EXPECT_NEAR(extent.top, 0.5f - 0.5f * (2.0f / 10.0f) - 0.05f, 1e-6f);
  EXPECT_NEAR(extent.bottom, 0.5f - 0.5f * (-4.0f / 10.0f) + 0.05f, 1e-6f);
  EXPECT_EQ(framing_problem(extent, 0.35f), "");  // 37.5 % × 40 %
}

TEST(ShotFraming, ASubjectTheFrameCutsOrThatIsTooSmallFails) {
  // Reaching 30 m to the right at depth 10: a quarter of the width outside.
  const std::vector<Vec3f> long_wire = {{0.0f, 10.0f, 0.0f}, {30.0f, 10.0f, 0.0f}};
  EXPECT_EQ(framing_problem(picture_extent(wire(0.0f), long_wire, square_on(), 2.0f), 0.5f),
            "nothing is drawn");  // a wire of radius 0 is torn
  const PictureExtent right = picture_extent(wire(0.01f), long_wire, square_on(), 2.0f);
  EXPECT_NE(framing_problem(right, 0.5f).find("cuts the subject at the right (25 % of the width"),
            std::string::npos)
      << framing_problem(right, 0.5f);
  // 4 m of 40 across and a thin wire's height: a tenth of the width.
  const std::vector<Vec3f> short_wire = {{-2.0f, 10.0f, 0.0f}, {2.0f, 10.0f, 0.0f}};
  const PictureExtent small = picture_extent(wire(0.01f), short_wire, square_on(), 2.0f);
  EXPECT_NE(framing_problem(small, 0.5f).find("spans 10 % of the width"), std::string::npos)
      << framing_problem(small, 0.5f);
  EXPECT_EQ(framing_problem(small, 0.05f), "");
  // Half behind the eye.
  const std::vector<Vec3f> through = {{0.0f, -1.0f, 0.0f}, {0.0f, 10.0f, 0.0f}};
  EXPECT_NE(framing_problem(picture_extent(wire(0.01f), through, square_on(), 2.0f), 0.5f)
                .find("behind the camera"),
            std::string::npos);
}

TEST(ShotFraming, SurfacesCountByTheirPointsAndATornTriangleNot) {
  DrawList list;
  list.point_radius = {0.0f, 0.0f, 0.0f, 0.0f};
  SurfaceBatch batch;
  batch.triangles = {0, 1, 2, 3, 3, 3};  // the second torn: collapsed onto point 3
  list.surfaces.push_back(batch);
  const std::vector<Vec3f> points = {
      {-10.0f, 10.0f, -5.0f}, {10.0f, 10.0f, -5.0f}, {0.0f, 10.0f, 5.0f}, {19.0f, 10.0f, 9.0f}};
  const PictureExtent extent = picture_extent(list, points, square_on(), 2.0f);
  EXPECT_NEAR(extent.left, 0.25f, 1e-6f);
  EXPECT_NEAR(extent.right, 0.75f, 1e-6f);
  EXPECT_NEAR(extent.top, 0.25f, 1e-6f);
  EXPECT_NEAR(extent.bottom, 0.75f, 1e-6f);
}

TEST(ShotFraming, ASubdividedSurfaceCountsByTheFramePointsItIsMadeFrom) {
  DrawList list;
  list.derived.offsets = {0, 2};  // one point made from points 1 and 2 (the frame gives 3)
  list.derived.sources = {1, 2};
  list.derived.weights = {0.5f, 0.5f};
  list.point_radius = {0.0f, 0.0f, 0.0f, 0.0f};
  SurfaceBatch batch;
  batch.triangles = {0, 3, 0};  // refined: it names the made point, not the frame's 1 and 2
  list.surfaces.push_back(batch);
  const std::vector<Vec3f> points = {
      {0.0f, 10.0f, 0.0f}, {-10.0f, 10.0f, -5.0f}, {10.0f, 10.0f, 5.0f}};
  const PictureExtent extent = picture_extent(list, points, square_on(), 2.0f);
  EXPECT_NEAR(extent.left, 0.25f, 1e-6f);
  EXPECT_NEAR(extent.right, 0.75f, 1e-6f);
  EXPECT_NEAR(extent.top, 0.25f, 1e-6f);
  EXPECT_NEAR(extent.bottom, 0.75f, 1e-6f);
}

}  // namespace
}  // namespace dinam
