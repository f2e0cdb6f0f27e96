// The rest mesh: vertices in node order, an object's faces as `f` and its loose bars as `l`.
#include "cache/obj_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "model/model.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// A rope (3 nodes, 2 bars, no faces) and a 1 × 1 grid of two triangles (4 nodes, 5 bars, 2 faces).
const char* const kTwoObjects = R"(version: 1
duration: 0.1
objects:
  - name: rope
    mesh: {polyline: {points: [[0, 0, 1], [1, 0, 1]], segments: 2}}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.004}
  - name: sheet
    mesh: {grid: {width: 1, height: 1, columns: 1, rows: 1}, translation: [0, 0, 2]}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.004}
)";

struct ObjText {
  std::vector<Vec3f> vertices;
  std::vector<std::string> faces;
  std::vector<std::string> lines;
  std::string name;
};

ObjText parse(const std::filesystem::path& path) {
  ObjText obj;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string kind;
    words >> kind;
    if (kind == "v") {
      Vec3f v;
      words >> v.x() >> v.y() >> v.z();
      obj.vertices.push_back(v);
    } else if (kind == "f") {
      obj.faces.push_back(line.substr(2));
    } else if (kind == "l") {
      obj.lines.push_back(line.substr(2));
    } else if (kind == "o") {
      obj.name = line.substr(2);
    }
  }
  return obj;
}

TEST(ObjFile, EachObjectIsWrittenInNodeOrderWithItsFacesAndLooseBars) {
  const Model model = build_model(test::scene_from_yaml(kTwoObjects));
  const test::TemporaryFolder folder("obj");
  for (std::size_t o = 0; o < 2; ++o) {
    const auto path = folder.path() / (model.objects[o].name + ".obj");
    write_obj(path, rest_mesh(model, o));
    const ObjText obj = parse(path);
    EXPECT_EQ(obj.name, model.objects[o].name);
    ASSERT_EQ(obj.vertices.size(), static_cast<std::size_t>(model.objects[o].node_count));
    for (Index i = 0; i < model.objects[o].node_count; ++i) {
      // The shortest decimal of a float reads back as that float.
      EXPECT_EQ(obj.vertices[i],
                model.node_initial_x[model.objects[o].first_node + i].cast<float>());
    }
  }
  const ObjText rope = parse(folder.path() / "rope.obj");
  EXPECT_TRUE(rope.faces.empty());
  EXPECT_EQ(rope.lines, (std::vector<std::string>{"1 2", "2 3"}));  // 1-based, within the object
  const ObjText sheet = parse(folder.path() / "sheet.obj");
  EXPECT_EQ(sheet.faces.size(), 2u);
  EXPECT_TRUE(sheet.lines.empty());  // every bar of the grid is on a face
}

// The rest mesh keeps what the artist's file had beyond positions: each corner's texture
// coordinates (as the file wrote them, v up) and the groups and materials of its faces.
TEST(ObjFile, TextureCoordinatesGroupsAndMaterialsOfTheMeshFileAreKept) {
  const Model model = build_model(test::scene_from_yaml(R"(version: 1
duration: 0.1
objects:
  - name: quad
    mesh: {file: textured_quad.obj, translation: [0, 0, 1]}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.004}
  - name: banner
    mesh: {file: banner.obj, translation: [0, 0, 1]}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.004}
)"));
  const test::TemporaryFolder folder("obj");
  std::vector<std::string> texts;
  for (std::size_t o = 0; o < 2; ++o) {
    const auto path = folder.path() / (model.objects[o].name + ".obj");
    write_obj(path, rest_mesh(model, o));
    std::ifstream in(path);
    texts.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  // textured_quad.obj: vt (0 0) (1 0) (1 1) (0 1) at its corners 1 2 3 4, material "painted".
  test::expect_contains(
      texts[0], {"vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n", "usemtl painted\n", "f 1/1 2/2 3/3 4/4\n"});
  // banner.obj: its triangles in group "cloth" of material "fabric", no texture coordinates.
  test::expect_contains(texts[1], {"g cloth\nusemtl fabric\nf 1 2 3\nf 1 3 4\n"});
  EXPECT_EQ(texts[1].find("vt "), std::string::npos);
}

}  // namespace
}  // namespace dinam
