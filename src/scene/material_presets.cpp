#include "scene/material_presets.hpp"

#include <cmath>

#include "scene/scene_description.hpp"

namespace dinam {

// The fabrics' values are representative of woven cloth of each kind as the Kawabata evaluation
// system (KES-F) measures it, converted to SI: bending rigidity B, gf·cm²/cm × 9.807e-5 = N·m;
// shear stiffness G, gf/(cm·deg) × 56.19 = N/m per radian; stretch stiffness, the secant at
// KES-F's 500 gf/cm (490 N/m) over the extension measured there (EMT). Areal densities are the
// usual weights these cloths are sold by. Ropes, cables and chain: a 12 mm rope, a 6 mm 6×19
// wire rope and a 6 mm link chain as manufacturers' tables give their weight per metre and
// stiffness (density is the weight per metre over the nominal circle), with bending stiffnesses
// far below a solid rod's, as strands and links slide. Metals: handbook moduli and densities,
// annealed yield stresses.
const std::vector<MaterialPreset>& material_presets() {
  static const std::vector<MaterialPreset> presets = {
      {"cotton",
       true,
       {{"areal_density", 0.12},
        {"stretch_stiffness", 1.0e4},
        {"shear_stiffness", 55.0},
        {"bending_rigidity", 8.0e-6},
        {"thickness", 3.0e-4}},
       "shirting cotton, 120 g/m²; KES-F B 0.08 gf·cm²/cm, G 1.0 gf/(cm·deg), EMT 5 %"},
      {"denim",
       true,
       {{"areal_density", 0.40},
        {"stretch_stiffness", 3.0e4},
        {"shear_stiffness", 250.0},
        {"bending_rigidity", 1.2e-4},
        {"thickness", 8.0e-4}},
       "12 oz denim, 400 g/m²; KES-F B 1.2 gf·cm²/cm, G 4.5 gf/(cm·deg), EMT 1.6 %"},
      {"silk",
       true,
       {{"areal_density", 0.06},
        {"stretch_stiffness", 5.0e3},
        {"shear_stiffness", 20.0},
        {"bending_rigidity", 1.5e-6},
        {"thickness", 1.5e-4}},
       "silk habotai, 60 g/m²; KES-F B 0.015 gf·cm²/cm, G 0.35 gf/(cm·deg), EMT 10 %"},
      {"canvas",
       true,
       {{"areal_density", 0.34},
        {"stretch_stiffness", 4.0e4},
        {"shear_stiffness", 400.0},
        {"bending_rigidity", 2.5e-4},
        {"thickness", 7.0e-4}},
       "10 oz cotton duck, 340 g/m²; KES-F B 2.5 gf·cm²/cm, G 7 gf/(cm·deg), EMT 1.2 %"},
      {"leather",
       true,
       {{"areal_density", 1.0},
        {"stretch_stiffness", 3.0e4},
        {"shear_stiffness", 1.0e4},
        {"bending_rigidity", 3.6e-3},
        {"thickness", 1.2e-3}},
       "garment leather 1.2 mm, 830 kg/m³; tensile modulus 25 MPa at low strain, nearly "
       "isotropic: S = E t, G = E t / 3, B = E t³ / 12"},
      {"rubber_sheet",
       true,
       {{"areal_density", 0.93},
        {"stretch_stiffness", 1.5e3},
        {"shear_stiffness", 500.0},
        {"bending_rigidity", 1.67e-4},
        {"thickness", 1.0e-3}},
       "natural rubber 1 mm, 930 kg/m³, E 1.5 MPa, ν 0.5: S = E t, G = E t / 3, "
       "B = E t³ / 12(1 − ν²)"},
      {"hemp_rope",
       false,
       {{"density", 973.0},
        {"youngs_modulus", 1.06e9},
        {"radius", 0.006},
        {"bending_stiffness", 1.0e-3},
        {"torsion_stiffness", 1.0e-3}},
       "12 mm three-strand hemp, 0.11 kg/m, EA 120 kN; bending estimated at 0.1 % of a solid "
       "rod's (strands that slide)"},
      {"nylon_rope",
       false,
       {{"density", 796.0},
        {"youngs_modulus", 5.3e8},
        {"radius", 0.006},
        {"bending_stiffness", 5.0e-4},
        {"torsion_stiffness", 5.0e-4}},
       "12 mm three-strand nylon, 0.09 kg/m, EA 60 kN at working loads; bending estimated at "
       "0.1 % of a solid rod's (strands that slide)"},
      {"steel_cable",
       false,
       {{"density", 4600.0},
        {"youngs_modulus", 4.9e10},
        {"radius", 0.003},
        {"bending_stiffness", 0.05},
        {"torsion_stiffness", 0.05}},
       "6 mm 6×19 wire rope, 0.13 kg/m, EA 1.4 MN (100 GPa on its 14 mm² of steel); bending "
       "near the sum of its 114 wires' (0.03 N·m²), not a solid rod's (12.7)"},
      {"chain",
       false,
       {{"density", 2546.0},
        {"youngs_modulus", 3.2e10},
        {"radius", 0.01},
        {"bending_stiffness", 1.0e-5},
        {"torsion_stiffness", 1.0e-4}},
       "6 mm steel link chain, 0.8 kg/m, 20 mm wide; its links hinge, so it barely resists "
       "bending"},
      {"copper_wire",
       false,
       {{"density", 8960.0},
        {"youngs_modulus", 1.17e11},
        {"shear_modulus", 4.4e10},
        {"radius", 0.001},
        {"yield_stress", 7.0e7}},
       "annealed copper: E 117 GPa, G 44 GPa, 8960 kg/m³, yield 70 MPa; 2 mm wire"},
      {"steel_wire",
       false,
       {{"density", 7850.0},
        {"youngs_modulus", 2.0e11},
        {"shear_modulus", 7.9e10},
        {"radius", 0.001},
        {"yield_stress", 2.5e8}},
       "mild steel: E 200 GPa, G 79 GPa, 7850 kg/m³, yield 250 MPa; 2 mm wire"},
  };
  return presets;
}

const double* MaterialPreset::find(std::string_view key) const {
  for (const auto& [known, value] : values) {
    if (key == known) {
      return &value;
    }
  }
  return nullptr;
}

const MaterialPreset* find_material_preset(std::string_view name) {
  for (const MaterialPreset& preset : material_presets()) {
    if (name == preset.name) {
      return &preset;
    }
  }
  return nullptr;
}

std::vector<MaterialValue> resolved_material_values(const MaterialDesc& material) {
  std::vector<MaterialValue> values;
  if (material.sheet) {
    const SheetDesc& s = *material.sheet;
    values = {{"areal_density", s.areal_density, "kg/m²"},
              {"stretch_stiffness", s.stretch_stiffness, "N/m"},
              {"shear_stiffness", s.shear_stiffness, "N/m"},
              {"bending_rigidity", s.bending_rigidity, "N·m"},
              {"thickness", s.thickness, "m"}};
    if (!std::isinf(s.yield_stretch)) {
      values.push_back({"yield.stretch", s.yield_stretch, "N/m"});
    }
    if (!std::isinf(s.yield_bending)) {
      values.push_back({"yield.bending", s.yield_bending, "N·m/m"});
    }
  } else {
    values = {{"density", material.density, "kg/m³"},
              {"youngs_modulus", material.youngs_modulus, "Pa"},
              {"shear_modulus", material.shear_modulus, "Pa"}};
    if (material.wire_radius > 0.0) {
      values.push_back({"radius", material.wire_radius, "m"});
    } else {
      values.push_back({"area", material.area, "m²"});
    }
    values.push_back({"bending_stiffness", material.youngs_modulus * material.area_moment, "N·m²"});
    values.push_back({"torsion_stiffness", material.shear_modulus * material.polar_moment, "N·m²"});
    const std::pair<const char*, double> yields[] = {
        {"yield.axial", material.yield_axial_force},
        {"yield.bending", material.yield_bending_moment},
        {"yield.torsion", material.yield_torsion_moment}};
    for (const auto& [key, value] : yields) {
      if (!std::isinf(value)) {
        values.push_back({key, value, key == std::string_view("yield.axial") ? "N" : "N·m"});
      }
    }
  }
  if (!std::isinf(material.breaking_strain)) {
    values.push_back({"breaking.strain", material.breaking_strain, ""});
  }
  if (!std::isinf(material.breaking_force)) {
    values.push_back({"breaking.force", material.breaking_force, material.sheet ? "N/m" : "N"});
  }
  return values;
}

}  // namespace dinam
