#pragma once
// Values a scene may give but that are far outside what the object makes plausible, most likely
// unit slips (millimetres given as metres): told as warnings at the key, the run goes on.
#include "scene/scene_description.hpp"

namespace dinam {

struct Model;

// Adds to model.warnings: an object whose wire radius is larger than its bars (the median bar),
// with the mass that makes it; an object read from a mesh file larger than such a thing is made
// (a sheet over 50 m across, anything else over 1 km), with its size and mass and `units`.
void note_implausible_values(const SceneDescription& scene, Model& model);

}  // namespace dinam
