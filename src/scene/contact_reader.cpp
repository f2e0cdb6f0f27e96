// The readers of contact: the scene's `contact` map, an object's, and the friction coefficients
// the ground shares with them. docs/scene-format.md documents every key read here.
#include <yaml-cpp/yaml.h>

#include <algorithm>

#include "scene/element_readers.hpp"

namespace dinam {

void read_friction(YamlMap map, double& static_friction, double& kinetic_friction, bool* stick) {
  if (stick != nullptr) {
    *stick = map.boolean("stick", false);
  }
  static_friction = map.number("static", static_friction);
  kinetic_friction = map.number("kinetic", std::min(kinetic_friction, static_friction));
  if (static_friction < 0.0 || kinetic_friction < 0.0) {
    throw_user_error(map.loc(), "friction coefficients cannot be negative");
  }
  if (kinetic_friction > static_friction) {
    throw_user_error(map.loc("kinetic"), "'{}' ({}) must not exceed 'static' ({})",
                     map.path("kinetic"), kinetic_friction, static_friction);
  }
  map.finish();
}

ContactDesc read_contact(YamlMap map) {
  ContactDesc contact;
  contact.loc = map.loc();
  contact.objects = map.boolean("objects", contact.objects);
  contact.self = map.boolean("self", contact.self);
  if (const YAML::Node stiffness = map.get("stiffness");
      stiffness && !(stiffness.IsScalar() && stiffness.Scalar() == "auto")) {
    contact.stiffness = as_double(stiffness, map.file(), map.path("stiffness"));
    contact.stiffness_loc = map.loc("stiffness");
    require_positive(*contact.stiffness, map.loc("stiffness"), map.path("stiffness"), "N/m");
  }
  contact.damping_ratio = map.number("damping_ratio", contact.damping_ratio);
  if (contact.damping_ratio < 0.0 || contact.damping_ratio > 1.0) {
    throw_user_error(map.loc("damping_ratio"), "'{}' must be between 0 and 1",
                     map.path("damping_ratio"));
  }
  if (map.has("friction")) {
    read_friction(YamlMap(map.get("friction"), map.file(), map.path("friction")),
                  contact.static_friction, contact.kinetic_friction);
  }
  map.finish();
  return contact;
}

ObjectContactDesc read_object_contact(YamlMap map) {
  ObjectContactDesc contact;
  if (map.has("objects")) {
    contact.objects = map.boolean("objects", false);
  }
  if (map.has("self")) {
    contact.self = map.boolean("self", false);
  }
  if (map.has("radius")) {
    contact.radius = map.number("radius", 0.0);
    contact.radius_loc = map.loc("radius");
    require_positive(*contact.radius, map.loc("radius"), map.path("radius"), "m");
  }
  if (map.has("faces")) {
    contact.faces = map.boolean("faces", true);
  }
  map.finish();
  return contact;
}

}  // namespace dinam
