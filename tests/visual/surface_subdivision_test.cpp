// Loop subdivision as drawn: counts as the scheme gives them, weights that make each refined
// point an affine combination, a flat sheet that stays flat with its border where it was, a
// closed coarse surface (an icosahedron) whose creases between faces smooth out level by level,
// and the draw list of a scene: its surfaces refined by default, its nodes and wires untouched.
#include "visual/surface_subdivision.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "model/model.hpp"
#include "test_support.hpp"
#include "visual/draw_list_from_model.hpp"

namespace dinam {
namespace {

// Positions of the refined points from base positions.
std::vector<Vec3> refined_positions(const DerivedPoints& points, const std::vector<Vec3>& base) {
  std::vector<Vec3> out;
  for (Index k = 0; k < points.size(); ++k) {
    Vec3 sum = Vec3::Zero();
    for (Index j = points.offsets[k]; j < points.offsets[k + 1]; ++j) {
      sum += static_cast<double>(points.weights[j]) * base[points.sources[j]];
    }
    out.push_back(sum);
  }
  return out;
}

// An n × n grid of unit cells in the plane z = 0, each cell two triangles.
void grid(int n, std::vector<Vec3>& points, std::vector<Index>& triangles) {
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      points.emplace_back(i, j, 0);
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const Index a = j * (n + 1) + i;
      triangles.insert(triangles.end(), {a, a + 1, a + n + 2, a, a + n + 2, a + n + 1});
    }
  }
}

