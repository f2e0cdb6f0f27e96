#include "scene/scene_description.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "test_support.hpp"

namespace dinam {
namespace {

using test::expect_user_error;
using test::scene_from_yaml;

// A complete, valid scene; the error tests below each break one thing in it.
const char* const kValidScene = R"(version: 1
name: demo
duration: 2.0
fps: 25
timestep: 0.001
gravity: [0, 0, -9.0]
ground: {height: -0.5, visible: false}
camera: {position: [1, -5, 2], look_at: [0, 0, 1], up: [0, 0, 1], fov: 30}
image: {width: 320, height: 180}
output: renders/demo
objects:
  - name: cloth
    mesh:
      grid: {width: 2, height: 1, columns: 4, rows: 2, diagonals: none}
      rotation: [90, 0, 0]
      translation: [0, 0, 1]
    material: {density: 1000, youngs_modulus: 1.0e6, shear_modulus: 4.0e5, radius: 0.002}
    pinned: {indices: [0], box: {min: [-0.1, -0.1, 1.9], max: [0.1, 0.1, 2.1]}}
    initial_velocity: [0, 1, 0]
    color: [1, 0, 0]
  - name: cube
    mesh: {file: cube.obj, scale: 0.5, translation: [3, 0, 0]}
    material: {density: 7800, youngs_modulus: 2.0e11, area: 1.0e-4}
)";

TEST(SceneReader, ReadsEveryKeyOfAValidScene) {
  const SceneDescription scene = scene_from_yaml(kValidScene);
  EXPECT_EQ(scene.name, "demo");
  EXPECT_DOUBLE_EQ(scene.duration, 2.0);
  EXPECT_DOUBLE_EQ(scene.fps, 25.0);
  EXPECT_EQ(scene.frame_count(), 50);
  ASSERT_TRUE(scene.timestep.has_value());
  EXPECT_DOUBLE_EQ(*scene.timestep, 0.001);
  EXPECT_EQ(scene.timestep_loc.line, 5);
  EXPECT_TRUE(scene.gravity.isApprox(Vec3(0, 0, -9.0)));
  EXPECT_TRUE(scene.ground.point.isApprox(Vec3(0, 0, -0.5)));
  EXPECT_FALSE(scene.ground.visible);
  EXPECT_DOUBLE_EQ(scene.camera.fov_degrees, 30.0);
  EXPECT_EQ(scene.image_width, 320);
  EXPECT_EQ(scene.image_height, 180);
  EXPECT_EQ(scene.output, "renders/demo");
  ASSERT_EQ(scene.objects.size(), 2u);

  const ObjectDesc& cloth = scene.objects[0];
  EXPECT_EQ(cloth.name, "cloth");
  EXPECT_EQ(cloth.mesh.vertices.size(), 15u);  // (4 + 1) × (2 + 1)
  // rotation [90, 0, 0] turns the grid's y into z; the far corner (2, 1) lands at (2, 0, 2).
  EXPECT_TRUE(cloth.mesh.vertices.back().isApprox(Vec3(2, 0, 2), 1e-12));
  const double r = 0.002;
  EXPECT_DOUBLE_EQ(cloth.material.area, std::numbers::pi * r * r);
  EXPECT_DOUBLE_EQ(cloth.material.area_moment, std::numbers::pi * std::pow(r, 4) / 4);
  EXPECT_DOUBLE_EQ(cloth.material.polar_moment, std::numbers::pi * std::pow(r, 4) / 2);
  EXPECT_DOUBLE_EQ(cloth.material.shear_modulus, 4.0e5);
  EXPECT_EQ(cloth.pins.vertex_ids, std::vector<Index>{0});
  ASSERT_EQ(cloth.pins.boxes.size(), 1u);
  EXPECT_TRUE(cloth.initial_velocity.isApprox(Vec3(0, 1, 0)));

  const ObjectDesc& cube = scene.objects[1];
  Vec3 lo = cube.mesh.vertices.front();
  Vec3 hi = lo;
  for (const Vec3& p : cube.mesh.vertices) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  EXPECT_TRUE(lo.isApprox(Vec3(3, 0, 0)));  // the unit cube scaled by 0.5, then moved
  EXPECT_TRUE(hi.isApprox(Vec3(3.5, 0.5, 0.5)));
  EXPECT_DOUBLE_EQ(cube.material.area, 1.0e-4);
  // G defaults to E / 2.6 (Poisson's ratio 0.3); I to that of the circle of the same area.
  EXPECT_DOUBLE_EQ(cube.material.shear_modulus, 2.0e11 / 2.6);
  EXPECT_DOUBLE_EQ(cube.material.area_moment, 1.0e-8 / (4 * std::numbers::pi));
}

// The box of a mesh's vertices.
std::pair<Vec3, Vec3> vertex_box(const RawMesh& mesh) {
  Vec3 lo = mesh.vertices.front();
  Vec3 hi = lo;
  for (const Vec3& p : mesh.vertices) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return {lo, hi};
}

TEST(SceneReader, MeshUnitsAndFitGiveMetres) {
  const SceneDescription scene = scene_from_yaml(R"(version: 1
duration: 1
objects:
  - mesh: {file: cube.obj, units: cm}
    material: {density: 1000, youngs_modulus: 1.0e6, radius: 0.01}
  - mesh: {file: cube.obj, units: in, translation: [1, 0, 0]}
    material: {density: 1000, youngs_modulus: 1.0e6, radius: 0.01}
  - mesh: {file: cube.obj, fit: {size: 1.5}, rotation: [0, 0, 45], translation: [0, 0, 2]}
    material: {density: 1000, youngs_modulus: 1.0e6, radius: 0.01}
  - mesh: {grid: {width: 4, height: 1, columns: 4, rows: 1}, fit: {size: 2}}
    material: {density: 1000, youngs_modulus: 1.0e6, radius: 0.01}
)");
  // The unit cube in centimetres and in inches.
  EXPECT_TRUE(vertex_box(scene.objects[0].mesh).second.isApprox(Vec3(0.01, 0.01, 0.01)));
  const auto [inch_lo, inch_hi] = vertex_box(scene.objects[1].mesh);
  EXPECT_TRUE(inch_lo.isApprox(Vec3(1, 0, 0)));
  EXPECT_TRUE(inch_hi.isApprox(Vec3(1.0254, 0.0254, 0.0254)));
  // Turned by 45° the cube is √2 wide across x and y: fitted, that side is 1.5 m, its bottom centre
  // at the origin, then moved up 2 m.
  const auto [fit_lo, fit_hi] = vertex_box(scene.objects[2].mesh);
  EXPECT_NEAR((fit_hi - fit_lo).maxCoeff(), 1.5, 1e-12);
  EXPECT_NEAR(fit_hi.z() - fit_lo.z(), 1.5 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(fit_lo.z(), 2.0, 1e-12);
  EXPECT_NEAR(fit_lo.x() + fit_hi.x(), 0.0, 1e-12);
  EXPECT_NEAR(fit_lo.y() + fit_hi.y(), 0.0, 1e-12);
  // A flat grid 4 m long becomes 2 m long and 0.5 m wide.
  const auto [grid_lo, grid_hi] = vertex_box(scene.objects[3].mesh);
  EXPECT_TRUE((grid_hi - grid_lo).isApprox(Vec3(2, 0.5, 0)));
}

TEST(SceneReader, TimestepAsAMapAimsTheAutomaticStep) {
  const std::string objects = R"(
objects:
  - mesh: {polyline: {points: [[0, 0, 1], [1, 0, 1]], segments: 10}, weld: 0.2}
    material: {density: 1000, youngs_modulus: 1.0e6, radius: 0.01}
)";
  const SceneDescription target = scene_from_yaml(
      "version: 1\nduration: 1\ntimestep: {target: 1e-4, max_added_mass: 0.05}" + objects);
  EXPECT_EQ(target.step_target.target, 1e-4);
  EXPECT_EQ(target.step_target.max_added_mass, 0.05);
  EXPECT_FALSE(target.timestep.has_value());
  EXPECT_DOUBLE_EQ(target.objects[0].weld_fraction, 0.2);
  const SceneDescription steps =
      scene_from_yaml("version: 1\nduration: 1\ntimestep: {max_steps: 1e6}" + objects);
  EXPECT_EQ(steps.step_target.max_steps, 1e6);
  const SceneDescription off =
      scene_from_yaml("version: 1\nduration: 1\ntimestep: {mass_scaling: false}" + objects);
  EXPECT_FALSE(off.step_target.mass_scaling);
  EXPECT_FALSE(off.step_target.aims());
}

TEST(SceneReader, ReadsThePhysicalModelKeys) {
  const SceneDescription scene = scene_from_yaml(R"(version: 1
duration: 1
damping: {global: 0.3}
ground: {point: [0, 0, -1], normal: [0, 0, 2], stiffness: 5000, damping_ratio: 0.5,
         friction: {static: 0.6, kinetic: 0.4}}
wind: {velocity: [4, 0, 0], gust: {amplitude: 2, period: 3}, turbulence: {amplitude: 1, seed: 9},
       air_density: 1.2, objects: [rope]}
forces:
  - {acceleration: [1, 0, 0], profile: {type: ramp, start: 1, end: 2}}
  - {force: [0, 0, 5], object: rope, nodes: {indices: [4]}, profile: {type: sine, frequency: 2}}
objects:
  - name: rope
    mesh: {file: rope.obj}
    material: {density: 1000, youngs_modulus: 1e6, radius: 0.01, yield_stress: 2e6,
               yield: {torsion: 3}}
    bending_pairs: all
    torsion: false
    damping: {axial_ratio: 0.1}
)");
  EXPECT_DOUBLE_EQ(scene.global_damping, 0.3);
  EXPECT_TRUE(scene.ground.normal.isApprox(Vec3(0, 0, 1)));  // normalised
  EXPECT_DOUBLE_EQ(*scene.ground.stiffness, 5000);
  EXPECT_DOUBLE_EQ(scene.ground.static_friction, 0.6);
  EXPECT_TRUE(scene.wind.enabled);
  EXPECT_EQ(scene.wind.seed, 9u);
  EXPECT_EQ(scene.wind.objects, std::vector<std::string>{"rope"});
  ASSERT_EQ(scene.fields.size(), 2u);
  EXPECT_TRUE(scene.fields[0].per_unit_mass);
  EXPECT_DOUBLE_EQ(scene.fields[0].profile(1.5), 0.5);
  EXPECT_FALSE(scene.fields[1].per_unit_mass);
  const MaterialDesc& m = scene.objects[0].material;
  // Ny = σy A; My = (4/3) r³ σy; Ty given directly.
  EXPECT_DOUBLE_EQ(m.yield_axial_force, 2e6 * m.area);
  EXPECT_NEAR(m.yield_bending_moment, 4.0 / 3.0 * 1e-6 * 2e6, 1e-9);
  EXPECT_DOUBLE_EQ(m.yield_torsion_moment, 3.0);
  EXPECT_EQ(scene.objects[0].bending_pairs, BendingPairs::kAll);
  EXPECT_FALSE(scene.objects[0].torsion);
  EXPECT_DOUBLE_EQ(scene.objects[0].axial_damping.ratio, 0.1);
}

TEST(SceneReader, PhysicalModelMistakesAreErrors) {
  const std::string base =
      "version: 1\nduration: 1\nobjects:\n  - name: rope\n    mesh: {file: rope.obj}\n    "
      "material: {density: 1000, youngs_modulus: 1e6, radius: 0.01}\n";
  expect_user_error(
      [&] { scene_from_yaml(base + "forces: [{acceleration: [1, 0, 0], object: nope}]\n"); }, 7,
      {"no object named 'nope'"});
  expect_user_error(
      [&] { scene_from_yaml(base + "forces: [{acceleration: [1, 0, 0], force: [1, 0, 0]}]\n"); }, 7,
      {"not both"});
  expect_user_error(
      [&] { scene_from_yaml(base + "ground: {friction: {static: 0.2, kinetic: 0.5}}\n"); }, 7,
      {"must not exceed"});
  expect_user_error(
      [&] {
        scene_from_yaml(base + "forces: [{acceleration: [1, 0, 0], profile: {type: pulse}}]\n");
      },
      7, {"constant, step, ramp or sine"});
  expect_user_error(
      [&] { scene_from_yaml(base + "wind: {velocity: [1, 0, 0], objects: [flag]}\n"); }, 7,
      {"'flag', which is no object"});
  expect_user_error([&] { scene_from_yaml(base + "settle: {duration: -1}\n"); }, 7,
                    {"'settle.duration' must be greater than zero"});
  expect_user_error([&] { scene_from_yaml(base + "settle: {duration: 2, damping: -3}\n"); }, 7,
                    {"'settle.damping' must be 'auto' or from 0"});
  expect_user_error(
      [&] { scene_from_yaml(base + "    pin_motion: {displacement: [0.1, 0, 0]}\n"); }, 7,
      {"has none; add 'pinned'"});
}

// A settling phase, and pinned nodes that follow a path.
TEST(SceneReader, SettleAndPinMotion) {
  const SceneDescription scene = scene_from_yaml(R"(version: 1
duration: 1
settle: {duration: 3}
objects:
  - name: tower
    mesh: {file: rope.obj}
    material: {density: 1000, youngs_modulus: 1e6, radius: 0.01}
    pinned: {indices: [0]}
    pin_motion: {displacement: [0.05, 0, 0], profile: {type: sine, frequency: 2}}
)");
  EXPECT_DOUBLE_EQ(scene.settle.duration, 3.0);
  const PinMotionDesc& motion = scene.objects[0].pin_motion;
  EXPECT_TRUE(motion.moving());
  EXPECT_TRUE(motion.displacement.isApprox(Vec3(0.05, 0, 0)));
  EXPECT_EQ(motion.profile.kind, TimeProfile::Kind::kSine);
  EXPECT_DOUBLE_EQ(motion.profile.frequency, 2.0);
}

TEST(SceneReader, CameraModesStylesAndOutput) {
  const std::string base = R"(version: 1
duration: 1
objects:
  - name: cube
    mesh: {file: cube.obj}
    material: {density: 1000, youngs_modulus: 1e6, radius: 0.01}
)";
  SceneDescription scene = scene_from_yaml(base);
  EXPECT_EQ(scene.camera.mode, CameraDesc::Mode::kAuto);   // no camera: frame the motion
  EXPECT_EQ(scene.objects[0].style, DrawStyle::kSurface);  // it has faces
  EXPECT_EQ(scene.movie, MovieFormat::kMp4);
  scene =
      scene_from_yaml(base + "camera: {position: [0, -5, 1], look_at: [0, 0, 1]}\nmovie: gif\n");
  EXPECT_EQ(scene.camera.mode, CameraDesc::Mode::kFixed);
  EXPECT_EQ(scene.movie, MovieFormat::kGif);
  scene = scene_from_yaml(base + "camera: {follow: cube, offset: [1, -4, 2], fov: 30}\n");
  EXPECT_EQ(scene.camera.mode, CameraDesc::Mode::kFollow);
  EXPECT_TRUE(scene.camera.offset.isApprox(Vec3(1, -4, 2)));
  scene = scene_from_yaml(base +
                          "camera: {auto: true, direction: [0, 1, -0.2]}\n"
                          "image: {samples: 1, shadows: false}\n");
  EXPECT_EQ(scene.camera.mode, CameraDesc::Mode::kAuto);
  EXPECT_EQ(scene.quality.samples, 1);
  EXPECT_FALSE(scene.quality.shadows);

