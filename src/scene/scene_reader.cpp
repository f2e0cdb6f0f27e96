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
#include <optional>
#include <set>
#include <sstream>
#include <system_error>

#include "core/sha256.hpp"
#include "scene/element_readers.hpp"
#include "scene/mesh_generators.hpp"
#include "scene/mesh_loader.hpp"
#include "scene/motion_settings.hpp"
#include "scene/scene_description.hpp"
#include "scene/yaml_map.hpp"

namespace dinam {
namespace {

constexpr int kSceneVersion = 1;

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
  const std::string backdrop = map.string("backdrop", "none");
  if (backdrop != "none" && backdrop != "cyclorama") {
    throw_user_error(map.loc("backdrop"), "'ground.backdrop' must be none or cyclorama; got '{}'",
                     backdrop);
  }
  ground.cyclorama = backdrop == "cyclorama";
  // A studio's backdrop is one colour, floor and wall: plain unless a checker is asked for.
  const std::string pattern = map.string("pattern", ground.cyclorama ? "plain" : "checker");
  if (pattern != "checker" && pattern != "plain") {
    throw_user_error(map.loc("pattern"), "'ground.pattern' must be checker or plain; got '{}'",
                     pattern);
  }
  ground.checker = pattern == "checker";
  if (map.has("color")) {
    ground.color = read_color(map, "color");
  }
  if (map.has("checker_color")) {
    ground.checker_color = read_color(map, "checker_color");
  }
  if (const YAML::Node tile = map.get("tile");
      tile && !(tile.IsScalar() && tile.Scalar() == "auto")) {
    ground.tile = as_double(tile, map.file(), "ground.tile");
    require_in_range(*ground.tile, 1e-3, 1e3, map.loc("tile"), "ground.tile", "m");
  }
  ground.contact = map.boolean("contact", ground.contact);
  if (const YAML::Node stiffness = map.get("stiffness");
      stiffness && !(stiffness.IsScalar() && stiffness.Scalar() == "auto")) {
    ground.stiffness = as_double(stiffness, map.file(), "ground.stiffness");
    ground.stiffness_loc = map.loc("stiffness");
    require_positive(*ground.stiffness, map.loc("stiffness"), "ground.stiffness", "N/m");
  }
  ground.damping_ratio = map.number("damping_ratio", ground.damping_ratio);
  if (ground.damping_ratio < 0.0 || ground.damping_ratio > 1.0) {
    throw_user_error(map.loc("damping_ratio"), "'ground.damping_ratio' must be between 0 and 1");
  }
  if (map.has("friction")) {
    read_friction(YamlMap(map.get("friction"), map.file(), "ground.friction"),
                  ground.static_friction, ground.kinetic_friction, &ground.stick);
  }
  map.finish();
  return ground;
}

}  // namespace

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
    profile.phase = map.number("phase", 0.0) * std::numbers::pi / 180.0;
  } else {
    throw_user_error(map.loc("type"), "'{}' must be constant, step, ramp or sine; got '{}'",
                     map.path("type"), kind);
  }
  map.finish();
  return profile;
}

