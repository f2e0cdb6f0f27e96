// The reader of a material (an object's `material`, and each of its `parts`). docs/scene-format.md
// documents every key read here; keep the two together.
#include <fmt/ranges.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "scene/element_readers.hpp"
#include "scene/material_presets.hpp"
#include "scene/scene_description.hpp"
#include "scene/yaml_map.hpp"

namespace dinam {

void require_positive(double value, const FileLoc& loc, const std::string& what, const char* unit) {
  if (!(value > 0.0)) {
    throw_user_error(loc, "'{}' must be greater than zero ({}), got {}", what, unit, value);
  }
}

void require_in_range(double value, double low, double high, const FileLoc& loc,
                      const std::string& what, const char* unit) {
  if (!(value >= low && value <= high)) {
    throw_user_error(loc, "'{}' must be between {:g} and {:g} {}, got {:g}", what, low, high, unit,
                     value);
  }
}

namespace {

// A material's keys as the scene gives them, else as its preset does: `has` and `number` read the
// scene's key where it is there (so an unknown key is still caught by finish()), the preset's
// value where not; `loc` names the key's line, or the preset's.
class MaterialKeys {
 public:
  explicit MaterialKeys(YamlMap& map) : map_(map) {
    if (map_.has("preset")) {
      const std::string name = map_.string("preset", "");
      preset_ = find_material_preset(name);
      if (preset_ == nullptr) {
        std::vector<std::string> names;
        for (const MaterialPreset& preset : material_presets()) {
          names.emplace_back(preset.name);
        }
        throw_user_error(map_.loc("preset"),
                         "'{}': no material preset is called '{}'{}; the presets are {} "
                         "(docs/materials.md gives their values)",
                         map_.path("preset"), name, did_you_mean(name, names),
                         fmt::join(names, ", "));
      }
    }
  }
  const MaterialPreset* preset() const { return preset_; }
  bool given(const std::string& key) {
    return map_.has(key) || (preset_ != nullptr && preset_->find(key) != nullptr);
  }
  bool in_scene(const std::string& key) { return map_.has(key); }
  double number(const std::string& key) {
    if (map_.has(key) || preset_ == nullptr || preset_->find(key) == nullptr) {
      return map_.required_number(key);
    }
    return *preset_->find(key);
  }
  FileLoc loc(const std::string& key) {
    return map_.has(key) || !map_.has("preset") ? map_.loc(key) : map_.loc("preset");
  }
  std::string path(const std::string& key) const { return map_.path(key); }

  // Reads `key` (given, or required) and checks it lies in [low, high].
  double bounded(const std::string& key, double low, double high, const char* unit) {
    const double value = number(key);
    require_positive(value, loc(key), path(key), unit);
    require_in_range(value, low, high, loc(key), path(key), unit);
    return value;
  }

