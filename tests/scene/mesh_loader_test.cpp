// Edge extraction from files read with assimp: each format gives the nodes and bars its shape
// has, counted by hand in the comment of each data file.
#include "scene/mesh_loader.hpp"

#include <gtest/gtest.h>

#include "model/model.hpp"
#include "scene/mesh_generators.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// A one-object scene around a mesh file, built into a model.
Model model_of_file(const std::string& file) {
  return build_model(test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
objects:
  - mesh: {{file: {}}}
    material: {{density: 1000, youngs_modulus: 1e6, radius: 0.01}}
)",
                                                       file)));
}

TEST(MeshLoader, CubeObjWithQuadFacesHasTwelveBars) {
  const Model model = model_of_file("cube.obj");
  EXPECT_EQ(model.node_count(), 8);
  EXPECT_EQ(model.bar_count(), 12);  // every edge is shared by two faces, and appears once
  EXPECT_EQ(model.face_count(), 6);
  for (const double length : model.bar_rest_length) {
    EXPECT_DOUBLE_EQ(length, 1.0);  // no diagonals: the quads were not triangulated
  }
}

TEST(MeshLoader, TriangleSoupStlIsWeldedIntoOneStructure) {
  const RawMesh raw = load_mesh_file(test::data_dir() / "cube_soup.stl", {});
  EXPECT_EQ(raw.faces.size(), 12u);
  EXPECT_GE(raw.vertices.size(), 8u);  // assimp keeps one vertex per triangle corner
  const Model model = model_of_file("cube_soup.stl");
  EXPECT_EQ(model.node_count(), 8);
  EXPECT_EQ(model.bar_count(), 18);  // 12 cube edges + one diagonal on each of 6 faces
}

TEST(MeshLoader, ObjLineElementsBecomeAChain) {
  const Model model = model_of_file("rope.obj");
  EXPECT_EQ(model.node_count(), 5);
  EXPECT_EQ(model.bar_count(), 4);
  EXPECT_EQ(model.face_count(), 0);
  for (const double length : model.bar_rest_length) {
    EXPECT_DOUBLE_EQ(length, 0.25);
  }
}

TEST(MeshLoader, PlyTetrahedronHasSixBars) {
  const Model model = model_of_file("tetra.ply");
  EXPECT_EQ(model.node_count(), 4);
  EXPECT_EQ(model.bar_count(), 6);
}

TEST(MeshLoader, GltfPyramidKeepsItsNodeTransform) {
  const Model model = model_of_file("pyramid.gltf");
  EXPECT_EQ(model.node_count(), 5);
  EXPECT_EQ(model.bar_count(), 9);  // 4 base sides + 1 base diagonal + 4 slant edges
  double lowest = 1e9;
  for (const Vec3& p : model.node_initial_x) {
    lowest = std::min(lowest, p.z());
  }
  EXPECT_DOUBLE_EQ(lowest, 2.0);  // the glTF node's translation (0, 0, 2) was applied
}

// `up_axis: y` turns a y-up file z-up as a z-up program's y-up export was made (Blender's: Up Y,
// Forward −Z): the file's (x, y, z) is the world's (x, −z, y).
TEST(MeshLoader, UpAxisYTurnsTheFilesUpToTheWorldsUp) {
  const auto scene_of = [](const std::string& mesh) {
    return test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
objects:
  - mesh: {}
    material: {{density: 1000, youngs_modulus: 1e6, radius: 0.01}}
)",
                                             mesh));
  };
  const SceneDescription as_is = scene_of("{file: pyramid.gltf, up_axis: z}");
  const SceneDescription turned = scene_of("{file: pyramid.gltf, up_axis: y}");
  const std::vector<Vec3>& before = as_is.objects[0].mesh.vertices;
  const std::vector<Vec3>& after = turned.objects[0].mesh.vertices;
  ASSERT_EQ(before.size(), after.size());
  for (std::size_t i = 0; i < before.size(); ++i) {
    EXPECT_EQ(after[i], Vec3(before[i].x(), -before[i].z(), before[i].y())) << i;
  }
  // Said either way, nothing to warn of.
  EXPECT_TRUE(as_is.warnings.empty());
  EXPECT_TRUE(turned.warnings.empty());
}

// A file that is probably y-up as dinam receives it gets a warning naming the key that turns it,
// and a z-up file none; an OBJ that Blender wrote only where its mesh looks y-up (an upright
// square exported Up Y stands on y = 0, flat in z = 0), not the same square exported Up Z.
TEST(MeshLoader, AFileThatIsProbablyYUpIsWarnedOf) {
  const auto warnings_of = [](const std::string& file) {
    return test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
objects:
  - mesh: {{file: {}, translation: [0, 0, 3]}}
    material: {{density: 1000, youngs_modulus: 1e6, radius: 0.01}}
)",
                                             file))
        .warnings;
  };
  const std::vector<std::string> gltf = warnings_of("pyramid.gltf");
  ASSERT_EQ(gltf.size(), 1u);
  test::expect_contains(gltf[0], {"inline.yaml:4:", "glTF", "up_axis: y"});
  const std::vector<std::string> blender = warnings_of("blender_y_up.obj");
  ASSERT_EQ(blender.size(), 1u);
  test::expect_contains(blender[0], {"Blender wrote this OBJ", "up_axis: y"});
  EXPECT_TRUE(warnings_of("cube.obj").empty());
  EXPECT_TRUE(warnings_of("blender_z_up.obj").empty());
}

