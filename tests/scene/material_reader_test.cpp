// Materials as the scene gives them (scene/material_reader.cpp, material_presets.cpp): a preset
// and the keys that override it, a sheet's areal values, a rope's own bending and twist, and the
// errors that name the line and the fix.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>

#include "model/model.hpp"
#include "scene/material_presets.hpp"
#include "test_support.hpp"

namespace dinam {
namespace {

// A scene of one object with `mesh` and `material` (YAML flow maps), on line 6 and 7.
SceneDescription scene_with(const std::string& mesh, const std::string& material) {
  return test::scene_from_yaml(fmt::format(R"(version: 1
duration: 1
objects:
  - name: thing
    mesh: {}
    material: {}
)",
                                           mesh, material));
}

const char* const kGrid = "{grid: {width: 1, height: 1, columns: 2, rows: 2}}";
const char* const kLine = "{polyline: {points: [[0, 0, 1], [1, 0, 1]], segments: 4}}";

TEST(MaterialPresets, EveryPresetReadsAndSaysWhereItsValuesComeFrom) {
  for (const MaterialPreset& preset : material_presets()) {
    const SceneDescription scene =
        scene_with(preset.sheet ? kGrid : kLine, fmt::format("{{preset: {}}}", preset.name));
    const MaterialDesc& m = scene.objects[0].material;
    EXPECT_EQ(m.preset, preset.name);
    EXPECT_EQ(m.sheet.has_value(), preset.sheet) << preset.name;
    EXPECT_GT(std::string(preset.source).size(), 20u) << preset.name;
    // What `dinam info` prints is the preset's own values, key by key.
    for (const MaterialValue& value : resolved_material_values(m)) {
      if (const double* given = preset.find(value.key)) {
        EXPECT_DOUBLE_EQ(value.value, *given) << preset.name << " " << value.key;
      }
    }
    EXPECT_NO_THROW(build_model(scene)) << preset.name;
  }
}

// docs/materials.md gives every preset with its values, as %g prints them, and its source.
TEST(MaterialPresets, TheDocsListEveryPresetWithItsValues) {
  std::ifstream in(std::filesystem::path(DINAM_SOURCE_DIR) / "docs" / "materials.md");
  const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const MaterialPreset& preset : material_presets()) {
    const auto at = doc.find(fmt::format("| `{}` |", preset.name));
    ASSERT_NE(at, std::string::npos) << preset.name;
    const std::string row = doc.substr(at, doc.find('\n', at) - at);
    for (const auto& [key, value] : preset.values) {
      EXPECT_NE(row.find(fmt::format("| {:g} |", value)), std::string::npos)
          << preset.name << " " << key << ": " << row;
    }
    EXPECT_NE(row.find(preset.source), std::string::npos) << preset.name;
  }
}

TEST(MaterialPresets, SceneKeysOverrideThePresetOneByOne) {
  const MaterialDesc rope =
      scene_with(kLine, "{preset: hemp_rope, radius: 0.008, bending_stiffness: 2.0e-3}")
          .objects[0]
          .material;
  EXPECT_DOUBLE_EQ(rope.wire_radius, 0.008);
  EXPECT_DOUBLE_EQ(rope.density, *find_material_preset("hemp_rope")->find("density"));
  EXPECT_DOUBLE_EQ(rope.youngs_modulus * rope.area_moment, 2.0e-3);
  const MaterialDesc silk =
      scene_with(kGrid, "{preset: silk, shear_stiffness: 30}").objects[0].material;
  ASSERT_TRUE(silk.sheet);
  EXPECT_DOUBLE_EQ(silk.sheet->shear_stiffness, 30.0);
  EXPECT_DOUBLE_EQ(silk.sheet->areal_density, 0.06);
  // The scene's own section beside a preset's radius: `area` wins, with the preset's E.
  const MaterialDesc cable =
      scene_with(kLine, "{preset: steel_cable, area: 2.0e-5}").objects[0].material;
  EXPECT_DOUBLE_EQ(cable.area, 2.0e-5);
  EXPECT_DOUBLE_EQ(cable.wire_radius, 0.0);
}

// A rope's bending and twist stiffness apart from its axial: E I and G J as given.
TEST(MaterialReader, ARopeTakesItsOwnBendingAndTorsionStiffness) {
  const MaterialDesc m =
      scene_with(kLine,
                 "{density: 1000, youngs_modulus: 1.0e9, radius: 0.005, bending_stiffness: "
                 "4.0e-3, torsion_stiffness: 1.0e-3}")
          .objects[0]
          .material;
  EXPECT_DOUBLE_EQ(m.area, std::numbers::pi * 25e-6);  // the axial section stays the wire's
  EXPECT_DOUBLE_EQ(m.youngs_modulus * m.area_moment, 4.0e-3);
  EXPECT_DOUBLE_EQ(m.shear_modulus * m.polar_moment, 1.0e-3);
}

