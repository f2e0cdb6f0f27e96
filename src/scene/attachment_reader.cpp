// The reader of an object's `attach` list: which of its nodes are tied to which other object, how
// stiffly, and where they break. The target is found by name when the model is built
// (model/tie_builder.cpp), after every object's mesh is read; docs/scene-format.md documents the
// keys read here.
#include <yaml-cpp/yaml.h>

#include "scene/element_readers.hpp"

namespace dinam {

namespace {

AttachmentDesc read_attachment(YamlMap map, const ObjectDesc& object) {
  AttachmentDesc attachment;
  attachment.loc = map.loc();
  attachment.nodes =
      read_nodes(YamlMap(map.required("nodes"), map.file(), map.path("nodes")), object.mesh);
  map.required("to");
  attachment.target = map.string("to", "");
  attachment.target_loc = map.loc("to");
  if (attachment.target == object.name) {
    throw_user_error(attachment.target_loc,
                     "'{}': object '{}' cannot be tied to itself; a seam within one object is one "
                     "mesh whose panels share their vertices",
                     map.path("to"), object.name);
  }
  if (map.has("stiffness") && map.get("stiffness").IsScalar() &&
      map.get("stiffness").Scalar() == "rigid") {
    map.string("stiffness", "rigid");  // read: it is the default
  } else if (map.has("stiffness")) {
    attachment.stiffness = map.number("stiffness", 0.0);
    require_positive(*attachment.stiffness, map.loc("stiffness"), map.path("stiffness"), "N/m");
  }
  attachment.swings = map.boolean("swing", false);
  if (map.has("break_force")) {
    attachment.break_force = map.number("break_force", 0.0);
    require_positive(attachment.break_force, map.loc("break_force"), map.path("break_force"), "N");
  }
  map.finish();
  return attachment;
}

}  // namespace

std::vector<AttachmentDesc> read_attachments(YamlMap& object_map, const ObjectDesc& object) {
  std::vector<AttachmentDesc> attachments;
  const YAML::Node list = object_map.get("attach");
  if (!list) {
    return attachments;
  }
  if (!list.IsSequence()) {
    throw_user_error(object_map.loc("attach"),
                     "'{}' must be a list of {{nodes: ..., to: OBJECT, stiffness: rigid or N/m, "
                     "break_force: N, swing: true or false}}",
                     object_map.path("attach"));
  }
  for (std::size_t i = 0; i < list.size(); ++i) {
    attachments.push_back(read_attachment(
        YamlMap(list[i], object_map.file(), fmt::format("{}[{}]", object_map.path("attach"), i)),
        object));
  }
  return attachments;
}

}  // namespace dinam