  expect_user_error([&] { scene_from_yaml(base + "camera: {follow: ball}\n"); }, 7,
                    {"'ball', which is no object"});
  expect_user_error([&] { scene_from_yaml(base + "movie: avi\n"); }, 7, {"mp4, gif or none"});
  std::string textured = base;
  textured += "    texture: no_such.png\n";
  expect_user_error([&] { scene_from_yaml(textured); }, 7, {"texture file", "no_such.png"});
  std::string not_png = base;
  not_png += "    texture: cube.obj\n";
  expect_user_error([&] { scene_from_yaml(not_png); }, 7, {"cube.obj", "is not a PNG image"});
  expect_user_error(
      [&] {
        scene_from_yaml(
            "version: 1\nduration: 1\nobjects:\n  - mesh: {file: rope.obj}\n"
            "    material: {density: 1, youngs_modulus: 1, radius: 0.1}\n"
            "    style: surface\n");
      },
      6, {"no faces to draw as a surface"});
}

TEST(SceneReader, DefaultsFillWhatTheSceneLeavesOut) {
  const SceneDescription scene = scene_from_yaml(R"(version: 1
duration: 1
objects:
  - mesh: {file: rope.obj}
    material: {density: 1000, youngs_modulus: 1e6, radius: 0.01}
)");
  EXPECT_EQ(scene.name, "inline");  // the file's stem
  EXPECT_DOUBLE_EQ(scene.fps, 24.0);
  EXPECT_FALSE(scene.timestep.has_value());  // auto
  EXPECT_TRUE(scene.gravity.isApprox(Vec3(0, 0, -9.81)));
  EXPECT_EQ(scene.output, "out/inline");
  EXPECT_EQ(scene.objects[0].name, "object0");
}

