#pragma once
// Contact with the ground (model.ground: each node's penalty) and between objects and within one
// (model.contact: which bars, nodes and face triangles take part, their radii and the penalty);
// the forces are dynamics/contact/ground_contact.hpp's and dynamics/contact/object_contact.hpp's.
#include "model/model.hpp"
#include "scene/scene_description.hpp"

namespace dinam {

// Call once every object, its pins and its springs are in the model.
void add_ground_contact(const SceneDescription& scene, Model& model);

// The ground of a model stepped by steps far longer than an impact: its automatic penalty's
// frequency capped at `frequency` (rad/s), each node's damper following; a stiffness the scene
// gives is kept. The implicit schemes soften their own copy of the model (ImplicitIntegrator).
void soften_ground(Model& model, double frequency);

// Call once every object, its pins and its springs are in the model, after the ground.
void add_object_contact(const SceneDescription& scene, Model& model);

}  // namespace dinam
