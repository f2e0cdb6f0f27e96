// One reader per scene element; each takes a YamlMap, reads every key it knows and finishes the
// map, so an unknown key is reported where it stands. docs/scene-format.md documents every key
// read here; keep the two together.
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>

#include "scene/mesh_generators.hpp"
#include "scene/mesh_loader.hpp"
#include "scene/scene_description.hpp"
#include "scene/yaml_map.hpp"

namespace dinam {
namespace {

constexpr int kSceneVersion = 1;

void require_positive(double value, const FileLoc& loc, const std::string& what, const char* unit) {
  if (!(value > 0.0)) {
    throw_user_error(loc, "'{}' must be greater than zero ({}), got {}", what, unit, value);
  }
}

CameraDesc read_camera(YamlMap map) {
  CameraDesc camera;
  camera.position = map.vec3("position", camera.position);
  camera.look_at = map.vec3("look_at", camera.look_at);
  camera.up = map.vec3("up", camera.up);
  camera.fov_degrees = map.number("fov", camera.fov_degrees);
  map.finish();
  const Vec3 view = camera.look_at - camera.position;
  if (view.norm() < 1e-9) {
    throw_user_error(map.loc("look_at"), "'camera.look_at' must differ from 'camera.position'");
  }
  if (camera.up.norm() < 1e-9 || view.normalized().cross(camera.up.normalized()).norm() < 1e-6) {
    throw_user_error(map.loc("up"),
                     "'camera.up' must be a non-zero direction not parallel to the line of sight");
  }
  if (!(camera.fov_degrees > 0.0 && camera.fov_degrees < 180.0)) {
    throw_user_error(map.loc("fov"),
                     "'camera.fov' is the vertical field of view in degrees, between 0 and 180; "
                     "got {}",
                     camera.fov_degrees);
  }
  return camera;
}

GroundDesc read_ground(YamlMap map) {
  GroundDesc ground;
  ground.height = map.number("height", ground.height);
  ground.visible = map.boolean("visible", ground.visible);
  map.finish();
  return ground;
}

MaterialDesc read_material(YamlMap map) {
  MaterialDesc material;
  material.loc = map.loc();
  material.density = map.required_number("density");
  require_positive(material.density, map.loc("density"), map.path("density"), "kg/m³");
  material.youngs_modulus = map.required_number("youngs_modulus");
  require_positive(material.youngs_modulus, map.loc("youngs_modulus"), map.path("youngs_modulus"),
                   "Pa");
  // G defaults to that of an isotropic solid with Poisson's ratio 0.3: G = E / (2 (1 + ν)).
  material.shear_modulus = map.number("shear_modulus", material.youngs_modulus / 2.6);
  require_positive(material.shear_modulus, map.loc("shear_modulus"), map.path("shear_modulus"),
                   "Pa");

  const bool has_radius = map.has("radius");
  const bool has_area = map.has("area");
  if (has_radius == has_area) {
    throw_user_error(map.loc(),
                     "'{}' needs the section: either 'radius' (a circular wire, m) or 'area' (m², "
                     "with optional 'area_moment' and 'polar_moment', m⁴), not both",
                     map.name());
  }
  constexpr double kPi = std::numbers::pi;
  if (has_radius) {
    const double r = map.required_number("radius");
    require_positive(r, map.loc("radius"), map.path("radius"), "m");
    material.wire_radius = r;
    material.area = kPi * r * r;
    material.area_moment = kPi * std::pow(r, 4) / 4.0;
    material.polar_moment = kPi * std::pow(r, 4) / 2.0;
  } else {
    material.area = map.required_number("area");
    require_positive(material.area, map.loc("area"), map.path("area"), "m²");
    // Without I and J, those of the circle of the same area: I = A²/(4π), J = 2I.
    material.area_moment = map.number("area_moment", material.area * material.area / (4.0 * kPi));
    require_positive(material.area_moment, map.loc("area_moment"), map.path("area_moment"), "m⁴");
    material.polar_moment = map.number("polar_moment", 2.0 * material.area_moment);
    require_positive(material.polar_moment, map.loc("polar_moment"), map.path("polar_moment"),
                     "m⁴");
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

// Exactly one of `file`, `grid` or `polyline`, then the placement. Returns the mesh in world space.
RawMesh read_mesh(YamlMap map, const std::filesystem::path& scene_folder) {
  const int sources = int{map.has("file")} + int{map.has("grid")} + int{map.has("polyline")};
  if (sources != 1) {
    throw_user_error(map.loc(),
                     "'{}' needs exactly one source: 'file' (a path read with assimp), 'grid' or "
                     "'polyline'",
                     map.name());
  }
  RawMesh mesh;
  if (map.has("file")) {
    const std::filesystem::path file = map.string("file", "");
    mesh = load_mesh_file(file.is_absolute() ? file : scene_folder / file, map.loc("file"));
  } else if (map.has("grid")) {
    mesh = make_grid(read_grid(YamlMap(map.get("grid"), map.file(), map.path("grid"))));
  } else {
    mesh = make_polyline(
        read_polyline(YamlMap(map.get("polyline"), map.file(), map.path("polyline"))));
  }
  apply_transform(read_transform(map), mesh);
  map.finish();
  return mesh;
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

PinDesc read_pins(YamlMap map, std::size_t vertex_count) {
  PinDesc pins;
  pins.loc = map.loc();
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
                         "pinned vertex index {} is out of range: the mesh has {} vertices "
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
  object.mesh =
      read_mesh(YamlMap(map.required("mesh"), map.file(), map.path("mesh")), scene_folder);
  object.material =
      read_material(YamlMap(map.required("material"), map.file(), map.path("material")));
  if (map.has("pinned")) {
    object.pins = read_pins(YamlMap(map.get("pinned"), map.file(), map.path("pinned")),
                            object.mesh.vertices.size());
  }
  object.initial_velocity = map.vec3("initial_velocity", object.initial_velocity);
  const Vec3 color = map.vec3("color", object.color.cast<double>());
  if ((color.array() < 0.0).any() || (color.array() > 1.0).any()) {
    throw_user_error(map.loc("color"), "'{}' must be [r, g, b] with each between 0 and 1",
                     map.path("color"));
  }
  object.color = color.cast<float>();
  if (map.has("render_radius")) {
    object.render_radius = map.number("render_radius", 0.0);
    require_positive(*object.render_radius, map.loc("render_radius"), map.path("render_radius"),
                     "m");
  }
  map.finish();
  return object;
}

SceneDescription read_root(const YAML::Node& root, const std::filesystem::path& source) {
  const std::string file = source.string();
  YamlMap map(root, file, "");
  SceneDescription scene;
  scene.source = source;

  if (!map.has("version")) {
    throw_user_error(map.loc(), "the scene has no 'version' key; add 'version: {}' at the top",
                     kSceneVersion);
  }
  scene.version = map.integer("version", kSceneVersion);
  if (scene.version != kSceneVersion) {
    throw_user_error(map.loc("version"),
                     "scene version {} is not supported; this dinam reads version {}",
                     scene.version, kSceneVersion);
  }
  scene.name = map.string("name", source.stem().string());
  if (scene.name.empty() || scene.name.find_first_of("/\\") != std::string::npos) {
    throw_user_error(map.loc("name"),
                     "'name' names the movie file: it must be a non-empty name "
                     "without slashes");
  }

  scene.duration = map.required_number("duration");  // no sensible default for a movie's length
  require_positive(scene.duration, map.loc("duration"), "duration", "s");
  scene.fps = map.number("fps", 24.0);
  require_positive(scene.fps, map.loc("fps"), "fps", "frames per second");
  if (scene.frame_count() < 1) {
    throw_user_error(map.loc("duration"),
                     "duration × fps must give at least one frame (got {} s at {} fps)",
                     scene.duration, scene.fps);
  }

  const YAML::Node timestep = map.get("timestep");
  scene.timestep_loc = map.loc("timestep");
  if (timestep && !(timestep.IsScalar() && timestep.Scalar() == "auto")) {
    double dt = 0.0;
    if (!timestep.IsScalar() || !YAML::convert<double>::decode(timestep, dt)) {
      throw_user_error(scene.timestep_loc,
                       "'timestep' must be 'auto' or a time in seconds, got '{}'",
                       timestep.IsScalar() ? timestep.Scalar() : "a non-scalar");
    }
    require_positive(dt, scene.timestep_loc, "timestep", "s");
    if (dt > 1.0 / scene.fps) {
      throw_user_error(scene.timestep_loc,
                       "'timestep' {} s is longer than one frame ({} s at {} fps); use a smaller "
                       "step or 'auto'",
                       dt, 1.0 / scene.fps, scene.fps);
    }
    scene.timestep = dt;
  }
  scene.gravity = map.vec3("gravity", scene.gravity);

  if (map.has("ground")) {
    scene.ground = read_ground(YamlMap(map.get("ground"), file, "ground"));
  }
  if (map.has("camera")) {
    scene.camera = read_camera(YamlMap(map.get("camera"), file, "camera"));
  }
  if (map.has("image")) {
    YamlMap image(map.get("image"), file, "image");
    scene.image_width = image.integer("width", scene.image_width);
    scene.image_height = image.integer("height", scene.image_height);
    for (const char* key : {"width", "height"}) {
      const int n = std::string(key) == "width" ? scene.image_width : scene.image_height;
      if (n < 16 || n > 8192) {
        throw_user_error(image.loc(key), "'image.{}' must be between 16 and 8192 pixels, got {}",
                         key, n);
      }
    }
    image.finish();
  }
  scene.output = map.string("output", "out/" + scene.name);

  const YAML::Node objects = map.get("objects");
  if (!objects || !objects.IsSequence() || objects.size() == 0) {
    throw_user_error(map.loc("objects"),
                     "the scene needs 'objects': a list with at least one object");
  }
  const std::filesystem::path folder = source.parent_path();
  std::set<std::string> names;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    ObjectDesc object = read_object(YamlMap(objects[i], file, fmt::format("objects[{}]", i)),
                                    static_cast<int>(i), folder);
    if (!names.insert(object.name).second) {
      throw_user_error(object.loc, "two objects are named '{}'; names must be unique", object.name);
    }
    scene.objects.push_back(std::move(object));
  }
  map.finish();
  return scene;
}

}  // namespace

int SceneDescription::frame_count() const {
  return static_cast<int>(std::llround(duration * fps));
}

SceneDescription read_scene_text(const std::string& text, const std::filesystem::path& source) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw UserError(FileLoc{source.string(), e.mark.line + 1, e.mark.column + 1},
                    "this is not valid YAML: " + e.msg);
  }
  if (!root || root.IsNull()) {
    throw UserError(FileLoc{source.string()}, "the scene file is empty");
  }
  return read_root(root, source);
}

SceneDescription read_scene(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) {
    throw UserError(FileLoc{path.string()}, "cannot open the scene file");
  }
  std::stringstream text;
  text << in.rdbuf();
  return read_scene_text(text.str(), path);
}

}  // namespace dinam