// Replaces the first occurrence of `from` in the valid scene by `to`.
std::string valid_scene_with(const std::string& from, const std::string& to) {
  std::string text = kValidScene;
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(SceneReader, UnknownKeyIsAnErrorAtItsLineWithASuggestion) {
  expect_user_error([] { scene_from_yaml(valid_scene_with("density: 1000", "densty: 1000")); }, 17,
                    {"inline.yaml:17:", "unknown key 'densty'", "did you mean 'density'?"});
  expect_user_error([] { scene_from_yaml(valid_scene_with("fps: 25", "fps: 25\nframerate: 3")); },
                    5, {"unknown key 'framerate'"});
}

TEST(SceneReader, WrongTypeNamesTheKey) {
  expect_user_error([] { scene_from_yaml(valid_scene_with("duration: 2.0", "duration: long")); }, 3,
                    {"'duration' must be a number", "'long'"});
  expect_user_error(
      [] { scene_from_yaml(valid_scene_with("gravity: [0, 0, -9.0]", "gravity: [0, -9.0]")); }, 6,
      {"'gravity' must be a list of three numbers"});
  expect_user_error([] { scene_from_yaml(valid_scene_with("columns: 4", "columns: 4.5")); }, 14,
                    {"objects[0].mesh.grid.columns", "whole number"});
}

TEST(SceneReader, MissingMeshFileIsAnErrorAtTheFileKey) {
  expect_user_error([] { scene_from_yaml(valid_scene_with("cube.obj", "no_such_mesh.obj")); }, 22,
                    {"mesh file", "no_such_mesh.obj", "not found"});
}

TEST(SceneReader, ImpossibleValuesAreErrors) {
  expect_user_error([] { scene_from_yaml(valid_scene_with("density: 1000", "density: -1000")); },
                    17, {"objects[0].material.density", "greater than zero"});
  expect_user_error([] { scene_from_yaml(valid_scene_with("radius: 0.002", "radius: 0")); }, 17,
                    {"radius", "greater than zero"});
  expect_user_error([] { scene_from_yaml(valid_scene_with("fov: 30", "fov: 190")); }, 8,
                    {"camera.fov"});
  expect_user_error([] { scene_from_yaml(valid_scene_with("timestep: 0.001", "timestep: 0.5")); },
                    5, {"longer than one frame"});
  expect_user_error(
      [] { scene_from_yaml(valid_scene_with("pinned: {indices: [0]", "pinned: {indices: [99]")); },
      18, {"vertex index 99 is out of range", "15 vertices"});
  // A material needs exactly one way of giving the section.
  expect_user_error(
      [] { scene_from_yaml(valid_scene_with("area: 1.0e-4", "area: 1.0e-4, radius: 0.1")); }, 23,
      {"either 'radius'", "not both"});
}

TEST(SceneReader, EmptyMeshIsAnError) {
  expect_user_error([] { scene_from_yaml(valid_scene_with("cube.obj", "points_only.obj")); }, 22,
                    {"points_only.obj", "no edges"});
}

TEST(SceneReader, StructuralMistakesAreErrors) {
  expect_user_error([] { scene_from_yaml("duration: 1\nobjects: []\n"); }, 1,
                    {"no 'version' key", "version: 1"});
  expect_user_error([] { scene_from_yaml(valid_scene_with("version: 1", "version: 7")); }, 1,
                    {"version 7 is not supported"});
  expect_user_error([] { scene_from_yaml("version: 1\nduration: 1\nobjects: [\n"); }, 0,
                    {"not valid YAML"});
  expect_user_error([] { scene_from_yaml(valid_scene_with("name: cube", "name: cloth")); }, 21,
                    {"two objects are named 'cloth'"});
  expect_user_error(
      [] {
        scene_from_yaml(
            valid_scene_with("    mesh: {file: cube.obj, ",
                             "    mesh: {grid: {width: 1, height: 1}, file: cube.obj, "));
      },
      22, {"exactly one source"});
}

}  // namespace
}  // namespace dinam

