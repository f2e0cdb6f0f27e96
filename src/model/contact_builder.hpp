#pragma once
// Contact between objects and within one: which bars, nodes and face triangles take part, their
// radii and the penalty (model.contact; the forces are dynamics/object_contact.hpp's).
#include "model/model.hpp"
#include "scene/scene_description.hpp"

namespace dinam {

// Call once every object, its pins and its springs are in the model, after the ground.
void add_object_contact(const SceneDescription& scene, Model& model);

}  // namespace dinam
