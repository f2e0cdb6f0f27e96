// The readers of a scene's objects: material, mesh (file, grid or polyline) and its placement,
// pinned and other node sets, velocities, drawing. Each reads every key it knows and finishes its
// map; docs/scene-format.md documents every key read here; keep the two together.
#include <fmt/ranges.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <numbers>
#include <system_error>

#include "scene/element_readers.hpp"
#include "scene/mesh_generators.hpp"
#include "scene/mesh_loader.hpp"
#include "scene/scene_description.hpp"
#include "scene/yaml_map.hpp"

namespace dinam {
namespace {

constexpr double kPi = std::numbers::pi;

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
    material.area = kPi * r * r;
    material.area_moment = kPi * std::pow(r, 4) / 4.0;
    material.polar_moment = kPi * std::pow(r, 4) / 2.0;
  } else {
    material.area = map.required_number("area");
    require_positive(material.area, map.loc("area"), map.path("area"), "m²");
    require_in_range(material.area, 1e-14, 1e4, map.loc("area"), map.path("area"), "m²");
    // Without I and J, those of the circle of the same area: I = A²/(4π), J = 2I.
    material.area_moment = map.number("area_moment", material.area * material.area / (4.0 * kPi));
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
    const double r = std::sqrt(material.area / kPi);
    material.yield_axial_force = sigma * material.area;
    material.yield_bending_moment = 4.0 / 3.0 * r * r * r * sigma;
    material.yield_torsion_moment = 2.0 * kPi / 3.0 * r * r * r * sigma / std::sqrt(3.0);
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

Transform read_transform(YamlMap& map) {
  Transform transform;
  const YAML::Node scale = map.get("scale");
  if (scale && scale.IsScalar()) {
    transform.scale = Vec3::Constant(as_double(scale, map.file(), map.path("scale")));
  } else if (scale) {
    transform.scale = as_vec3(scale, map.file(), map.path("scale"));
  }
  if ((transform.scale.array() <= 0.0).any()) {
    throw_user_error(map.loc("scale"), "'{}' must be positive", map.path("scale"));
  }
  transform.rotation_degrees = map.vec3("rotation", transform.rotation_degrees);
  transform.translation = map.vec3("translation", transform.translation);
  return transform;
}

GridSpec read_grid(YamlMap map) {
  GridSpec grid;
  grid.width = map.required_number("width");
  require_positive(grid.width, map.loc("width"), map.path("width"), "m");
  grid.height = map.required_number("height");
  require_positive(grid.height, map.loc("height"), map.path("height"), "m");
  grid.columns = map.integer("columns", grid.columns);
  grid.rows = map.integer("rows", grid.rows);
  for (const char* key : {"columns", "rows"}) {
    const int n = std::string(key) == "columns" ? grid.columns : grid.rows;
    if (n < 1 || n > 4096) {
      throw_user_error(map.loc(key), "'{}' must be between 1 and 4096, got {}", map.path(key), n);
    }
  }
  const std::string diagonals = map.string("diagonals", "one");
  if (diagonals == "none") {
    grid.diagonals = GridDiagonals::kNone;
  } else if (diagonals == "one") {
    grid.diagonals = GridDiagonals::kOne;
  } else if (diagonals == "both") {
    grid.diagonals = GridDiagonals::kBoth;
  } else {
    throw_user_error(map.loc("diagonals"), "'{}' must be none, one or both; got '{}'",
                     map.path("diagonals"), diagonals);
  }
  map.finish();
  return grid;
}

PolylineSpec read_polyline(YamlMap map) {
  PolylineSpec polyline;
  const YAML::Node points = map.get("points");
  if (!points || !points.IsSequence() || points.size() < 2) {
    throw_user_error(map.loc("points"), "'{}' must be a list of at least two points [x, y, z]",
                     map.path("points"));
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    polyline.points.push_back(
        as_vec3(points[i], map.file(), fmt::format("{}[{}]", map.path("points"), i)));
  }
  polyline.segments_per_span = map.integer("segments", polyline.segments_per_span);
  if (polyline.segments_per_span < 1 || polyline.segments_per_span > 100000) {
    throw_user_error(map.loc("segments"), "'{}' must be between 1 and 100000, got {}",
                     map.path("segments"), polyline.segments_per_span);
  }
  map.finish();
  return polyline;
}

// The length of one of the mesh's units in metres: `units` when given, else what the file states
// (FBX), else 1 (the file is taken to be in metres).
double read_units(YamlMap& map, const RawMesh& mesh) {
  if (!map.has("units")) {
    map.get("units");  // known, absent
    return mesh.metres_per_unit.value_or(1.0);
  }
  static constexpr std::array<std::pair<const char*, double>, 5> kUnits = {
      {{"mm", 1e-3}, {"cm", 1e-2}, {"m", 1.0}, {"in", 0.0254}, {"ft", 0.3048}}};
  const std::string units = map.string("units", "");
  for (const auto& [name, metres] : kUnits) {
    if (units == name) {
      return metres;
    }
  }
  throw_user_error(map.loc("units"), "'{}' must be mm, cm, m, in or ft; got '{}'",
                   map.path("units"), units);
}

// Reads `weld`: the fraction of the object's median bar length below which a bar is collapsed.
void read_weld(YamlMap& map, ObjectDesc& object) {
  object.weld_loc = map.has("weld") ? map.loc("weld") : map.loc();
  if (map.has("weld") && map.string("weld", "") == "off") {
    object.weld_fraction = 0.0;
    return;
  }
  object.weld_fraction = map.number("weld", object.weld_fraction);
  require_in_range(object.weld_fraction, 0.0, 0.5, map.loc("weld"), map.path("weld"),
                   "(a fraction of the median bar length)");
}

// Exactly one of `file`, `grid` or `polyline`, then the units and placement. Fills the object's
// mesh, in world space, and its `weld`.
void read_mesh(YamlMap map, const std::filesystem::path& scene_folder, ObjectDesc& object) {
  const int sources = int{map.has("file")} + int{map.has("grid")} + int{map.has("polyline")};
  if (sources != 1) {
    throw_user_error(map.loc(),
                     "'{}' needs exactly one source: 'file' (a path read with assimp), 'grid' or "
                     "'polyline'",
                     map.name());
  }
  RawMesh& mesh = object.mesh;
  if (map.has("file")) {
    const std::filesystem::path file = map.string("file", "");
    mesh = load_mesh_file(file.is_absolute() ? file : scene_folder / file, map.loc("file"));
  } else if (map.has("grid")) {
    mesh = make_grid(read_grid(YamlMap(map.get("grid"), map.file(), map.path("grid"))));
  } else {
    mesh = make_polyline(
        read_polyline(YamlMap(map.get("polyline"), map.file(), map.path("polyline"))));
  }
  if (map.has("fit") && (map.has("scale") || map.has("units"))) {
    throw_user_error(map.loc("fit"),
                     "'{}' sets the size itself: give it, or 'scale' and 'units', not both",
                     map.path("fit"));
  }
  Transform transform = read_transform(map);
  transform.scale *= read_units(map, mesh);
  if (map.has("fit")) {
    YamlMap fit(map.get("fit"), map.file(), map.path("fit"));
    const double size = fit.required_number("size");
    require_in_range(size, 1e-6, 1e5, fit.loc("size"), fit.path("size"), "m");
    fit.finish();
    const Vec3 translation = transform.translation;
    transform.translation.setZero();
    apply_transform(transform, mesh);
    fit_to_size(size, mesh);
    apply_transform({Vec3::Ones(), Vec3::Zero(), translation}, mesh);
  } else {
    apply_transform(transform, mesh);
  }
  read_weld(map, object);
  map.finish();
  object.mesh_source = map.has("file") ? fmt::format("mesh file '{}'", map.string("file", ""))
                                       : std::string("the generated mesh");
  check_mesh_values(mesh, map.has("file") ? map.loc("file") : map.loc(), object.mesh_source);
}

BoxDesc read_box(YamlMap map) {
  BoxDesc box;
  box.min = map.required_vec3("min");
  box.max = map.required_vec3("max");
  map.finish();
  if ((box.min.array() > box.max.array()).any()) {
    throw_user_error(map.loc(), "'{}': every coordinate of 'min' must be at most that of 'max'",
                     map.name());
  }
  return box;
}

// One entry of an object's `parts`: which bars (exactly one of `nodes`, `mesh_material`,
// `mesh_group`) and their `material`.
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
    desc.nodes = read_nodes(YamlMap(part.get("nodes"), part.file(), part.path("nodes")),
                            mesh.vertices.size());
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

}  // namespace

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

NodeSelection read_nodes(YamlMap map, std::size_t vertex_count, bool* clamped) {
  NodeSelection pins;
  pins.loc = map.loc();
  if (clamped != nullptr) {
    *clamped = map.boolean("clamped", false);
  }
  pins.all = map.boolean("all", false);
  const YAML::Node indices = map.get("indices");
  if (indices) {
    if (!indices.IsSequence()) {
      throw_user_error(map.loc("indices"), "'{}' must be a list of vertex indices",
                       map.path("indices"));
    }
    for (std::size_t i = 0; i < indices.size(); ++i) {
      const int id = as_int(indices[i], map.file(), fmt::format("{}[{}]", map.path("indices"), i));
      if (id < 0 || static_cast<std::size_t>(id) >= vertex_count) {
        throw_user_error(loc_of(indices[i], map.file()),
                         "vertex index {} is out of range: the mesh has {} vertices "
                         "(0 to {})",
                         id, vertex_count, vertex_count - 1);
      }
      pins.vertex_ids.push_back(id);
    }
  }
  const YAML::Node box = map.get("box");
  if (box && box.IsSequence()) {
    for (std::size_t i = 0; i < box.size(); ++i) {
      pins.boxes.push_back(
          read_box(YamlMap(box[i], map.file(), fmt::format("{}[{}]", map.path("box"), i))));
    }
  } else if (box) {
    pins.boxes.push_back(read_box(YamlMap(box, map.file(), map.path("box"))));
  }
  map.finish();
  return pins;
}

ObjectDesc read_object(YamlMap map, int index, const std::filesystem::path& scene_folder) {
  ObjectDesc object;
  object.loc = map.loc();
  object.name = map.string("name", fmt::format("object{}", index));
  object.mesh_loc = map.loc("mesh");
  read_mesh(YamlMap(map.required("mesh"), map.file(), map.path("mesh")), scene_folder, object);
  object.material =
      read_material(YamlMap(map.required("material"), map.file(), map.path("material")));
  if (map.has("pinned")) {
    object.pins = read_nodes(YamlMap(map.get("pinned"), map.file(), map.path("pinned")),
                             object.mesh.vertices.size(), &object.pins_clamped);
  }
  if (map.has("pin_motion")) {
    YamlMap motion(map.get("pin_motion"), map.file(), map.path("pin_motion"));
    object.pin_motion.loc = motion.loc();
    object.pin_motion.displacement = motion.required_vec3("displacement");
    if (motion.has("profile")) {
      object.pin_motion.profile =
          read_profile(YamlMap(motion.get("profile"), map.file(), motion.path("profile")));
    }
    motion.finish();
    if (object.pins.empty()) {
      throw_user_error(object.pin_motion.loc,
                       "'{}' moves the pinned nodes of object '{}', which has none; add 'pinned'",
                       map.path("pin_motion"), object.name);
    }
  }
  object.initial_velocity = map.vec3("initial_velocity", object.initial_velocity);
  if (const YAML::Node groups = map.get("velocity_groups"); groups) {
    if (!groups.IsSequence()) {
      throw_user_error(map.loc("velocity_groups"),
                       "'{}' must be a list of {{nodes: ..., velocity: [x, y, z]}}",
                       map.path("velocity_groups"));
    }
    for (std::size_t i = 0; i < groups.size(); ++i) {
      YamlMap group(groups[i], map.file(), fmt::format("{}[{}]", map.path("velocity_groups"), i));
      VelocityGroupDesc desc;
      desc.nodes = read_nodes(YamlMap(group.required("nodes"), map.file(), group.path("nodes")),
                              object.mesh.vertices.size());
      desc.velocity = group.required_vec3("velocity");
      group.finish();
      object.velocity_groups.push_back(std::move(desc));
    }
  }
  if (const YAML::Node parts = map.get("parts"); parts) {
    if (!parts.IsSequence()) {
      throw_user_error(map.loc("parts"),
                       "'{}' must be a list of {{nodes | mesh_material | mesh_group: ..., "
                       "material: ...}}",
                       map.path("parts"));
    }
    for (std::size_t i = 0; i < parts.size(); ++i) {
      object.parts.push_back(read_material_part(
          YamlMap(parts[i], map.file(), fmt::format("{}[{}]", map.path("parts"), i)), object.mesh));
    }
  }
  const std::string pairs = map.string("bending_pairs", "auto");
  if (pairs == "auto") {
    object.bending_pairs = BendingPairs::kAuto;
  } else if (pairs == "collinear") {
    object.bending_pairs = BendingPairs::kMostCollinear;
  } else if (pairs == "all") {
    object.bending_pairs = BendingPairs::kAll;
  } else if (pairs == "none") {
    object.bending_pairs = BendingPairs::kNone;
  } else {
    throw_user_error(map.loc("bending_pairs"),
                     "'{}' must be auto, collinear, all or none; got '{}'",
                     map.path("bending_pairs"), pairs);
  }
  object.torsion = map.boolean("torsion", object.torsion);
  if (map.has("contact")) {
    object.contact =
        read_object_contact(YamlMap(map.get("contact"), map.file(), map.path("contact")));
  }
  if (map.has("damping")) {
    YamlMap damping(map.get("damping"), map.file(), map.path("damping"));
    if (damping.has("axial") && damping.has("axial_ratio")) {
      throw_user_error(damping.loc(), "'{}': give 'axial' (N·s/m) or 'axial_ratio', not both",
                       damping.name());
    }
    object.axial_damping.coefficient = damping.number("axial", 0.0);
    object.axial_damping.ratio = damping.number("axial_ratio", 0.0);
    if (object.axial_damping.coefficient < 0.0 || object.axial_damping.ratio < 0.0) {
      throw_user_error(damping.loc(), "'{}': damping cannot be negative", damping.name());
    }
    damping.finish();
  }
  const Vec3 color = map.vec3("color", object.color.cast<double>());
  if ((color.array() < 0.0).any() || (color.array() > 1.0).any()) {
    throw_user_error(map.loc("color"), "'{}' must be [r, g, b] with each between 0 and 1",
                     map.path("color"));
  }
  object.color = color.cast<float>();
  if (map.has("finish")) {
    object.finish = read_finish(map.get("finish"), map.file(), map.path("finish"));
  }
  const std::string style = map.string("style", object.mesh.faces.empty() ? "wire" : "surface");
  if (style == "surface") {
    object.style = DrawStyle::kSurface;
  } else if (style == "wire") {
    object.style = DrawStyle::kWire;
  } else if (style == "both") {
    object.style = DrawStyle::kBoth;
  } else {
    throw_user_error(map.loc("style"), "'{}' must be surface, wire or both; got '{}'",
                     map.path("style"), style);
  }
  if (object.style != DrawStyle::kWire && object.mesh.faces.empty()) {
    throw_user_error(map.loc("style"), "'{}': object '{}' has no faces to draw as a surface",
                     map.path("style"), object.name);
  }
  object.joints = map.boolean("joints", object.joints);
  if (!map.has("texture") && !object.mesh.texture.empty()) {
    object.texture = object.mesh.texture;  // the mesh file's own material
    object.texture_loc = object.mesh_loc;
  }
  if (map.has("texture")) {
    const std::filesystem::path texture = map.string("texture", "");
    object.texture = texture.is_absolute() ? texture : scene_folder / texture;
    object.texture_loc = map.loc("texture");
    std::error_code ec;
    if (!std::filesystem::is_regular_file(object.texture, ec)) {
      throw_user_error(map.loc("texture"),
                       "texture file '{}' not found; paths are relative to the scene file's folder",
                       object.texture.string());
    }
    // Only PNG is read: check its signature now, so a wrong file is a scene error at this line.
    std::ifstream in(object.texture, std::ios::binary);
    std::array<char, 8> signature{};
    in.read(signature.data(), signature.size());
    if (!in || std::memcmp(signature.data(), "\x89PNG\r\n\x1a\n", 8) != 0) {
      throw_user_error(map.loc("texture"), "texture file '{}' is not a PNG image",
                       object.texture.string());
    }
  }
  if (map.has("render_radius")) {
    object.render_radius = map.number("render_radius", 0.0);
    require_positive(*object.render_radius, map.loc("render_radius"), map.path("render_radius"),
                     "m");
  }
  map.finish();
  return object;
}

}  // namespace dinam