namespace dinam {
namespace {

// Bad input that once got through: duplicate keys, non-finite or absurd mesh vertices, material
// values no real material has. Each stops at its line with what to do.
TEST(SceneReader, DuplicateKeysAreErrorsAtTheSecondNamingTheFirst) {
  const std::string object =
      "objects:\n  - mesh: {file: rope.obj}\n    material: {density: 1000, youngs_modulus: 1e6, "
      "radius: 0.01}\n";
  test::expect_user_error(
      [&] { test::scene_from_yaml("version: 1\nduration: 1\nduration: 2\n" + object); }, 3,
      {"the key 'duration' appears twice", "first at", "inline.yaml:2:1"});
  test::expect_user_error(
      [&] {
        test::scene_from_yaml(
            "version: 1\nduration: 1\nobjects:\n  - mesh: {file: rope.obj}\n    material: "
            "{density: 1000, youngs_modulus: 1e6, radius: 0.01, density: .nan}\n");
      },
      5, {"the key 'density' appears twice", "keep one"});
}

TEST(SceneReader, NonFiniteOrFarMeshVerticesAreRefusedNamingTheFileAndVertex) {
  const test::TemporaryFolder folder("badmesh");
  std::ofstream(folder.path() / "badid.ply")
      << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
         "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n";
  std::ofstream(folder.path() / "nan.obj") << "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n";
  std::ofstream(folder.path() / "far.obj") << "v 0 0 0\nv 1e30 0 0\nv 0 1 0\nf 1 2 3\n";
  const auto scene = [&](const char* mesh) {
    return fmt::format(
        "version: 1\nduration: 1\nobjects:\n  - mesh: {{file: {}}}\n    material: {{density: "
        "1000, youngs_modulus: 1e6, radius: 0.01}}\n",
        mesh);
  };
  test::expect_user_error([&] { read_scene_text(scene("nan.obj"), folder.path() / "s.yaml"); }, 4,
                          {"vertex 1 of mesh file '", "nan.obj' is (", "not a finite point"});
  test::expect_user_error(
      [&] { read_scene_text(scene("far.obj"), folder.path() / "s.yaml"); }, 4,
      {"vertex 1 of mesh file '", "far.obj' is at (1e+30, 0, 0) m", "beyond 1e+06 m", "'scale'"});
  // Found by fuzzing: assimp passes a face's vertex ids on unchecked.
  test::expect_user_error([&] { read_scene_text(scene("badid.ply"), folder.path() / "s.yaml"); }, 4,
                          {"a face of mesh file", "refers to vertex 7, but it has 3 vertices"});
  test::expect_user_error(
      [&] {
        test::scene_from_yaml(
            "version: 1\nduration: 1\nobjects:\n  - mesh: {file: rope.obj, scale: 1e300}\n    "
            "material: {density: 1000, youngs_modulus: 1e6, radius: 0.01}\n");
      },
      4, {"beyond 1e+06 m"});
}

TEST(SceneReader, MaterialValuesNoMaterialHasAreRefusedAtTheirKey) {
  const auto scene = [](const char* material) {
    return fmt::format(
        "version: 1\nduration: 1\nobjects:\n  - mesh: {{file: rope.obj}}\n    material: {{{}}}\n",
        material);
  };
  // 1e-300 m squared underflows to a zero area; 1e300 kg/m³ overflows the energies.
  test::expect_user_error(
      [&] { test::scene_from_yaml(scene("density: 1000, youngs_modulus: 1e6, radius: 1e-300")); },
      5, {"'objects[0].material.radius' must be between 1e-07 and 100 m"});
  test::expect_user_error(
      [&] { test::scene_from_yaml(scene("density: 1e300, youngs_modulus: 1e6, radius: 0.01")); }, 5,
      {"'objects[0].material.density' must be between"});
  test::expect_user_error(
      [&] { test::scene_from_yaml(scene("density: 1000, youngs_modulus: 1e20, radius: 0.01")); }, 5,
      {"youngs_modulus' must be between"});
  test::expect_user_error(
      [&] { test::scene_from_yaml(scene("density: 1000, youngs_modulus: 1e6, area: 1e-40")); }, 5,
      {"area' must be between"});
}

}  // namespace
}  // namespace dinam

