// The scene's `camera`: `auto`, a fixed view, one that follows an object, a path through keys, or
// an orbit (docs/scene-format.md, "camera").
#include <algorithm>
#include <cmath>

#include "scene/element_readers.hpp"

namespace dinam {
namespace {

// A field of view under this many degrees is a telescope's, and most likely radians read as
// degrees (0.785 for 45°): the frames would show a patch of ground. Allowed, with a warning.
constexpr double kNarrowestPlausibleFov = 5.0;

void require_fov(double fov, const FileLoc& loc, const std::string& what,
                 std::vector<std::string>& warnings) {
  if (!(fov > 0.0 && fov < 180.0)) {
    throw_user_error(
        loc, "'{}' is the vertical field of view in degrees, between 0 and 180; got {}", what, fov);
  }
  if (fov < kNarrowestPlausibleFov) {
    warnings.push_back(fmt::format(
        "{}: warning: '{}' is {:g}°, a telescope's view; the field of view is in degrees (45, "
        "not 0.785)",
        loc.to_string(), what, fov));
  }
}

// `keys`: a list of {time, position, look_at, fov} at increasing times.
std::vector<CameraKeyDesc> read_keys(const YAML::Node& node, const std::string& file,
                                     double default_fov, std::vector<std::string>& warnings) {
  if (!node.IsSequence() || node.size() < 1) {
    throw_user_error(loc_of(node, file),
                     "'camera.keys' must be a list of keys, each {{time, position, look_at, fov}}");
  }
  std::vector<CameraKeyDesc> keys;
  for (std::size_t k = 0; k < node.size(); ++k) {
    YamlMap map(node[k], file, fmt::format("camera.keys[{}]", k));
    CameraKeyDesc key;
    key.loc = map.loc();
    key.time = map.required_number("time");
    key.position = map.required_vec3("position");
    key.look_at = map.required_vec3("look_at");
    key.fov_degrees = map.number("fov", keys.empty() ? default_fov : keys.back().fov_degrees);
    map.finish();
    require_fov(key.fov_degrees, map.loc("fov"), map.path("fov"), warnings);
    if (!keys.empty() && !(key.time > keys.back().time)) {
      throw_user_error(map.loc("time"),
                       "'{}' is {} s, not after the previous key's {} s; list the keys in "
                       "increasing time",
                       map.path("time"), key.time, keys.back().time);
    }
    if ((key.look_at - key.position).norm() < 1e-9) {
      throw_user_error(map.loc("look_at"), "'{}' equals the key's position: the eye sees nothing",
                       map.path("look_at"));
    }
    keys.push_back(key);
  }
  return keys;
}

OrbitDesc read_orbit(YamlMap map) {
  OrbitDesc orbit;
  if (map.has("center")) {
    orbit.center = map.vec3("center", Vec3::Zero());
  }
  if (map.has("radius")) {
    orbit.radius = map.number("radius", 0.0);
    require_positive(*orbit.radius, map.loc("radius"), map.path("radius"), "m");
  }
  orbit.height_given = map.has("height");
  orbit.height = map.number("height", orbit.height);
  orbit.turns = map.number("turns", orbit.turns);
  orbit.start_degrees = map.number("start", orbit.start_degrees);
  map.finish();
  if (!std::isfinite(orbit.turns) || std::abs(orbit.turns) > 1000.0) {
    throw_user_error(map.loc("turns"), "'{}' must be a number of turns within ±1000, got {}",
                     map.path("turns"), orbit.turns);
  }
  return orbit;
}

}  // namespace

CameraDesc read_camera(const YAML::Node& node, const std::string& file,
                       std::vector<std::string>& warnings) {
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
  require_fov(camera.fov_degrees, map.loc("fov"), "camera.fov", warnings);
  camera.follow = map.string("follow", "");
  const bool automatic = map.boolean("auto", false);
  const int movers = (camera.follow.empty() ? 0 : 1) + (map.has("keys") ? 1 : 0) +
                     (map.has("orbit") ? 1 : 0) + (automatic ? 1 : 0);
  if (movers > 1) {
    throw_user_error(map.loc(),
                     "'camera' may have one of 'auto', 'follow', 'keys' and 'orbit', not several");
  }
  if (map.has("keys")) {
    camera.mode = CameraDesc::Mode::kPath;
    if (has_view) {
      throw_user_error(map.loc(map.has("position") ? "position" : "look_at"),
                       "'camera': a path gives position and look_at in each of its keys");
    }
    camera.keys = read_keys(map.get("keys"), file, camera.fov_degrees, warnings);
  } else if (map.has("orbit")) {
    camera.mode = CameraDesc::Mode::kOrbit;
    if (has_view) {
      throw_user_error(map.loc(map.has("position") ? "position" : "look_at"),
                       "'camera': an orbit places the eye itself; give its 'center', 'radius' "
                       "and 'height' instead of position and look_at");
    }
    camera.orbit = read_orbit(YamlMap(map.get("orbit"), file, "camera.orbit"));
  } else if (!camera.follow.empty()) {
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
  if (camera.up.norm() < 1e-9) {
    throw_user_error(map.loc("up"), "'camera.up' must be a non-zero direction");
  }
  const auto check_view = [&](const Vec3& view, const FileLoc& loc) {
    if (view.norm() < 1e-9) {
      throw_user_error(loc,
                       "'camera': the line of sight is zero (look_at equals position, or "
                       "a zero direction or offset)");
    }
    if (view.normalized().cross(camera.up.normalized()).norm() < 1e-6) {
      throw_user_error(loc, "'camera.up' must not be parallel to the line of sight");
    }
  };
  switch (camera.mode) {
    case CameraDesc::Mode::kFixed:
      check_view(camera.look_at - camera.position, map.loc());
      break;
    case CameraDesc::Mode::kAuto:
      check_view(camera.direction, map.loc("direction"));
      break;
    case CameraDesc::Mode::kFollow:
      check_view(-camera.offset, map.loc("offset"));
      break;
    case CameraDesc::Mode::kPath:
      for (const CameraKeyDesc& key : camera.keys) {
        check_view(key.look_at - key.position, key.loc);
      }
      break;
    case CameraDesc::Mode::kOrbit:
      break;  // the eye circles the up axis; a line of sight along it needs a zero radius
  }
  return camera;
}

}  // namespace dinam