 private:
  YamlMap& map_;
  const MaterialPreset* preset_ = nullptr;
};

constexpr const char* kSheetKeys[] = {"areal_density", "stretch_stiffness", "shear_stiffness",
                                      "bending_rigidity", "thickness"};
constexpr const char* kWireKeys[] = {
    "density",      "youngs_modulus",    "shear_modulus",     "radius",      "area", "area_moment",
    "polar_moment", "bending_stiffness", "torsion_stiffness", "yield_stress"};

// A sheet's areal values (SheetDesc); a wire's keys beside them are an error.
SheetDesc read_sheet(YamlMap& map, MaterialKeys& keys) {
  for (const char* key : kWireKeys) {
    if (keys.in_scene(key)) {
      throw_user_error(map.loc(key),
                       "'{}' is a wire's or a rope's value, but this material is a sheet (it "
                       "has 'areal_density'{}): a sheet takes areal_density, stretch_stiffness, "
                       "shear_stiffness, bending_rigidity and thickness",
                       map.path(key),
                       keys.preset() != nullptr
                           ? fmt::format(", from the preset '{}'", keys.preset()->name)
                           : "");
    }
  }
  SheetDesc sheet;
  sheet.areal_density = keys.bounded("areal_density", 1e-4, 1e3, "kg/m²");
  sheet.stretch_stiffness = keys.bounded("stretch_stiffness", 1e-3, 1e10, "N/m");
  sheet.shear_stiffness = keys.bounded("shear_stiffness", 1e-3, 1e10, "N/m");
  sheet.bending_rigidity = keys.bounded("bending_rigidity", 1e-12, 1e6, "N·m");
  sheet.thickness = keys.given("thickness") ? keys.bounded("thickness", 1e-6, 0.1, "m") : 5e-4;
  if (map.has("yield")) {
    YamlMap yield(map.get("yield"), map.file(), map.path("yield"));
    if (yield.has("stretch")) {
      sheet.yield_stretch = yield.number("stretch", 0.0);
      require_positive(sheet.yield_stretch, yield.loc("stretch"), yield.path("stretch"), "N/m");
    }
    if (yield.has("bending")) {
      sheet.yield_bending = yield.number("bending", 0.0);
      require_positive(sheet.yield_bending, yield.loc("bending"), yield.path("bending"), "N·m/m");
    }
    yield.finish();
  }
  return sheet;
}

// A wire's or a rope's section and moduli, with the values derived from them.
void read_wire(YamlMap& map, MaterialKeys& keys, MaterialDesc& material) {
  for (const char* key : kSheetKeys) {
    if (keys.in_scene(key)) {
      throw_user_error(
          map.loc(key),
          "'{}' is a sheet's value, but this material is a wire or a rope{}: give a "
          "sheet 'areal_density' and no 'density' or section",
          map.path(key),
          keys.preset() != nullptr ? fmt::format(" (the preset '{}')", keys.preset()->name) : "");
    }
  }
  material.density = keys.bounded("density", 1e-6, 1e6, "kg/m³");
  material.youngs_modulus = keys.bounded("youngs_modulus", 1e-3, 1e13, "Pa");
  // G defaults to that of an isotropic solid with Poisson's ratio 0.3: G = E / (2 (1 + ν)).
  material.shear_modulus = keys.given("shear_modulus")
                               ? keys.bounded("shear_modulus", 1e-3, 1e13, "Pa")
                               : material.youngs_modulus / 2.6;

  // The scene's own section wins over a preset's: `area` given beside a preset's `radius`.
  const bool has_area = keys.in_scene("area") || (!keys.in_scene("radius") && keys.given("area"));
  const bool has_radius = keys.in_scene("radius") || (!has_area && keys.given("radius"));
  if (keys.in_scene("radius") && keys.in_scene("area")) {
    throw_user_error(map.loc(),
                     "'{}' needs the section: either 'radius' (a circular wire, m) or 'area' (m², "
                     "with optional 'area_moment' and 'polar_moment', m⁴), not both",
                     map.name());
  }
  if (!has_radius && !has_area) {
    throw_user_error(map.loc(),
                     "'{}' needs the section: either 'radius' (a circular wire, m) or 'area' (m², "
                     "with optional 'area_moment' and 'polar_moment', m⁴); or, for a sheet, "
                     "'areal_density' and the sheet's stiffnesses; or a 'preset'",
                     map.name());
  }
  if (has_radius) {
    const double r = keys.bounded("radius", 1e-7, 100.0, "m");
    material.wire_radius = r;
    material.area = std::numbers::pi * r * r;
    material.area_moment = std::numbers::pi * std::pow(r, 4) / 4.0;
    material.polar_moment = std::numbers::pi * std::pow(r, 4) / 2.0;
  } else {
    material.area = keys.bounded("area", 1e-14, 1e4, "m²");
    // Without I and J, those of the circle of the same area: I = A²/(4π), J = 2I.
    material.area_moment = keys.given("area_moment")
                               ? keys.bounded("area_moment", 1e-30, 1e8, "m⁴")
                               : material.area * material.area / (4.0 * std::numbers::pi);
    material.polar_moment = keys.given("polar_moment")
                                ? keys.bounded("polar_moment", 1e-30, 1e8, "m⁴")
                                : 2.0 * material.area_moment;
  }
  // A rope's or a chain's bending and twist, far below a solid rod's of its diameter: E I and G J
  // given as such, which the section's I and J then follow.
  if (keys.given("bending_stiffness")) {
    material.area_moment =
        keys.bounded("bending_stiffness", 1e-15, 1e12, "N·m²") / material.youngs_modulus;
  }
  if (keys.given("torsion_stiffness")) {
    material.polar_moment =
        keys.bounded("torsion_stiffness", 1e-15, 1e12, "N·m²") / material.shear_modulus;
  }

  // Yield: from a yield stress σy and the section, then any kind given directly overrides it.
  // With r the wire radius (or that of the circle of the same area), the fully plastic values
  // of a round section: Ny = σy A, My = (4/3) r³ σy, Ty = (2π/3) r³ τy with τy = σy/√3 (von
  // Mises).
  if (keys.given("yield_stress")) {
    const double sigma = keys.number("yield_stress");
    require_positive(sigma, keys.loc("yield_stress"), keys.path("yield_stress"), "Pa");
    const double r = std::sqrt(material.area / std::numbers::pi);
    material.yield_axial_force = sigma * material.area;
    material.yield_bending_moment = 4.0 / 3.0 * r * r * r * sigma;
    material.yield_torsion_moment =
        2.0 * std::numbers::pi / 3.0 * r * r * r * sigma / std::sqrt(3.0);
  }
  if (map.has("yield")) {
    YamlMap yield(map.get("yield"), map.file(), map.path("yield"));
    const std::pair<const char*, double*> kinds[] = {{"axial", &material.yield_axial_force},
                                                     {"bending", &material.yield_bending_moment},
                                                     {"torsion", &material.yield_torsion_moment}};
    for (const auto& [key, value] : kinds) {
      if (yield.has(key)) {
        *value = yield.number(key, 0.0);
        require_positive(*value, yield.loc(key), yield.path(key),
                         std::string(key) == "axial" ? "N" : "N·m");
      } else {
        yield.get(key);  // known, absent
      }
    }
    yield.finish();
  }
}

}  // namespace

MaterialDesc read_material(YamlMap map) {
  MaterialDesc material;
  material.loc = map.loc();
  MaterialKeys keys(map);
  if (keys.preset() != nullptr) {
    material.preset = keys.preset()->name;
  }
  const bool sheet = keys.preset() != nullptr ? keys.preset()->sheet : keys.given("areal_density");
  if (sheet) {
    material.sheet = read_sheet(map, keys);
  } else {
    read_wire(map, keys, material);
  }
  if (map.has("breaking")) {
    YamlMap breaking(map.get("breaking"), map.file(), map.path("breaking"));
    const char* force_unit = sheet ? "N/m" : "N";
    if (!breaking.has("strain") && !breaking.has("force")) {
      throw_user_error(breaking.loc(), "'{}' needs 'strain' (for example 0.3) or 'force' ({})",
                       breaking.name(), sheet ? "N/m, per width" : "N");
    }
    if (breaking.has("strain")) {
      material.breaking_strain = breaking.number("strain", 0.0);
      require_in_range(material.breaking_strain, 1e-6, 100.0, breaking.loc("strain"),
                       breaking.path("strain"), "(a strain)");
    }
    if (breaking.has("force")) {
      material.breaking_force = breaking.number("force", 0.0);
      require_positive(material.breaking_force, breaking.loc("force"), breaking.path("force"),
                       force_unit);
    }
    breaking.finish();
  }
  map.finish();
  return material;
}

MaterialPartDesc read_material_part(YamlMap part, const RawMesh& mesh) {
  MaterialPartDesc desc;
  desc.loc = part.loc();
  const int selectors =
      int{part.has("nodes")} + int{part.has("mesh_material")} + int{part.has("mesh_group")};
  if (selectors != 1) {
    throw_user_error(part.loc(),
                     "'{}' needs exactly one of 'nodes' (a node selection), 'mesh_material' or "
                     "'mesh_group' (a name from the mesh file) to say which bars it holds",
                     part.name());
  }
  if (part.has("nodes")) {
    desc.nodes = read_nodes(YamlMap(part.get("nodes"), part.file(), part.path("nodes")), mesh);
  } else {
    const bool by_material = part.has("mesh_material");
    const char* key = by_material ? "mesh_material" : "mesh_group";
    const MeshNameKind kind = by_material ? MeshNameKind::kMaterial : MeshNameKind::kGroup;
    const std::string name = part.string(key, "");
    const MeshElementIds ids = elements_named(mesh, kind, name);
    if (ids.empty()) {
      const std::vector<std::string> names = element_names(mesh, kind);
      throw_user_error(part.loc(key), "'{}': no face or line of the mesh has the {} '{}'; {}",
                       part.path(key), by_material ? "material" : "group", name,
                       names.empty()
                           ? fmt::format("the mesh names no {}s (only a mesh file can)",
                                         by_material ? "material" : "group")
                           : fmt::format("its {}s are {}", by_material ? "material" : "group",
                                         fmt::join(names, ", ")));
    }
    desc.mesh_faces = ids.faces;
    desc.mesh_lines = ids.lines;
  }
  desc.material =
      read_material(YamlMap(part.required("material"), part.file(), part.path("material")));
  part.finish();
  return desc;
}

}  // namespace dinam