namespace dinam {
namespace {

const std::string kLookBase =
    "version: 1\nduration: 2\nobjects:\n  - name: rope\n    mesh: {file: rope.obj}\n    "
    "material: {density: 1000, youngs_modulus: 1e6, radius: 0.01}\n";

TEST(SceneReader, QualityPresetsSetTheLookAndKeysBesideThemOverride) {
  const SceneDescription standard = scene_from_yaml(kLookBase);
  EXPECT_EQ(standard.quality.preset, QualityPreset::kStandard);
  EXPECT_EQ(standard.quality.samples, 4);
  EXPECT_FALSE(standard.quality.look.ambient_occlusion);
  EXPECT_FALSE(standard.quality.motion_blur.enabled());

  const SceneDescription draft = scene_from_yaml(kLookBase + "image: {quality: draft}\n");
  EXPECT_EQ(draft.quality.samples, 1);
  EXPECT_EQ(draft.quality.shadow_resolution, 1024);

  const SceneDescription final_look =
      scene_from_yaml(kLookBase +
                      "image: {quality: final, samples: 2, motion_blur: {shutter: 0.25}, "
                      "exposure: -0.5, tone_mapping: none}\nlight: {size: 4}\n");
  EXPECT_EQ(final_look.quality.samples, 2);
  EXPECT_TRUE(final_look.quality.look.soft_shadows);
  EXPECT_TRUE(final_look.quality.look.ambient_occlusion);
  EXPECT_EQ(final_look.quality.motion_blur.samples, 8);
  EXPECT_DOUBLE_EQ(final_look.quality.motion_blur.shutter, 0.25);
  EXPECT_FLOAT_EQ(final_look.quality.look.exposure, -0.5f);
  EXPECT_FALSE(final_look.quality.look.tone_mapping);
  EXPECT_DOUBLE_EQ(final_look.light_size_degrees, 4.0);

  const SceneDescription unblurred =
      scene_from_yaml(kLookBase + "image: {quality: final, motion_blur: false}\n");
  EXPECT_FALSE(unblurred.quality.motion_blur.enabled());
}

TEST(SceneReader, ReadsFinishesByNameAndByValue) {
  const SceneDescription scene =
      scene_from_yaml(kLookBase +
                      "    finish: metal\n  - name: other\n    mesh: {file: rope.obj}\n    "
                      "material: {density: 1000, youngs_modulus: 1e6, radius: 0.01}\n    "
                      "finish: {like: cloth, roughness: 0.5}\n");
  EXPECT_FLOAT_EQ(scene.objects[0].finish.metallic, 1.0f);
  EXPECT_FLOAT_EQ(scene.objects[1].finish.roughness, 0.5f);
  EXPECT_FLOAT_EQ(scene.objects[1].finish.sheen, 0.8f);
}

TEST(SceneReader, CameraPathsAndOrbitsAreRead) {
  const SceneDescription path =
      scene_from_yaml(kLookBase +
                      "camera:\n  keys:\n    - {time: 0, position: [4, -6, 2], look_at: [0, 0, 1], "
                      "fov: 35}\n    - {time: 2, position: [1, -3, 1], look_at: [0, 0, 1]}\n");
  EXPECT_EQ(path.camera.mode, CameraDesc::Mode::kPath);
  ASSERT_EQ(path.camera.keys.size(), 2u);
  EXPECT_DOUBLE_EQ(path.camera.keys[1].fov_degrees, 35.0);  // the previous key's
  const SceneDescription orbit =
      scene_from_yaml(kLookBase + "camera: {orbit: {radius: 5, turns: -0.5}}\n");
  EXPECT_EQ(orbit.camera.mode, CameraDesc::Mode::kOrbit);
  EXPECT_DOUBLE_EQ(*orbit.camera.orbit.radius, 5.0);
  EXPECT_DOUBLE_EQ(orbit.camera.orbit.turns, -0.5);
}

TEST(SceneReader, LookMistakesAreErrorsAtTheirLine) {
  expect_user_error([&] { scene_from_yaml(kLookBase + "image: {quality: best}\n"); }, 7,
                    {"draft, standard or final"});
  expect_user_error([&] { scene_from_yaml(kLookBase + "image: {motion_blur: {shutter: 2}}\n"); }, 7,
                    {"image.motion_blur.shutter", "(0, 1]"});
  expect_user_error([&] { scene_from_yaml(kLookBase + "image: {motion_blur: {samples: 100}}\n"); },
                    7, {"between 1 (no blur) and 64"});
  expect_user_error([&] { scene_from_yaml(kLookBase + "image: {tone_mapping: aces}\n"); }, 7,
                    {"filmic or none"});
  expect_user_error([&] { scene_from_yaml(kLookBase + "light: {size: 60}\n"); }, 7,
                    {"apparent diameter"});
  expect_user_error([&] { scene_from_yaml(kLookBase + "    finish: velvet\n"); }, 7,
                    {"names no finish", "metal"});
  expect_user_error([&] { scene_from_yaml(kLookBase + "    finish: {roughness: 2}\n"); }, 7,
                    {"between 0 and 1"});
  expect_user_error(
      [&] {
        scene_from_yaml(kLookBase +
                        "camera:\n  keys:\n    - {time: 1, position: [4, -6, 2], "
                        "look_at: [0, 0, 1]}\n    - {time: 1, position: [1, -3, 1], "
                        "look_at: [0, 0, 1]}\n");
      },
      10, {"increasing time"});
  expect_user_error([&] { scene_from_yaml(kLookBase + "camera: {orbit: {}, follow: rope}\n"); }, 7,
                    {"not several"});
  expect_user_error(
      [&] { scene_from_yaml(kLookBase + "camera: {orbit: {}, position: [1, 2, 3]}\n"); }, 7,
      {"an orbit places the eye itself"});
}

// `fov: 0.785` (45° in radians) draws a patch of ground: allowed, with a warning at the key, for
// the camera and for each key of a path; 30° gets none.
TEST(SceneReader, AFieldOfViewUnderFiveDegreesIsWarnedOf) {
  const SceneDescription fixed = test::scene_from_yaml(R"(version: 1
duration: 1
camera: {position: [3, 0, 1], look_at: [0, 0, 0], fov: 0.785}
objects:
  - mesh: {grid: {width: 1, height: 1, columns: 2, rows: 2}, translation: [0, 0, 1]}
    material: {density: 1000, youngs_modulus: 1.0e6, radius: 0.001}
)");
  ASSERT_EQ(fixed.warnings.size(), 1U);
  test::expect_contains(fixed.warnings[0],
                        {":3:56: warning: 'camera.fov' is 0.785°", "in degrees (45, not 0.785)"});
  const SceneDescription path = test::scene_from_yaml(R"(version: 1
duration: 1
camera:
  keys:
    - {time: 0, position: [3, 0, 1], look_at: [0, 0, 0], fov: 30}
    - {time: 1, position: [3, 1, 1], look_at: [0, 0, 0], fov: 0.5}
objects:
  - mesh: {grid: {width: 1, height: 1, columns: 2, rows: 2}, translation: [0, 0, 1]}
    material: {density: 1000, youngs_modulus: 1.0e6, radius: 0.001}
)");
  ASSERT_EQ(path.warnings.size(), 1U);
  test::expect_contains(path.warnings[0], {"'camera.keys[1].fov' is 0.5°"});
}

}  // namespace
}  // namespace dinam

