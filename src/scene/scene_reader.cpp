// One reader per scene element; each takes a YamlMap, reads every key it knows and finishes the
// map, so an unknown key is reported where it stands. docs/scene-format.md documents every key
// read here; keep the two together.
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>
#include <system_error>

#include "core/sha256.hpp"
#include "scene/mesh_generators.hpp"
#include "scene/mesh_loader.hpp"
#include "scene/motion_settings.hpp"
#include "scene/scene_description.hpp"
#include "scene/yaml_map.hpp"

namespace dinam {
namespace {

constexpr int kSceneVersion = 1;
constexpr double kPi = std::numbers::pi;

NodeSelection read_nodes(YamlMap map, std::size_t vertex_count);

void require_positive(double value, const FileLoc& loc, const std::string& what, const char* unit) {
  if (!(value > 0.0)) {
    throw_user_error(loc, "'{}' must be greater than zero ({}), got {}", what, unit, value);
  }
}

// A material value within the range docs/scene-format.md gives: beyond it no real material lies,
// and the masses, stiffnesses and the stable step derived from it leave double precision.
void require_in_range(double value, double low, double high, const FileLoc& loc,
                      const std::string& what, const char* unit) {
  if (!(value >= low && value <= high)) {
    throw_user_error(loc, "'{}' must be between {:g} and {:g} {}, got {:g}", what, low, high, unit,
                     value);
  }
}

CameraDesc read_camera(const YAML::Node& node, const std::string& file) {
  CameraDesc camera;
  camera.loc = loc_of(node, file);
  if (node.IsScalar() && node.Scalar() == "auto") {
    camera.mode = CameraDesc::Mode::kAuto;
    return camera;
  }
  YamlMap map(node, file, "camera");
  const bool has_view = map.has("position") || map.has("look_at");
  camera.position = map.vec3("position", camera.position);
  camera.look_at = map.vec3("look_at", camera.look_at);
  camera.up = map.vec3("up", camera.up);
  camera.fov_degrees = map.number("fov", camera.fov_degrees);
  camera.follow = map.string("follow", "");
  const bool automatic = map.boolean("auto", false);
  if (!camera.follow.empty()) {
    camera.mode = CameraDesc::Mode::kFollow;
    camera.offset = has_view ? Vec3(camera.position - camera.look_at) : camera.offset;
    camera.offset = map.vec3("offset", camera.offset);
  } else if (automatic || !has_view) {
    camera.mode = CameraDesc::Mode::kAuto;
    camera.direction = has_view ? Vec3(camera.look_at - camera.position) : camera.direction;
    camera.direction = map.vec3("direction", camera.direction);
  } else {
    camera.mode = CameraDesc::Mode::kFixed;
  }
  map.finish();
  const Vec3 view = camera.mode == CameraDesc::Mode::kFixed ? Vec3(camera.look_at - camera.position)
                    : camera.mode == CameraDesc::Mode::kAuto ? camera.direction
                                                             : Vec3(-camera.offset);
  if (view.norm() < 1e-9) {
    throw_user_error(map.loc(),
                     "'camera': the line of sight is zero (look_at equals position, or "
                     "a zero direction or offset)");
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
  ground.loc = map.loc();
  if (map.has("height") && map.has("point")) {
    throw_user_error(map.loc(), "'ground': give 'height' or 'point', not both");
  }
  ground.point =
      map.has("point") ? map.vec3("point", ground.point) : Vec3(0, 0, map.number("height", 0.0));
  ground.normal = map.vec3("normal", ground.normal);
  if (ground.normal.norm() < 1e-9) {
    throw_user_error(map.loc("normal"), "'ground.normal' must be a non-zero direction");
  }
  ground.normal.normalize();
  ground.visible = map.boolean("visible", ground.visible);
  const std::string pattern = map.string("pattern", "checker");
  if (pattern != "checker" && pattern != "plain") {
    throw_user_error(map.loc("pattern"), "'ground.pattern' must be checker or plain; got '{}'",
                     pattern);
  }
  ground.checker = pattern == "checker";
  ground.contact = map.boolean("contact", ground.contact);
  if (const YAML::Node stiffness = map.get("stiffness");
      stiffness && !(stiffness.IsScalar() && stiffness.Scalar() == "auto")) {
    ground.stiffness = as_double(stiffness, map.file(), "ground.stiffness");
    require_positive(*ground.stiffness, map.loc("stiffness"), "ground.stiffness", "N/m");
  }
  ground.damping_ratio = map.number("damping_ratio", ground.damping_ratio);
  if (ground.damping_ratio < 0.0 || ground.damping_ratio > 1.0) {
    throw_user_error(map.loc("damping_ratio"), "'ground.damping_ratio' must be between 0 and 1");
  }
  if (map.has("friction")) {
    YamlMap friction(map.get("friction"), map.file(), "ground.friction");
    ground.stick = friction.boolean("stick", false);
    ground.static_friction = friction.number("static", ground.static_friction);
    ground.kinetic_friction =
        friction.number("kinetic", std::min(ground.kinetic_friction, ground.static_friction));
    if (ground.static_friction < 0.0 || ground.kinetic_friction < 0.0) {
      throw_user_error(friction.loc(), "friction coefficients cannot be negative");
    }
    if (ground.kinetic_friction > ground.static_friction) {
      throw_user_error(friction.loc("kinetic"),
                       "'ground.friction.kinetic' ({}) must not exceed 'static' ({})",
                       ground.kinetic_friction, ground.static_friction);
    }
    friction.finish();
  }
  map.finish();
  return ground;
}

TimeProfile read_profile(YamlMap map) {
  TimeProfile profile;
  const std::string kind = map.string("type", "constant");
  if (kind == "constant") {
    profile.kind = TimeProfile::Kind::kConstant;
  } else if (kind == "step") {
    profile.kind = TimeProfile::Kind::kStep;
    profile.start = map.number("start", 0.0);
  } else if (kind == "ramp") {
    profile.kind = TimeProfile::Kind::kRamp;
    profile.start = map.number("start", 0.0);
    profile.end = map.required_number("end");
    if (!(profile.end > profile.start)) {
      throw_user_error(map.loc("end"), "'{}' must be later than 'start'", map.path("end"));
    }
  } else if (kind == "sine") {
    profile.kind = TimeProfile::Kind::kSine;
    profile.start = map.number("start", 0.0);
    profile.frequency = map.required_number("frequency");
    require_positive(profile.frequency, map.loc("frequency"), map.path("frequency"), "Hz");
    profile.phase = map.number("phase", 0.0) * kPi / 180.0;
  } else {
    throw_user_error(map.loc("type"), "'{}' must be constant, step, ramp or sine; got '{}'",
                     map.path("type"), kind);
  }
  map.finish();
  return profile;
}

WindDesc read_wind(YamlMap map) {
  WindDesc wind;
  wind.enabled = true;
  wind.velocity = map.required_vec3("velocity");
  if (map.has("gust")) {
    YamlMap gust(map.get("gust"), map.file(), "wind.gust");
    wind.gust_amplitude = gust.required_number("amplitude");
    wind.gust_period = gust.number("period", wind.gust_period);
    require_positive(wind.gust_period, gust.loc("period"), "wind.gust.period", "s");
    gust.finish();
  }
  if (map.has("turbulence")) {
    YamlMap turbulence(map.get("turbulence"), map.file(), "wind.turbulence");
    wind.turbulence = turbulence.required_number("amplitude");
    wind.turbulence_scale = turbulence.number("scale", wind.turbulence_scale);
    require_positive(wind.turbulence_scale, turbulence.loc("scale"), "wind.turbulence.scale", "m");
    const int seed = turbulence.integer("seed", 1);
    wind.seed = static_cast<std::uint32_t>(seed);
    turbulence.finish();
  }
  wind.air_density = map.number("air_density", wind.air_density);
  require_positive(wind.air_density, map.loc("air_density"), "wind.air_density", "kg/m³");
  wind.face_drag = map.number("face_drag", wind.face_drag);
  wind.bar_drag = map.number("bar_drag", wind.bar_drag);
  if (wind.face_drag < 0.0 || wind.bar_drag < 0.0) {
    throw_user_error(map.loc(), "'wind': drag coefficients cannot be negative");
  }
  if (const YAML::Node objects = map.get("objects"); objects) {
    if (!objects.IsSequence()) {
      throw_user_error(map.loc("objects"), "'wind.objects' must be a list of object names");
    }
    for (std::size_t i = 0; i < objects.size(); ++i) {
      wind.objects.push_back(as_string(objects[i], map.file(), "wind.objects"));
    }
  }
  map.finish();
  return wind;
}

const ObjectDesc* find_object(const std::vector<ObjectDesc>& objects, const std::string& name) {
  for (const ObjectDesc& object : objects) {
    if (object.name == name) {
      return &object;
    }
  }
  return nullptr;
}

FieldForceDesc read_field(YamlMap map, const std::vector<ObjectDesc>& objects) {
  FieldForceDesc field;
  field.loc = map.loc();
  if (map.has("acceleration") == map.has("force")) {
    throw_user_error(map.loc(),
                     "'{}' needs 'acceleration' (m/s², per unit mass) or 'force' (N, on each "
                     "node), not both",
                     map.name());
  }
  field.per_unit_mass = map.has("acceleration");
  field.value =
      field.per_unit_mass ? map.required_vec3("acceleration") : map.required_vec3("force");
  field.object = map.string("object", "");
  const ObjectDesc* object = nullptr;
  if (!field.object.empty()) {
    object = find_object(objects, field.object);
    if (object == nullptr) {
      throw_user_error(map.loc("object"), "'{}': there is no object named '{}'", map.path("object"),
                       field.object);
    }
  }
  if (map.has("nodes")) {
    if (object == nullptr) {
      throw_user_error(map.loc("nodes"), "'{}' needs 'object': node ids belong to one object",
                       map.path("nodes"));
    }
    field.nodes = read_nodes(YamlMap(map.get("nodes"), map.file(), map.path("nodes")),
                             object->mesh.vertices.size());
  }
  if (map.has("profile")) {
    field.profile = read_profile(YamlMap(map.get("profile"), map.file(), map.path("profile")));
  }
  map.finish();
  return field;
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
  check_mesh_values(mesh, map.has("file") ? map.loc("file") : map.loc(),
                    map.has("file") ? fmt::format("mesh file '{}'", map.string("file", ""))
                                    : std::string("the generated mesh"));
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

NodeSelection read_nodes(YamlMap map, std::size_t vertex_count) {
  NodeSelection pins;
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
  object.mesh =
      read_mesh(YamlMap(map.required("mesh"), map.file(), map.path("mesh")), scene_folder);
  object.material =
      read_material(YamlMap(map.required("material"), map.file(), map.path("material")));
  if (map.has("pinned")) {
    object.pins = read_nodes(YamlMap(map.get("pinned"), map.file(), map.path("pinned")),
                             object.mesh.vertices.size());
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
  const std::string pairs = map.string("bending_pairs", "collinear");
  if (pairs == "collinear") {
    object.bending_pairs = BendingPairs::kMostCollinear;
  } else if (pairs == "all") {
    object.bending_pairs = BendingPairs::kAll;
  } else if (pairs == "none") {
    object.bending_pairs = BendingPairs::kNone;
  } else {
    throw_user_error(map.loc("bending_pairs"), "'{}' must be collinear, all or none; got '{}'",
                     map.path("bending_pairs"), pairs);
  }
  object.torsion = map.boolean("torsion", object.torsion);
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
  if (map.has("damping")) {
    YamlMap damping(map.get("damping"), file, "damping");
    scene.global_damping = damping.number("global", 0.0);
    if (scene.global_damping < 0.0) {
      throw_user_error(damping.loc("global"), "'damping.global' cannot be negative (1/s)");
    }
    damping.finish();
  }
  if (map.has("settle")) {
    YamlMap settle(map.get("settle"), file, "settle");
    scene.settle.loc = settle.loc();
    scene.settle.duration = settle.required_number("duration");
    require_positive(scene.settle.duration, settle.loc("duration"), "settle.duration", "s");
    settle.finish();
  }

  if (map.has("ground")) {
    scene.ground = read_ground(YamlMap(map.get("ground"), file, "ground"));
  }
  if (map.has("camera")) {
    scene.camera = read_camera(map.get("camera"), file);
  }
  if (map.has("image")) {
    YamlMap image(map.get("image"), file, "image");
    scene.image_width = image.integer("width", scene.image_width);
    scene.image_height = image.integer("height", scene.image_height);
    scene.quality.samples = image.integer("samples", scene.quality.samples);
    if (scene.quality.samples < 1 || scene.quality.samples > 16) {
      throw_user_error(image.loc("samples"), "'image.samples' must be between 1 and 16, got {}",
                       scene.quality.samples);
    }
    scene.quality.shadows = image.boolean("shadows", scene.quality.shadows);
    scene.quality.shadow_resolution =
        image.integer("shadow_resolution", scene.quality.shadow_resolution);
    if (scene.quality.shadow_resolution < 64 || scene.quality.shadow_resolution > 8192) {
      throw_user_error(image.loc("shadow_resolution"),
                       "'image.shadow_resolution' must be between 64 and 8192, got {}",
                       scene.quality.shadow_resolution);
    }
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
  const std::string movie = map.string("movie", "mp4");
  if (movie == "mp4") {
    scene.movie = MovieFormat::kMp4;
  } else if (movie == "gif") {
    scene.movie = MovieFormat::kGif;
  } else if (movie == "none") {
    scene.movie = MovieFormat::kNone;
  } else {
    throw_user_error(map.loc("movie"), "'movie' must be mp4, gif or none; got '{}'", movie);
  }
  if (map.has("light")) {
    YamlMap light(map.get("light"), file, "light");
    scene.light_direction = light.required_vec3("direction");
    if (scene.light_direction.norm() < 1e-9) {
      throw_user_error(light.loc("direction"), "'light.direction' must be a non-zero direction");
    }
    light.finish();
  }

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
  if (const YAML::Node fields = map.get("forces"); fields) {
    if (!fields.IsSequence()) {
      throw_user_error(map.loc("forces"), "'forces' must be a list of field forces");
    }
    for (std::size_t i = 0; i < fields.size(); ++i) {
      scene.fields.push_back(
          read_field(YamlMap(fields[i], file, fmt::format("forces[{}]", i)), scene.objects));
    }
  }
  if (scene.camera.mode == CameraDesc::Mode::kFollow &&
      find_object(scene.objects, scene.camera.follow) == nullptr) {
    throw_user_error(scene.camera.loc, "'camera.follow' names '{}', which is no object",
                     scene.camera.follow);
  }
  if (map.has("wind")) {
    scene.wind = read_wind(YamlMap(map.get("wind"), file, "wind"));
    for (const std::string& name : scene.wind.objects) {
      if (find_object(scene.objects, name) == nullptr) {
        throw_user_error(map.loc("wind"), "'wind.objects' names '{}', which is no object", name);
      }
    }
  }
  map.finish();
  return scene;
}

}  // namespace

double TimeProfile::operator()(double t) const {
  switch (kind) {
    case Kind::kConstant:
      return 1.0;
    case Kind::kStep:
      return t >= start ? 1.0 : 0.0;
    case Kind::kRamp:
      return std::clamp((t - start) / (end - start), 0.0, 1.0);
    case Kind::kSine:
      return t >= start ? std::sin(2.0 * kPi * frequency * (t - start) + phase) : 0.0;
  }
  return 1.0;
}

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
  check_no_duplicate_keys(root, source.string());
  SceneDescription scene = read_root(root, source);
  scene.source_sha256 = sha256_hex(text);
  scene.motion_settings = motion_settings(root, scene.objects);
  return scene;
}

SceneDescription read_scene(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw UserError(FileLoc{path.string()}, "this is a folder, not a scene file (YAML)");
  }
  if (!std::filesystem::exists(path, ec)) {
    throw UserError(FileLoc{path.string()}, "there is no such scene file");
  }
  std::ifstream in(path);
  if (!in) {
    throw UserError(FileLoc{path.string()},
                    fmt::format("cannot open the scene file: {}", std::strerror(errno)));
  }
  std::stringstream text;
  text << in.rdbuf();
  return read_scene_text(text.str(), path);
}

}  // namespace dinam