namespace {

WindDesc read_wind(YamlMap map) {
  WindDesc wind;
  wind.enabled = true;
  wind.velocity = map.required_vec3("velocity");
  if (map.has("gust")) {
    // The optional keys asked first, so that a number given for the map names them all.
    YamlMap gust(map.get("gust"), map.file(), "wind.gust");
    wind.gust_period = gust.number("period", wind.gust_period);
    require_positive(wind.gust_period, gust.loc("period"), "wind.gust.period", "s");
    wind.gust_amplitude = gust.required_number("amplitude");
    gust.finish();
  }
  if (map.has("turbulence")) {
    YamlMap turbulence(map.get("turbulence"), map.file(), "wind.turbulence");
    wind.turbulence_scale = turbulence.number("scale", wind.turbulence_scale);
    require_positive(wind.turbulence_scale, turbulence.loc("scale"), "wind.turbulence.scale", "m");
    const int seed = turbulence.integer("seed", 1);
    wind.seed = static_cast<std::uint32_t>(seed);
    wind.turbulence = turbulence.required_number("amplitude");
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
    field.nodes =
        read_nodes(YamlMap(map.get("nodes"), map.file(), map.path("nodes")), object->mesh);
  }
  if (map.has("profile")) {
    field.profile = read_profile(YamlMap(map.get("profile"), map.file(), map.path("profile")));
  }
  map.finish();
  return field;
}

// `timestep`: `auto`, a step in seconds, or a map that aims the automatic step (`target` or
// `max_steps`, with mass scaling and edge collapse) or turns the default mass scaling off.
void read_timestep(YamlMap& map, SceneDescription& scene) {
  const YAML::Node timestep = map.get("timestep");
  scene.timestep_loc = map.loc("timestep");
  if (!timestep || (timestep.IsScalar() && timestep.Scalar() == "auto")) {
    return;
  }
  if (timestep.IsMap()) {
    YamlMap aim(timestep, map.file(), "timestep");
    StepTargetDesc& target = scene.step_target;
    target.loc = aim.loc();
    if (aim.has("target") && aim.has("max_steps")) {
      throw_user_error(aim.loc("max_steps"),
                       "'timestep' takes 'target' (a step, s) or 'max_steps', not both");
    }
    if (aim.has("target")) {
      target.target = aim.number("target", 0.0);
      require_positive(*target.target, aim.loc("target"), "timestep.target", "s");
      if (*target.target > 1.0 / scene.fps) {
        throw_user_error(aim.loc("target"),
                         "'timestep.target' {} s is longer than one frame ({} s at {} fps)",
                         *target.target, 1.0 / scene.fps, scene.fps);
      }
      target.loc = aim.loc("target");
    }
    if (aim.has("max_steps")) {
      target.max_steps = aim.number("max_steps", 0.0);
      require_in_range(*target.max_steps, 1.0, 1e12, aim.loc("max_steps"), "timestep.max_steps",
                       "steps");
      target.loc = aim.loc("max_steps");
    }
    target.max_added_mass = aim.number("max_added_mass", target.max_added_mass);
    require_in_range(target.max_added_mass, 0.0, 10.0, aim.loc("max_added_mass"),
                     "timestep.max_added_mass", "(a fraction of the mass)");
    target.mass_scaling = aim.boolean("mass_scaling", target.mass_scaling);
    if (!target.mass_scaling && (target.target || target.max_steps)) {
      throw_user_error(aim.loc("mass_scaling"),
                       "'timestep.mass_scaling: false' leaves nothing to reach a 'target' or "
                       "'max_steps' with; drop one of them");
    }
    aim.finish();
    return;
  }
  double dt = 0.0;
  if (!timestep.IsScalar() || !YAML::convert<double>::decode(timestep, dt)) {
    throw_user_error(scene.timestep_loc,
                     "'timestep' must be 'auto', a time in seconds, or a map such as "
                     "{{target: 1e-4}} or {{max_steps: 1e6}}; got '{}'",
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

SceneDescription read_root(const YAML::Node& root, const std::filesystem::path& source) {
  const std::string file = source.string();
  if (!root.IsMap()) {
    throw_user_error(loc_of(root, file),
                     "a scene is a map of keys (version, duration, objects, …), not {}: see "
                     "docs/scene-format.md",
                     root.IsSequence() ? "a list" : "'" + root.Scalar() + "'");
  }
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
  require_plain_name(scene.name, map.has("name") ? map.loc("name") : FileLoc{source.string()},
                     map.path("name"));
  if (scene.name.find_first_of("/\\") != std::string::npos) {
    throw_user_error(map.loc("name"),
                     "'name' names the movie file: it must be a non-empty name "
                     "without slashes");
  }

  scene.duration = map.required_number("duration");  // no sensible default for a movie's length
  scene.duration_loc = map.loc("duration");
  require_positive(scene.duration, map.loc("duration"), "duration", "s");
  scene.fps = map.number("fps", 24.0);
  require_positive(scene.fps, map.loc("fps"), "fps", "frames per second");
  if (scene.frame_count() < 1) {
    throw_user_error(map.loc("duration"),
                     "duration × fps must give at least one frame (got {} s at {} fps)",
                     scene.duration, scene.fps);
  }

  read_timestep(map, scene);
  scene.integrator_loc = map.loc("integrator");
  const std::string integrator = map.string("integrator", "central_difference");
  if (integrator == "implicit" || integrator == "implicit_bdf2") {
    scene.integrator = IntegratorKind::kImplicit;
    scene.implicit_scheme =
        integrator == "implicit" ? ImplicitScheme::kBackwardEuler : ImplicitScheme::kBdf2;
  } else if (integrator == "xpbd") {
    scene.integrator = IntegratorKind::kXpbd;
  } else if (integrator != "central_difference") {
    throw_user_error(scene.integrator_loc,
                     "'integrator' must be central_difference (explicit, the paper's method), "
                     "xpbd (the same with the bars held as constraints: cloth, rope and cable at "
                     "a tenth of the steps), implicit (backward Euler, steps as long as a frame) "
                     "or implicit_bdf2 (the same steps, second order, less numerical damping); "
                     "got '{}'",
                     integrator);
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
    scene.settle.enabled = true;
    scene.settle.loc = settle.loc();
    const std::string method = settle.string("method", "newton");
    if (method == "newton") {
      scene.settle.method = SettleMethod::kNewton;
    } else if (method == "relax") {
      scene.settle.method = SettleMethod::kRelax;
    } else {
      throw_user_error(settle.loc("method"), "'settle.method' must be newton or relax; got '{}'",
                       method);
    }
    scene.settle.duration = settle.number("duration", scene.settle.duration);
    scene.settle.duration_loc = settle.loc("duration");
    require_positive(scene.settle.duration, settle.loc("duration"), "settle.duration", "s");
    scene.settle.residual = settle.number("residual", scene.settle.residual);
    if (!(scene.settle.residual >= 1e-12 && scene.settle.residual <= 0.1)) {
      throw_user_error(settle.loc("residual"),
                       "'settle.residual' must be from 1e-12 to 0.1 (the largest out-of-balance "
                       "force on a node as a fraction of its weight); 1e-6 is the default");
    }
    if (settle.has("damping") && settle.string("damping", "") != "auto") {
      scene.settle.damping = settle.number("damping", 0.0);
      if (!(*scene.settle.damping >= 0.0 && *scene.settle.damping <= 1e6)) {
        throw_user_error(settle.loc("damping"),
                         "'settle.damping' must be 'auto' or from 0 to 1e6 (1/s, the viscous "
                         "damping of the first stage; 0 leaves only kinetic damping)");
      }
    }
    settle.finish();
  }

  if (map.has("ground")) {
    scene.ground = read_ground(YamlMap(map.get("ground"), file, "ground"));
  }
  if (map.has("contact")) {
    scene.contact = read_contact(YamlMap(map.get("contact"), file, "contact"));
  }
  if (map.has("sky")) {
    YamlMap sky(map.get("sky"), file, "sky");
    if (sky.has("horizon")) {
      scene.sky.horizon = read_color(sky, "horizon");
    }
    if (sky.has("zenith")) {
      scene.sky.zenith = read_color(sky, "zenith");
    }
    sky.finish();
  }
  if (map.has("camera")) {
    scene.camera = read_camera(map.get("camera"), file, scene.warnings);
  }
  if (map.has("image")) {
    read_image(YamlMap(map.get("image"), file, "image"), scene);
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
    scene.light_direction = light.vec3("direction", scene.light_direction);
    if (scene.light_direction.norm() < 1e-9) {
      throw_user_error(light.loc("direction"), "'light.direction' must be a non-zero direction");
    }
    scene.light_size_degrees = light.number("size", scene.light_size_degrees);
    if (!(scene.light_size_degrees >= 0.0 && scene.light_size_degrees <= 45.0)) {
      throw_user_error(light.loc("size"),
                       "'light.size' is the sun's apparent diameter in degrees (the real sun's is "
                       "0.53), between 0 and 45; got {}",
                       scene.light_size_degrees);
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
                                    static_cast<int>(i), folder, scene.duration * scene.fps,
                                    scene.warnings);
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
  // A colour is each object's own: at the top level it would colour nothing. (Looked for in the
  // node itself: the map's own lookup would list it among the scene's keys.)
  for (const char* key : {"color", "colour"}) {
    if (const YAML::Node misplaced = root[key]; misplaced.IsDefined()) {
      throw_user_error(loc_of(misplaced, file),
                       "'{}' is not a key of the scene: each object has its own colour, as "
                       "'color: [r, g, b]' in its entry under 'objects' (sRGB, 0 to 1)",
                       key);
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
      return t >= start ? std::sin(2.0 * std::numbers::pi * frequency * (t - start) + phase) : 0.0;
  }
  return 1.0;
}

int SceneDescription::frame_count() const {
  return static_cast<int>(std::llround(duration * fps));
}

SceneDescription read_scene_text(const std::string& text, const std::filesystem::path& source) {
  const YAML::Node root = parse_yaml(text, source);
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