// The nodes of an OBJ file are numbered as its `v` lines, whatever order its faces meet them in,
// so that a point cache written in node order moves the artist's own object.
TEST(MeshLoader, NodesFollowAnObjFilesVertexOrder) {
  const Model model = model_of_file("out_of_order.obj");
  ASSERT_EQ(model.node_count(), 4);
  EXPECT_EQ(model.objects[0].source_vertex_count, 6);
  const std::vector<Vec3> file_order{{0, 0, 1}, {1, 0, 1}, {1, 0, 2}, {0, 0, 2}};
  for (Index k = 0; k < 4; ++k) {
    EXPECT_EQ(model.node_source_vertex[k], k);
    EXPECT_EQ(model.node_initial_x[k], file_order[k]) << k;
  }
  // Bars follow their nodes' ids.
  for (Index b = 1; b < model.bar_count(); ++b) {
    const auto ids = [&](Index bar) {
      return std::pair{std::min(model.bar_nodes[2 * bar], model.bar_nodes[2 * bar + 1]),
                       std::max(model.bar_nodes[2 * bar], model.bar_nodes[2 * bar + 1])};
    };
    EXPECT_LT(ids(b - 1), ids(b));
  }
  // A generated mesh has no file numbering.
  const Model grid = build_model(test::scene_from_yaml(R"(version: 1
duration: 1
objects:
  - mesh: {grid: {width: 1, height: 1, columns: 2, rows: 2}}
    material: {density: 1000, youngs_modulus: 1e6, radius: 0.01}
)"));
  EXPECT_EQ(grid.objects[0].source_vertex_count, 0);
  for (const Index source : grid.node_source_vertex) {
    EXPECT_EQ(source, -1);
  }
}

// `indices` of an OBJ file are the numbers of its `v` lines, as the program that wrote it (and the
// user) sees them, not assimp's vertex per face corner.
TEST(MeshLoader, IndicesOfAnObjFileAreItsVertexNumbers) {
  const auto scene_pinning = [](int index) {
    return test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
objects:
  - mesh: {{file: out_of_order.obj}}
    material: {{density: 1000, youngs_modulus: 1e6, radius: 0.01}}
    pinned: {{indices: [{}]}}
)",
                                             index));
  };
  const Model model = build_model(scene_pinning(2));
  for (Index k = 0; k < model.node_count(); ++k) {
    EXPECT_EQ(model.pinned(k), k == 2) << k;
  }
  EXPECT_EQ(model.node_initial_x[2], Vec3(1, 0, 2));  // the file's v line 2 (from 0)
  try {
    scene_pinning(4);
    ADD_FAILURE() << "vertex 4 is on no face";
  } catch (const UserError& e) {
    test::expect_contains(e.message(), {"vertex 4 of the mesh file is on no face or line"});
  }
  try {
    scene_pinning(6);
    ADD_FAILURE() << "the file has 6 vertices";
  } catch (const UserError& e) {
    test::expect_contains(e.message(), {"the mesh has 6 vertices"});
  }
}

// banner.obj: two triangles in group "cloth" of material "fabric", two lines in group "ropes" of
// material "rope" (see the file). Every element keeps where it came from.
TEST(MeshLoader, FacesAndLinesKeepTheFilesMaterialsAndGroups) {
  const RawMesh mesh = load_mesh_file(test::data_dir() / "banner.obj", {});
  ASSERT_EQ(mesh.faces.size(), 2u);
  ASSERT_EQ(mesh.lines.size(), 2u);
  using Names = std::vector<std::string>;
  EXPECT_EQ(element_names(mesh, MeshNameKind::kMaterial), (Names{"fabric", "rope"}));
  EXPECT_EQ(element_names(mesh, MeshNameKind::kGroup), (Names{"cloth", "ropes"}));
  const MeshElementIds rope = elements_named(mesh, MeshNameKind::kMaterial, "rope");
  EXPECT_TRUE(rope.faces.empty());
  EXPECT_EQ(rope.lines, (std::vector<Index>{0, 1}));
  const MeshElementIds cloth = elements_named(mesh, MeshNameKind::kGroup, "cloth");
  EXPECT_EQ(cloth.faces, (std::vector<Index>{0, 1}));
  EXPECT_TRUE(cloth.lines.empty());
  EXPECT_TRUE(elements_named(mesh, MeshNameKind::kMaterial, "cloth").empty());  // a group's name
  // A generated mesh names nothing.
  const RawMesh generated = make_grid({.width = 1.0, .height = 1.0});
  EXPECT_TRUE(element_names(generated, MeshNameKind::kMaterial).empty());
}