// The twelve corners of an icosahedron on the unit sphere and its twenty faces.
void icosahedron(std::vector<Vec3>& points, std::vector<Index>& triangles) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  const double corners[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                 {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                 {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (const auto& c : corners) {
    points.push_back(Vec3(c[0], c[1], c[2]).normalized());
  }
  triangles = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
               4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
               6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
}

// The largest angle between the normals of two triangles that share an edge, in degrees.
double largest_crease_degrees(const std::vector<Vec3>& x, const std::vector<Index>& triangles) {
  std::map<std::pair<Index, Index>, std::vector<Vec3>> normals;
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const Vec3 n = (x[triangles[t + 1]] - x[triangles[t]])
                       .cross(x[triangles[t + 2]] - x[triangles[t]])
                       .normalized();
    for (int k = 0; k < 3; ++k) {
      const Index a = triangles[t + k];
      const Index b = triangles[t + (k + 1) % 3];
      normals[{std::min(a, b), std::max(a, b)}].push_back(n);
    }
  }
  double largest = 0.0;
  for (const auto& [edge, pair] : normals) {
    if (pair.size() == 2) {
      const double c = std::clamp(pair[0].dot(pair[1]), -1.0, 1.0);
      largest = std::max(largest, std::acos(c) * 180.0 / std::numbers::pi);
    }
  }
  return largest;
}

TEST(SurfaceSubdivision, EachLevelSplitsEveryTriangleInFourAndAddsAPointAnEdge) {
  std::vector<Vec3> x;
  std::vector<Index> triangles;
  grid(3, x, triangles);  // 16 points, 33 edges, 18 triangles
  const SubdividedSurface one = subdivide_loop(triangles, 1);
  EXPECT_EQ(one.triangles.size(), 4 * triangles.size());
  EXPECT_EQ(one.points.size(), 16 + 33);
  const SubdividedSurface two = subdivide_loop(triangles, 2);
  EXPECT_EQ(two.triangles.size(), 16 * triangles.size());
}

TEST(SurfaceSubdivision, EveryRefinedPointIsAnAffineCombinationOfTheNodes) {
  std::vector<Vec3> x;
  std::vector<Index> triangles;
  icosahedron(x, triangles);
  const SubdividedSurface surface = subdivide_loop(triangles, 2);
  for (Index k = 0; k < surface.points.size(); ++k) {
    double sum = 0.0;
    for (Index j = surface.points.offsets[k]; j < surface.points.offsets[k + 1]; ++j) {
      EXPECT_GT(surface.points.weights[j], 0.0f);  // within the nodes' hull
      sum += surface.points.weights[j];
    }
    EXPECT_NEAR(sum, 1.0, 1e-6) << k;
  }
}

// A flat sheet stays flat, and its border stays on the border lines: the smooth surface does not
// pull a flag's edge in from where its nodes are.
TEST(SurfaceSubdivision, AFlatSheetStaysFlatWithItsBorderInPlace) {
  std::vector<Vec3> x;
  std::vector<Index> triangles;
  grid(4, x, triangles);
  const SubdividedSurface surface = subdivide_loop(triangles, 2, x);
  const std::vector<Vec3> refined = refined_positions(surface.points, x);
  double low_x = 1e9;
  double high_x = -1e9;
  for (const Vec3& p : refined) {
    EXPECT_NEAR(p.z(), 0.0, 1e-6);
    low_x = std::min(low_x, p.x());
    high_x = std::max(high_x, p.x());
  }
  EXPECT_NEAR(low_x, 0.0, 1e-6);
  EXPECT_NEAR(high_x, 4.0, 1e-6);
  // The border's corners stay where they are (its straight runs are curves of their own).
  EXPECT_TRUE(std::any_of(refined.begin(), refined.end(),
                          [](const Vec3& p) { return (p - Vec3(4, 4, 0)).norm() < 1e-6; }));
}

// The icosahedron's faces meet at 41.8°; Loop's surface has continuous normals, so the crease
// between refined triangles shrinks with each level (about halving), and the points approach a
// round surface.
TEST(SurfaceSubdivision, ACoarseClosedSurfaceSmoothsOutLevelByLevel) {
  std::vector<Vec3> x;
  std::vector<Index> triangles;
  icosahedron(x, triangles);
  const double coarse = largest_crease_degrees(x, triangles);
  EXPECT_NEAR(coarse, 41.81, 0.01);
  double previous = coarse;
  for (int level = 1; level <= 3; ++level) {
    const SubdividedSurface surface = subdivide_loop(triangles, level);
    const std::vector<Vec3> refined = refined_positions(surface.points, x);
    const double crease = largest_crease_degrees(refined, surface.triangles);
    EXPECT_LT(crease, 0.65 * previous) << "level " << level;
    previous = crease;
    double low = 1e9;
    double high = 0.0;
    for (const Vec3& p : refined) {
      low = std::min(low, p.norm());
      high = std::max(high, p.norm());
    }
    EXPECT_LT(high / low, 1.06) << "level " << level;  // the icosahedron's own: 1.26
  }
  EXPECT_LT(previous, 8.0);
}

// A scene's draw list: a cloth's surface refined by default (its nodes' own points and
// the wire capsules as they were), `subdivide: 0` drawn as simulated, a scene that can tear not
// refined.
TEST(SurfaceSubdivision, TheDrawListRefinesSurfacesAndLeavesNodesAndWires) {
  const auto scene_text = [](const std::string& extra, const std::string& material) {
    return fmt::format(R"(version: 1
duration: 0.1
objects:
  - name: cloth
    mesh: {{grid: {{width: 1, height: 1, columns: 10, rows: 10}}}}
    material: {}
    style: both
{}  - name: rope
    mesh: {{polyline: {{points: [[0, 0, 1], [1, 0, 1]], segments: 4}}}}
    material: {{density: 1000, youngs_modulus: 1.0e7, radius: 0.004}}
)",
                       material, extra);
  };
  const char* cotton = "{preset: cotton}";
  const SceneDescription smooth = test::scene_from_yaml(scene_text("", cotton));
  const Model model = build_model(smooth);
  Bounds bounds;
  bounds.add(Vec3f(0, 0, 0));
  bounds.add(Vec3f(1, 1, 1));
  const DrawList list = make_draw_list(smooth, model, bounds, {Image{}, Image{}});
  ASSERT_EQ(list.surfaces.size(), 1u);
  // 10 × 10 cells of two triangles: level 1 (800 triangles; level 2 would pass 2 000).
  EXPECT_EQ(list.surfaces[0].triangles.size(), 4u * 200u * 3u);
  EXPECT_GT(list.derived.size(), 0);
  EXPECT_EQ(list.point_radius.size(),
            static_cast<std::size_t>(model.node_count() + list.derived.size()));
  for (const Index id : list.surfaces[0].triangles) {
    EXPECT_GE(id, model.node_count());  // drawn over refined points only
  }
  const std::size_t segments = list.segment_radius.size();

  const SceneDescription coarse = test::scene_from_yaml(scene_text("    subdivide: 0\n", cotton));
  const DrawList plain = make_draw_list(coarse, build_model(coarse), bounds, {Image{}, Image{}});
  EXPECT_EQ(plain.surfaces[0].triangles.size(), 200u * 3u);
  EXPECT_EQ(plain.derived.size(), 0);
  EXPECT_EQ(plain.segment_radius.size(), segments);  // the same wires either way

  const SceneDescription tearing =
      test::scene_from_yaml(scene_text("", "{preset: cotton, breaking: {strain: 0.3}}"));
  const DrawList torn = make_draw_list(tearing, build_model(tearing), bounds, {Image{}, Image{}});
  EXPECT_EQ(torn.derived.size(), 0);
}

TEST(SurfaceSubdivision, ALevelOutOfRangeOrOnAWireIsRefusedAtItsKey) {
  const auto error = [](const std::string& object_extra, const std::string& style) {
    try {
      test::scene_from_yaml(fmt::format(R"(version: 1
duration: 0.1
objects:
  - name: cloth
    mesh: {{grid: {{width: 1, height: 1, columns: 4, rows: 4}}}}
    material: {{preset: cotton}}
    style: {}
    {}
)",
                                        style, object_extra));
    } catch (const UserError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error("subdivide: 4", "surface").find("0 (drawn as simulated) to 3"),
            std::string::npos);
  EXPECT_NE(error("subdivide: 2", "wire").find("no surface to smooth"), std::string::npos);
  EXPECT_EQ(error("subdivide: 3", "surface"), "");
}

}  // namespace
}  // namespace dinam
