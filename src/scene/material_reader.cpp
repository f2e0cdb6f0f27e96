// The reader of a material (an object's `material`, and each of its `parts`). docs/scene-format.md
// documents every key read here; keep the two together.
#include <fmt/ranges.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "scene/element_readers.hpp"
#include "scene/scene_description.hpp"
#include "scene/yaml_map.hpp"

namespace dinam {
namespace {}  // namespace

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

MaterialDesc read_material(YamlMap map) {
  MaterialDesc material;
  material.loc = map.loc();
  material.density = map.required_number("density");
  require_positive(material.density, map.loc("density"), map.path("density"), "kg/m³");
  require_in_range(material.density, 1e-6, 1e6, map.loc("density"), map.path("density"), "kg/m³");
  material.youngs_modulus = map.required_number("youngs_modulus");
  require_positive(material.youngs_modulus, map.loc("youngs_modulus"), map.path("youngs_modulus"),
                   "Pa");
  require_in_range(material.youngs_modulus, 1e-3, 1e13, map.loc("youngs_modulus"),
                   map.path("youngs_modulus"), "Pa");
  // G defaults to that of an isotropic solid with Poisson's ratio 0.3: G = E / (2 (1 + ν)).
  material.shear_modulus = map.number("shear_modulus", material.youngs_modulus / 2.6);
  require_positive(material.shear_modulus, map.loc("shear_modulus"), map.path("shear_modulus"),
                   "Pa");
  require_in_range(material.shear_modulus, 1e-3, 1e13, map.loc("shear_modulus"),
                   map.path("shear_modulus"), "Pa");

  const bool has_radius = map.has("radius");
  const bool has_area = map.has("area");
  if (has_radius == has_area) {
    throw_user_error(map.loc(),
                     "'{}' needs the section: either 'radius' (a circular wire, m) or 'area' (m², "
                     "with optional 'area_moment' and 'polar_moment', m⁴), not both",
                     map.name());
  }
  if (has_radius) {
    const double r = map.required_number("radius");
    require_positive(r, map.loc("radius"), map.path("radius"), "m");
    require_in_range(r, 1e-7, 100.0, map.loc("radius"), map.path("radius"), "m");
    material.wire_radius = r;
    material.area = std::numbers::pi * r * r;
    material.area_moment = std::numbers::pi * std::pow(r, 4) / 4.0;
    material.polar_moment = std::numbers::pi * std::pow(r, 4) / 2.0;
  } else {
    material.area = map.required_number("area");
    require_positive(material.area, map.loc("area"), map.path("area"), "m²");
    require_in_range(material.area, 1e-14, 1e4, map.loc("area"), map.path("area"), "m²");
    // Without I and J, those of the circle of the same area: I = A²/(4π), J = 2I.
    material.area_moment =
        map.number("area_moment", material.area * material.area / (4.0 * std::numbers::pi));
    require_positive(material.area_moment, map.loc("area_moment"), map.path("area_moment"), "m⁴");
    require_in_range(material.area_moment, 1e-30, 1e8, map.loc("area_moment"),
                     map.path("area_moment"), "m⁴");
    material.polar_moment = map.number("polar_moment", 2.0 * material.area_moment);
    require_positive(material.polar_moment, map.loc("polar_moment"), map.path("polar_moment"),
                     "m⁴");
    require_in_range(material.polar_moment, 1e-30, 1e8, map.loc("polar_moment"),
                     map.path("polar_moment"), "m⁴");
  }

  // Yield: from a yield stress σy and the section, then any kind given directly overrides it.
  // With r the wire radius (or that of the circle of the same area), the fully plastic values
  // of a round section: Ny = σy A, My = (4/3) r³ σy, Ty = (2π/3) r³ τy with τy = σy/√3 (von
  // Mises).
  if (map.has("yield_stress")) {
    const double sigma = map.number("yield_stress", 0.0);
    require_positive(sigma, map.loc("yield_stress"), map.path("yield_stress"), "Pa");
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
  if (map.has("breaking")) {
    YamlMap breaking(map.get("breaking"), map.file(), map.path("breaking"));
    if (!breaking.has("strain") && !breaking.has("force")) {
      throw_user_error(breaking.loc(), "'{}' needs 'strain' (for example 0.3) or 'force' (N)",
                       breaking.name());
    }
    if (breaking.has("strain")) {
      material.breaking_strain = breaking.number("strain", 0.0);
      require_in_range(material.breaking_strain, 1e-6, 100.0, breaking.loc("strain"),
                       breaking.path("strain"), "(a strain)");
    }
    if (breaking.has("force")) {
      material.breaking_force = breaking.number("force", 0.0);
      require_positive(material.breaking_force, breaking.loc("force"), breaking.path("force"), "N");
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
