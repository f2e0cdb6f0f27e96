// Which settings decide the motion: a cache is reused across edits of the look-only keys, so each
// of them must leave the motion the same bit for bit, and every other edit must show.
#include "scene/motion_settings.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <map>

#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "run/frame_source.hpp"
#include "stepping/time_step.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// A textured cloth falling onto the ground from a slant, with a wire rope beside it: contact,
// friction, faces and bars all in play within 6 frames.
const char* const kScene = R"(version: 1
name: drop
duration: 0.6
fps: 10
camera: {position: [2, -4, 2], look_at: [0.5, 0.5, 0.3], fov: 40}
light: {direction: [0.3, -0.4, 0.8]}
image: {width: 320, height: 180, samples: 2}
output: out/drop
movie: mp4
ground: {height: 0, visible: true, pattern: checker, color: [0.6, 0.6, 0.6], checker_color: [0.5, 0.5, 0.5], tile: 0.5}
sky: {horizon: [0.8, 0.8, 0.9]}
objects:
  - name: cloth
    mesh: {grid: {width: 1, height: 1, columns: 6, rows: 6}, rotation: [20, 0, 0], translation: [0, 0, 0.1]}
    material: {density: 800, youngs_modulus: 2.0e6, radius: 0.003}
    color: [0.7, 0.2, 0.2]
    render_radius: 0.01
    style: surface
    joints: true
    texture: quad.png
    finish: cloth
  - name: rope
    mesh: {polyline: {points: [[1.5, 0, 0.2], [1.5, 1, 0.3]], segments: 6}}
    material: {density: 1000, youngs_modulus: 1.0e7, radius: 0.004}
    color: [0.1, 0.9, 0.1]
)";

using test::replaced;

std::vector<std::vector<Vec3f>> motion_of(const SceneDescription& scene) {
  const Model model = build_model(scene);
  const TimeStep timestep = choose_timestep(model, scene.timestep, scene.fps, {});
  return simulate_frames(model, timestep, scene.frame_count(), false).positions;
}

// One edit per look-only key, each a change a user could make to the scene above.
const std::map<std::string, std::pair<std::string, std::string>> kLookEdits = {
    {"name", {"name: drop", "name: other"}},
    {"camera", {"fov: 40", "fov: 25"}},
    {"light", {"direction: [0.3, -0.4, 0.8]", "direction: [-0.5, 0.2, 0.6]"}},
    {"image", {"width: 320, height: 180, samples: 2", "width: 640, height: 480, samples: 8"}},
    {"output", {"output: out/drop", "output: elsewhere"}},
    {"movie", {"movie: mp4", "movie: gif"}},
    {"ground.visible", {"visible: true", "visible: false"}},
    {"ground.pattern", {"pattern: checker", "pattern: plain"}},
    {"ground.color", {"color: [0.6, 0.6, 0.6]", "color: [0.9, 0.2, 0.2]"}},
    {"ground.checker_color", {"checker_color: [0.5, 0.5, 0.5]", "checker_color: [0.1, 0.1, 0.1]"}},
    {"ground.tile", {"tile: 0.5", "tile: 2"}},
    {"ground.backdrop", {"visible: true", "visible: true, backdrop: cyclorama"}},
    {"sky",
     {"sky: {horizon: [0.8, 0.8, 0.9]}", "sky: {horizon: [1, 0.5, 0.1], zenith: [0, 0, 0.5]}"}},
    {"objects[].color", {"color: [0.7, 0.2, 0.2]", "color: [0.2, 0.2, 0.7]"}},
    {"objects[].render_radius", {"render_radius: 0.01", "render_radius: 0.05"}},
    {"objects[].style", {"style: surface", "style: both"}},
    {"objects[].joints", {"joints: true", "joints: false"}},
    {"objects[].subdivide", {"joints: true", "joints: true\n    subdivide: 3"}},
    {"objects[].shading", {"joints: true", "joints: true\n    shading: flat"}},
    {"objects[].sharp_angle",
     {"joints: true", "joints: true\n    shading: auto\n    sharp_angle: 45"}},
    {"objects[].texture", {"    texture: quad.png\n", ""}},
    {"objects[].finish", {"finish: cloth", "finish: {like: metal, roughness: 0.2}"}},
};

