// Flat and auto shading (visual/sharp_edges.hpp): a face's corners get points of their own where
// it meets its neighbour sharply, and share them where it meets it smoothly, counted on a cube and
// on a 24-sided cylinder with n-gon caps (Blender's default cylinder).
#include "visual/sharp_edges.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <vector>

namespace dinam {
namespace {

struct Fanned {
  std::vector<Vec3> x;
  std::vector<Index> triangles;
  std::vector<Index> face;
};

// Faces (each a loop of point ids) fanned into triangles from their first corner.
Fanned fanned(std::vector<Vec3> x, const std::vector<std::vector<Index>>& faces) {
  Fanned out{std::move(x), {}, {}};
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (std::size_t k = 1; k + 1 < faces[f].size(); ++k) {
      out.triangles.insert(out.triangles.end(), {faces[f][0], faces[f][k], faces[f][k + 1]});
      out.face.push_back(static_cast<Index>(f));
    }
  }
  return out;
}

Fanned cylinder(int sides) {
  std::vector<Vec3> x;
  std::vector<std::vector<Index>> faces;
  std::vector<Index> top;
  std::vector<Index> bottom;
  for (int k = 0; k < sides; ++k) {
    const double a = 2.0 * std::numbers::pi * k / sides;
    x.emplace_back(std::cos(a), std::sin(a), 0.0);
    x.emplace_back(std::cos(a), std::sin(a), 1.0);
    const Index b = 2 * k;
    const Index n = 2 * ((k + 1) % sides);
    faces.push_back({b, n, n + 1, b + 1});
    top.push_back(b + 1);
    bottom.insert(bottom.begin(), b);
  }
  faces.push_back(top);
  faces.push_back(bottom);
  return fanned(x, faces);
}

// The distinct points the triangles use.
std::size_t points_used(const std::vector<Index>& triangles) {
  return std::set<Index>(triangles.begin(), triangles.end()).size();
}

TEST(SharpEdges, ACubesFacesEachGetTheirOwnCornersWhereTheyMeetAtRightAngles) {
  const std::vector<Vec3> corners{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                  {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const Fanned cube =
      fanned(corners,
             {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}});
  for (const double sharp : {-1.0, 30.0 * std::numbers::pi / 180.0}) {
    std::vector<Index> triangles = cube.triangles;
    const std::vector<Index> sources = split_at_sharp_edges(triangles, cube.face, cube.x, sharp, 8);
    EXPECT_EQ(sources.size(), 16U);  // each corner in three faces: two new points each
    EXPECT_EQ(points_used(triangles), 24U);
    for (std::size_t c = 0; c < triangles.size(); ++c) {
      const Index p = triangles[c];
      EXPECT_EQ(p < 8 ? p : sources[p - 8], cube.triangles[c]) << "a copy of its own corner";
    }
  }
  // At 100° no edge of the cube is sharp: it stays as it was.
  std::vector<Index> triangles = cube.triangles;
  EXPECT_TRUE(
      split_at_sharp_edges(triangles, cube.face, cube.x, 100.0 * std::numbers::pi / 180.0, 8)
          .empty());
  EXPECT_EQ(triangles, cube.triangles);
}

// Its sides turn by 15° at each edge: under 30° they share their points, and only the rims are
// split (48 more); flat, every side has its own four corners too (96 on the sides, 48 on the caps).
TEST(SharpEdges, ACylindersSidesStaySmoothUnderTheAngleAndItsRimsSharp) {
  const Fanned c = cylinder(24);
  std::vector<Index> auto_shaded = c.triangles;
  split_at_sharp_edges(auto_shaded, c.face, c.x, 30.0 * std::numbers::pi / 180.0, 48);
  EXPECT_EQ(points_used(auto_shaded), 96U);
  std::vector<Index> flat = c.triangles;
  split_at_sharp_edges(flat, c.face, c.x, -1.0, 48);
  EXPECT_EQ(points_used(flat), 144U);
  std::vector<Index> blunt = c.triangles;
  split_at_sharp_edges(blunt, c.face, c.x, 10.0 * std::numbers::pi / 180.0, 48);
  EXPECT_EQ(points_used(blunt), 144U) << "at 10°, each 15° turn is sharp";
}

}  // namespace
}  // namespace dinam