TEST(MaterialReader, ASheetTakesItsArealValues) {
  const MaterialDesc m =
      scene_with(kGrid,
                 "{areal_density: 0.2, stretch_stiffness: 5000, shear_stiffness: 40, "
                 "bending_rigidity: 1.0e-5, yield: {bending: 1.0e-3}, breaking: {strain: 0.2}}")
          .objects[0]
          .material;
  ASSERT_TRUE(m.sheet);
  EXPECT_DOUBLE_EQ(m.sheet->stretch_stiffness, 5000.0);
  EXPECT_DOUBLE_EQ(m.sheet->thickness, 5e-4);  // the default
  EXPECT_DOUBLE_EQ(m.sheet->yield_bending, 1e-3);
  EXPECT_DOUBLE_EQ(m.breaking_strain, 0.2);
}

TEST(MaterialReader, MixedUpKeysNameTheLineAndTheFix) {
  test::expect_user_error([] { scene_with(kGrid, "{preset: velvet}"); }, 6,
                          {"no material preset is called 'velvet'", "cotton", "steel_cable"});
  test::expect_user_error([] { scene_with(kGrid, "{preset: cotton, radius: 0.001}"); }, 6,
                          {"'objects[0].material.radius' is a wire's", "preset 'cotton'"});
  test::expect_user_error([] { scene_with(kLine, "{preset: hemp_rope, areal_density: 0.1}"); }, 6,
                          {"is a sheet's value", "hemp_rope"});
  test::expect_user_error([] { scene_with(kLine, "{density: 1000, youngs_modulus: 1.0e6}"); }, 6,
                          {"needs the section", "areal_density", "preset"});
  test::expect_user_error(
      [] {
        scene_with(kGrid, "{areal_density: 0.2, stretch_stiffness: 5000, bending_rigidity: 1}");
      },
      6, {"shear_stiffness"});
  test::expect_user_error(
      [] {
        scene_with(kGrid,
                   "{areal_density: 0.2, stretch_stiffness: -5, shear_stiffness: 1, "
                   "bending_rigidity: 1}");
      },
      6, {"stretch_stiffness", "greater than zero", "N/m"});
}

// A sheet's mass and stiffness are its faces': on a mesh of lines it would have none.
TEST(MaterialReader, ASheetOnAMeshWithoutFacesIsRefused) {
  test::expect_user_error([] { build_model(scene_with(kLine, "{preset: cotton}")); }, 6,
                          {"object 'thing' has a sheet material", "no faces", "hemp_rope"});
}

TEST(MaterialReader, ANetOfSheetIsRefused) {
  test::expect_user_error(
      [] {
        test::scene_from_yaml(R"(version: 1
duration: 1
objects:
  - name: thing
    mesh: {grid: {width: 1, height: 1, columns: 2, rows: 2}}
    material: {preset: cotton}
    faces: net
)");
      },
      7, {"sheet material", "a net needs a wire material"});
}

// A sheet whose bending length (B / ρ_A g)^⅓ is below its bars cannot show its folds: warned,
// with the bar length that would.
TEST(MaterialReader, ASheetTooSupplyForItsMeshIsWarned) {
  const Model coarse = build_model(
      scene_with(kGrid, "{preset: silk}"));  // 0.5 m bars; c = (1.5e-6 / (0.06 g))^⅓ = 13.7 mm
  ASSERT_EQ(coarse.warnings.size(), 1u);
  test::expect_contains(coarse.warnings[0],
                        {"inline.yaml:6:15: warning", "bending length", "13.7 mm", "500 mm"});
  const Model fine = build_model(
      scene_with("{grid: {width: 0.1, height: 0.1, columns: 10, rows: 10}}", "{preset: silk}"));
  EXPECT_TRUE(fine.warnings.empty()) << fine.warnings.front();
  // Pinned whole (an obstacle, the Blender add-on's collider) it never bends: nothing to warn of.
  SceneDescription obstacle = scene_with(kGrid, "{preset: silk}");
  obstacle.objects[0].pins.all = true;
  const Model still = build_model(obstacle);
  EXPECT_TRUE(still.warnings.empty()) << still.warnings.front();
}

}  // namespace
}  // namespace dinam