namespace dinam {
namespace {

// Colours as artists pick them: [r, g, b] is sRGB, decoded by the sRGB transfer function
// (IEC 61966-2-1: 0.5 is 0.2140 in linear light, 0.04 below the curve's knee is 0.04 / 12.92);
// {linear: [...]} is kept as it is; out of range or an unknown key is an error at its line.
TEST(SceneReader, ColoursAreSrgbUnlessGivenLinear) {
  const std::string base =
      "version: 1\nduration: 1\nobjects:\n  - name: rope\n    mesh: {file: rope.obj}\n    "
      "material: {density: 1000, youngs_modulus: 1e6, radius: 0.01}\n";
  const Vec3f picked = scene_from_yaml(base + "    color: [0.5, 1, 0.04]\n").objects[0].color;
  EXPECT_NEAR(picked.x(), 0.21404, 1e-5);
  EXPECT_FLOAT_EQ(picked.y(), 1.0f);
  EXPECT_NEAR(picked.z(), 0.04 / 12.92, 1e-7);
  const Vec3f linear =
      scene_from_yaml(base + "    color: {linear: [0.5, 1, 0.04]}\n").objects[0].color;
  EXPECT_FLOAT_EQ(linear.x(), 0.5f);
  EXPECT_FLOAT_EQ(linear.z(), 0.04f);
  expect_user_error([&] { scene_from_yaml(base + "    color: [1.5, 0, 0]\n"); }, 7,
                    {"sRGB, as a colour picker gives it", "{linear: [r, g, b]}"});
  expect_user_error([&] { scene_from_yaml(base + "    color: {linear: [0, -1, 0]}\n"); }, 7,
                    {"between 0 and 1"});
  expect_user_error([&] { scene_from_yaml(base + "    color: {srgb: [0, 1, 0]}\n"); }, 7, {"srgb"});
}

}  // namespace
}  // namespace dinam