// glTF: the paper's flag names its cloth's material "cloth" and its ropes' "rope", and its mesh
// primitives become groups of their own below the file's node (assimp names them "paper_flag-0"
// and "paper_flag-1"): 330 triangles and the 58 rope segments of scripts/make-paper-flag.py.
TEST(MeshLoader, GltfPrimitivesKeepTheirMaterials) {
  const RawMesh mesh = load_mesh_file(test::data_dir() / "../../assets/paper_flag.gltf", {});
  const MeshElementIds rope = elements_named(mesh, MeshNameKind::kMaterial, "rope");
  const MeshElementIds cloth = elements_named(mesh, MeshNameKind::kMaterial, "cloth");
  EXPECT_EQ(rope.lines.size(), 58u);
  EXPECT_TRUE(rope.faces.empty());
  EXPECT_EQ(cloth.faces.size(), 330u);
  EXPECT_TRUE(cloth.lines.empty());
  EXPECT_EQ(elements_named(mesh, MeshNameKind::kGroup, "paper_flag-1").lines, rope.lines);
}

TEST(MeshLoader, MaterialTextureAndTextureCoordinatesComeFromTheFile) {
  const RawMesh mesh = load_mesh_file(test::data_dir() / "textured_quad.obj", {});
  EXPECT_EQ(mesh.texture, test::data_dir() / "quad.png");
  ASSERT_EQ(mesh.uvs.size(), mesh.vertices.size());
  // v is flipped to run from the top of the picture: the vertex at (0, 0) has vt (0, 0) → (0, 1).
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (mesh.vertices[v].isZero()) {
      EXPECT_TRUE(mesh.uvs[v].isApprox(Eigen::Vector2d(0, 1))) << mesh.uvs[v].transpose();
    }
  }
  // A scene that names no texture takes the file's.
  const SceneDescription scene = test::scene_from_yaml(R"(version: 1
duration: 1
objects:
  - mesh: {file: textured_quad.obj}
    material: {density: 1, youngs_modulus: 1, radius: 0.1}
)");
  EXPECT_EQ(scene.objects[0].texture, test::data_dir() / "quad.png");
  EXPECT_EQ(scene.objects[0].style, DrawStyle::kSurface);
}

// A mesh left with no bar once its degenerate faces are dropped is an error that says so.
TEST(MeshLoader, MeshWithOnlyADegenerateFaceIsAnError) {
  test::expect_user_error([] { model_of_file("degenerate.obj"); }, 4,
                          {"no edges", "1 degenerate face", "faces 0"});
}

// Real files carry faces with a repeated corner, corners that weld together and faces listed
// twice: they are dropped, counted in a warning, and the rest of the mesh loads (tests/data/
// untidy.obj: a unit square of two triangles, with one of each kind of flaw beside them).
TEST(MeshLoader, DegenerateAndDuplicateFacesAreDroppedWithAWarning) {
  const Model model = model_of_file("untidy.obj");
  EXPECT_EQ(model.node_count(), 6);  // the square's corners, the line's end, the corner below
  EXPECT_EQ(model.bar_count(), 8);   // four sides, the diagonal, the line, two below the square
  EXPECT_EQ(model.face_count(), 3);  // the two triangles and the quad with a repeated corner
  ASSERT_EQ(model.warnings.size(), 1U);
  const std::string& warning = model.warnings[0];
  // (assimp splits the line into segments: 2–2, a line of a single point, and 2–6.)
  for (const char* part : {"warning: object", "2 degenerate faces", "1 duplicate face",
                           "1 zero-length side", "1 line of a single point", "faces 2, 3, 4)"}) {
    EXPECT_NE(warning.find(part), std::string::npos) << part << " in: " << warning;
  }
  EXPECT_TRUE(model_of_file("cube.obj").warnings.empty());
  // PLY keeps a file's vertices as they are (assimp's OBJ reader leaves out unused ones).
  const Model stray = model_of_file("stray_point.ply");
  EXPECT_EQ(stray.node_count(), 3);
  ASSERT_EQ(stray.warnings.size(), 1U);
  EXPECT_NE(stray.warnings[0].find("dropped 1 vertex on no face or line"), std::string::npos)
      << stray.warnings[0];
}

TEST(MeshLoader, UnreadableFileIsAnError) {
  test::expect_user_error(
      [] {
        load_mesh_file(test::data_dir() / "inline_not_a_mesh.txt", FileLoc{"s.yaml", 3, 7});
      },
      3, {"not found"});
  // A file that exists but is not a mesh.
  test::expect_user_error(
      [] {
        load_mesh_file(test::data_dir() / "cube.obj.notmesh", FileLoc{"s.yaml", 3, 7});
      },
      3, {"cannot read mesh file"});
}

}  // namespace
}  // namespace dinam
