// The reader of an object's `mesh`: a file, a grid or a polyline, its units and placement, and
// `weld`. docs/scene-format.md documents every key read here; keep the two together.
#include <yaml-cpp/yaml.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "scene/element_readers.hpp"
#include "scene/mesh_generators.hpp"
#include "scene/mesh_loader.hpp"
#include "scene/scene_description.hpp"
#include "scene/yaml_map.hpp"

namespace dinam {
namespace {

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

// Whether a rotation in degrees looks like one in radians: every angle given is a whole multiple
// of π/12 (15°, 30°, 45°, 90° … in radians) to 0.002, none more than a turn. A turn of 1.5708°
// is never what a scene means; 90° is.
bool looks_like_radians(const Vec3& degrees) {
  constexpr double kStep = std::numbers::pi / 12.0;
  bool any = false;
  for (int c = 0; c < 3; ++c) {
    const double r = std::abs(degrees[c]);
    if (r == 0.0) {
      continue;
    }
    const double steps = std::round(r / kStep);
    if (steps == 0.0 || r > 2.0 * std::numbers::pi + 0.002 || std::abs(r - steps * kStep) > 0.002) {
      return false;
    }
    any = true;
  }
  return any;
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

// Whether a mesh looks y-up: read so, it stands on the floor (nothing below y = 0, something
// above it), and read z-up it would not (part of it below z = 0, or all of it flat in the floor
// plane z = 0, where a y-up export puts an upright sheet or a horizontal rope). A z-up mesh of a
// thing on the floor has its depth on both sides of y = 0 and its height above z = 0.
bool mesh_suggests_y_up(const RawMesh& mesh) {
  if (mesh.vertices.empty()) {
    return false;
  }
  Vec3 low = mesh.vertices.front();
  Vec3 high = low;
  for (const Vec3& v : mesh.vertices) {
    low = low.cwiseMin(v);
    high = high.cwiseMax(v);
  }
  const double tolerance = 0.02 * (high - low).maxCoeff();
  const bool stands_on_y = low.y() >= -tolerance && high.y() > tolerance;
  const bool under_z = low.z() < -tolerance;
  const bool flat_on_z0 = high.z() - low.z() <= tolerance && std::abs(low.z()) <= tolerance;
  return stands_on_y && (under_z || flat_on_z0);
}

// Why a mesh file's geometry is probably y-up as dinam receives it, or "" when nothing says so:
// glTF is y-up by its specification, assimp turns a Collada file y-up whatever its <up_axis>, and
// Blender writes OBJ files y-up unless told otherwise (Up Axis: Y is its exporter's default): an
// OBJ that Blender wrote only where the mesh looks y-up too, since a correct Up Z export (the
// add-on's) is as common.
std::string y_up_hint(const std::filesystem::path& file, const RawMesh& mesh) {
  const std::string extension = lower_extension(file);
  if (extension == ".gltf" || extension == ".glb") {
    return "glTF files are y-up by their specification (Blender's glTF export turns z-up into "
           "y-up)";
  }
  if (extension == ".dae") {
    return "assimp turns Collada files y-up whatever their <up_axis>";
  }
  if (extension == ".obj") {
    std::ifstream in(file);
    std::string line;
    for (int k = 0; k < 5 && std::getline(in, line); ++k) {
      if (line.rfind("# Blender", 0) == 0 && mesh_suggests_y_up(mesh)) {
        return "Blender wrote this OBJ file, and its OBJ export is y-up unless its Up Axis is set "
               "to Z: this mesh stands on y = 0 and lies flat or below z = 0, as a y-up one does";
      }
    }
  }
  return "";
}

// `up_axis`: the file's up direction. A y-up mesh is turned so that its +y points up (+z) and its
// +z towards the viewer of a front view (−y), the inverse of what a z-up program's y-up export
// (Blender's: Forward −Z, Up Y) did, before any other placement.
void read_up_axis(YamlMap& map, const std::filesystem::path& file, const std::string& object_name,
                  RawMesh& mesh, Placement& placement, std::vector<std::string>& warnings) {
  if (!map.has("up_axis")) {
    map.get("up_axis");  // known, absent
    if (const std::string why = file.empty() ? "" : y_up_hint(file, mesh); !why.empty()) {
      warnings.push_back(fmt::format(
          "{}: warning: object '{}': {}; if it lies on its side, add 'up_axis: y' to its mesh, "
          "or 'up_axis: z' if it is z-up already",
          map.loc("file").to_string(), object_name, why));
    }
    return;
  }
  const std::string axis = map.string("up_axis", "z");
  if (axis == "y") {
    for (Vec3& v : mesh.vertices) {
      v = Vec3(v.x(), -v.z(), v.y());
    }
    Mat3 y_up;
    y_up << 1, 0, 0, 0, 0, -1, 0, 1, 0;
    placement.then(y_up, Vec3::Zero());
  } else if (axis != "z") {
    throw_user_error(map.loc("up_axis"),
                     "'{}' must be z (the file's +z is up, as in dinam and Blender) or y (its +y "
                     "is up: glTF, and Blender's default OBJ export); got '{}'",
                     map.path("up_axis"), axis);
  }
}

}  // namespace

void read_mesh(YamlMap map, const std::filesystem::path& scene_folder, ObjectDesc& object,
               std::vector<std::string>& warnings) {
  const int sources = int{map.has("file")} + int{map.has("grid")} + int{map.has("polyline")};
  if (sources != 1) {
    throw_user_error(map.loc(),
                     "'{}' needs exactly one source: 'file' (a path read with assimp), 'grid' or "
                     "'polyline'",
                     map.name());
  }
  RawMesh& mesh = object.mesh;
  std::filesystem::path file;
  if (map.has("file")) {
    file = map.string("file", "");
    file = file.is_absolute() ? file : scene_folder / file;
    mesh = load_mesh_file(file, map.loc("file"));
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
  if (file.empty() && map.has("up_axis")) {
    throw_user_error(map.loc("up_axis"),
                     "'{}' is for mesh files; a grid or a polyline is made in dinam's z-up world",
                     map.path("up_axis"));
  }
  Placement& placement = object.placement;
  read_up_axis(map, file, object.name, mesh, placement, warnings);
  Transform transform = read_transform(map);
  if (looks_like_radians(transform.rotation_degrees)) {
    const Vec3 r = transform.rotation_degrees;
    const Vec3 meant = r * (180.0 / std::numbers::pi);
    warnings.push_back(fmt::format(
        "{}: warning: object '{}': '{}' is in degrees, so [{:g}, {:g}, {:g}] turns it by at most "
        "{:g}°; if these are radians, write [{:g}, {:g}, {:g}]",
        map.loc("rotation").to_string(), object.name, map.path("rotation"), r.x(), r.y(), r.z(),
        r.cwiseAbs().maxCoeff(), std::round(meant.x()), std::round(meant.y()),
        std::round(meant.z())));
  }
  transform.scale *= read_units(map, mesh);
  if (map.has("fit")) {
    YamlMap fit(map.get("fit"), map.file(), map.path("fit"));
    const double size = fit.required_number("size");
    require_in_range(size, 1e-6, 1e5, fit.loc("size"), fit.path("size"), "m");
    fit.finish();
    const Vec3 translation = transform.translation;
    transform.translation.setZero();
    apply_transform(transform, mesh);
    const Placement fitted = fit_to_size(size, mesh);
    apply_transform({Vec3::Ones(), Vec3::Zero(), translation}, mesh);
    placement.then(transform.rotation() * transform.scale.asDiagonal(), Vec3::Zero());
    placement.then(fitted.linear, fitted.offset);
    placement.then(Mat3::Identity(), translation);
  } else {
    apply_transform(transform, mesh);
    placement.then(transform.rotation() * transform.scale.asDiagonal(), transform.translation);
  }
  read_weld(map, object);
  map.finish();
  object.mesh_source = map.has("file") ? fmt::format("mesh file '{}'", map.string("file", ""))
                                       : std::string("the generated mesh");
  check_mesh_values(mesh, map.has("file") ? map.loc("file") : map.loc(), object.mesh_source);
}

}  // namespace dinam