namespace dinam {
namespace {

// Mistakes a new user makes, answered with the fix: a number written with its unit is refused
// with its value in SI units (the scene's units are SI base units, grams as kilograms), and a
// scene-wide key given to an object names where it belongs.
TEST(SceneReader, UnitsAndMisplacedKeysAreAnsweredWithTheFix) {
  const std::string head =
      "version: 1\nduration: 1\nobjects:\n  - name: rope\n    mesh: {file: rope.obj}\n";
  expect_user_error(
      [&] {
        scene_from_yaml(head +
                        "    material: {density: 1000, youngs_modulus: 200 GPa, radius: 0.01}\n");
      },
      6, {"'200 GPa'", "units are not read", "here 2e+11"});
  expect_user_error(
      [&] {
        scene_from_yaml(head +
                        "    material: {density: 1000, youngs_modulus: 1e6, radius: 5 mm}\n");
      },
      6, {"here 0.005"});
  expect_user_error(
      [&] {
        scene_from_yaml(head +
                        "    material: {density: 1000, youngs_modulus: 1e6, radius: 0.01}\n" +
                        "    damping: {global: 0.5}\n");
      },
      7, {"'objects[0].damping.global'", "top-level 'damping: {global: …}'", "axial_ratio"});
  // Text that is no number with a unit keeps the plain message.
  expect_user_error(
      [&] {
        scene_from_yaml(head +
                        "    material: {density: lots, youngs_modulus: 1e6, radius: 0.01}\n");
      },
      6, {"must be a number, got 'lots'"});
}

}  // namespace
}  // namespace dinam