TEST(MotionSettings, EveryLookOnlyKeyLeavesTheMotionTheSameBitForBit) {
  const SceneDescription base = test::scene_from_yaml(kScene);
  const auto base_motion = motion_of(base);
  for (const std::string& key : look_only_keys()) {
    const auto edit = kLookEdits.find(key);
    ASSERT_NE(edit, kLookEdits.end()) << "no edit of the look-only key '" << key << "' is tested";
    const SceneDescription edited =
        test::scene_from_yaml(replaced(kScene, edit->second.first, edit->second.second));
    EXPECT_EQ(edited.motion_settings, base.motion_settings) << key;
    EXPECT_EQ(motion_of(edited), base_motion) << key;
  }
}

TEST(MotionSettings, EditsThatMoveTheSceneDifferentlyChangeTheSettings) {
  const SceneDescription base = test::scene_from_yaml(kScene);
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"density: 800", "density: 900"},
           {"duration: 0.6", "duration: 0.7"},
           {"columns: 6", "columns: 7"},
           {"ground: {height: 0,", "ground: {height: 0.01,"},
           {"name: rope", "name: cord"},
           {"objects:\n", "gravity: [0, 0, -9.8]\nobjects:\n"}}) {
    const SceneDescription edited = test::scene_from_yaml(replaced(kScene, from, to));
    EXPECT_NE(edited.motion_settings, base.motion_settings) << from << " → " << to;
  }
  // Text that only looks different is the same setting: comments, spacing, flow or block style.
  const SceneDescription restyled = test::scene_from_yaml(
      replaced(kScene, "material: {density: 800, youngs_modulus: 2.0e6, radius: 0.003}",
               "material:  # a soft fabric\n      density: 800\n      youngs_modulus: 2.0e6\n"
               "      radius:   0.003"));
  EXPECT_EQ(restyled.motion_settings, base.motion_settings);
  // A placement's default written out places the mesh where it was: the same geometry, the same
  // setting (a cache made before stays valid).
  const SceneDescription defaults_written = test::scene_from_yaml(
      replaced(kScene, "translation: [0, 0, 0.1]}", "translation: [0, 0, 0.1], scale: 1}"));
  EXPECT_EQ(defaults_written.motion_settings, base.motion_settings);
  const auto rope_file = [](const std::string& mesh) {
    return test::scene_from_yaml("version: 1\nduration: 0.1\nobjects:\n  - mesh: " + mesh +
                                 "\n    material: {density: 800, youngs_modulus: 2.0e6, radius: "
                                 "0.003}\n");
  };
  EXPECT_EQ(rope_file("{file: rope.obj, up_axis: z}").motion_settings,
            rope_file("{file: rope.obj}").motion_settings);
  EXPECT_NE(rope_file("{file: rope.obj, rotation: [0, 0, 90]}").motion_settings,
            rope_file("{file: rope.obj}").motion_settings);
}

TEST(MotionSettings, AnEditedMeshFileCountsThoughTheSceneTextIsTheSame) {
  const test::TemporaryFolder folder("mesh");
  const auto write_mesh = [&](const char* top) {
    std::ofstream(folder.path() / "tri.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 " << top << "\nf 1 2 3\n";
  };
  const std::string scene = R"(version: 1
duration: 0.1
objects:
  - mesh: {file: tri.obj}
    material: {density: 800, youngs_modulus: 2.0e6, radius: 0.003}
)";
  write_mesh("0");
  const SceneDescription before = read_scene_text(scene, folder.path() / "s.yaml");
  write_mesh("0.5");
  const SceneDescription after = read_scene_text(scene, folder.path() / "s.yaml");
  EXPECT_EQ(before.source_sha256, after.source_sha256);
  EXPECT_NE(before.motion_settings, after.motion_settings);
  EXPECT_EQ(before.motion_settings.back().key, "objects[0].mesh geometry");
  EXPECT_EQ(before.motion_settings.back().value.rfind("sha256:", 0), 0u);
}

}  // namespace
}  // namespace dinam
