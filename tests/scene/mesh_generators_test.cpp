#include "scene/mesh_generators.hpp"

#include <gtest/gtest.h>

#include "model/model.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

Model model_of_mesh(const std::string& mesh_yaml) {
  return build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
objects:
  - mesh: {}
    material: {{density: 1000, youngs_modulus: 1e6, radius: 0.01}}
)",
                                                       mesh_yaml)));
}

// A grid of c × r cells has (c + 1)(r + 1) nodes, c (r + 1) + r (c + 1) sides, and one or two
// diagonals per cell.
TEST(MeshGenerators, GridCountsFollowTheCellCounts) {
  const int c = 4;
  const int r = 3;
  const int sides = c * (r + 1) + r * (c + 1);
  const std::string base = "{grid: {width: 2, height: 1.5, columns: 4, rows: 3, diagonals: ";
  for (const auto& [diagonals, per_cell] :
       std::vector<std::pair<std::string, int>>{{"none", 0}, {"one", 1}, {"both", 2}}) {
    const Model model = model_of_mesh(base + diagonals + "}}");
    EXPECT_EQ(model.node_count(), (c + 1) * (r + 1)) << diagonals;
    EXPECT_EQ(model.bar_count(), sides + per_cell * c * r) << diagonals;
  }
}

TEST(MeshGenerators, GridVertexIdsRunAlongRows) {
  const RawMesh mesh = make_grid({.width = 2.0, .height = 1.0, .columns = 2, .rows = 1});
  ASSERT_EQ(mesh.vertices.size(), 6u);
  EXPECT_TRUE(mesh.vertices[2].isApprox(Vec3(2, 0, 0)));  // end of row 0
  EXPECT_TRUE(mesh.vertices[3].isApprox(Vec3(0, 1, 0)));  // start of row 1
}

TEST(MeshGenerators, PolylineDividesEachSpan) {
  const Model model =
      model_of_mesh("{polyline: {points: [[0, 0, 0], [1, 0, 0], [1, 2, 0]], segments: 4}}");
  EXPECT_EQ(model.node_count(), 9);  // 1 + 2 spans × 4
  EXPECT_EQ(model.bar_count(), 8);
  EXPECT_DOUBLE_EQ(model.bar_rest_length.front(), 0.25);
  EXPECT_DOUBLE_EQ(model.bar_rest_length.back(), 0.5);
}

}  // namespace
}  // namespace dinam