namespace dinam {
namespace {

// `shading`: smooth by default; flat and auto (with its sharp angle, 30° unless given) draw the
// surface as modelled, so a `subdivide` beside them, or a sharp angle beside another shading, is
// refused at its line.
TEST(SceneReader, ShadingIsReadAndWhatContradictsItRefused) {
  auto object = [](const std::string& keys) {
    return test::scene_from_yaml(R"(version: 1
duration: 1
objects:
  - name: box
    mesh: {file: cube.obj}
    role: collider
)" + keys)
        .objects[0];
  };
  EXPECT_EQ(object("").shading, Shading::kSmooth);
  EXPECT_EQ(object("    shading: flat\n").shading, Shading::kFlat);
  const ObjectDesc sharp = object("    shading: auto\n    sharp_angle: 40\n");
  EXPECT_EQ(sharp.shading, Shading::kAuto);
  EXPECT_DOUBLE_EQ(sharp.sharp_angle, 40.0);
  EXPECT_DOUBLE_EQ(object("    shading: auto\n").sharp_angle, kDefaultSharpAngle);
  test::expect_user_error([&] { object("    shading: flat\n    subdivide: 2\n"); }, 8,
                          {"is shaded flat, drawn as modelled", "leave 'subdivide' out"});
  test::expect_user_error([&] { object("    sharp_angle: 40\n"); }, 7, {"beside 'shading: auto'"});
  test::expect_user_error([&] { object("    shading: faceted\n"); }, 7,
                          {"must be smooth, flat or auto", "got 'faceted'"});
}

}  // namespace
}  // namespace dinam
