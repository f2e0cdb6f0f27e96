#pragma once
// `pin_motion: {point_cache: FILE}`: an object's pinned nodes follow their mesh vertices' tracks
// in a point cache (PC2 or MDD, io/point_cache.hpp) — an animated collider, a hand carrying a
// cloth — exported by the program that animates them, one point per vertex of the mesh file.
#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene_description.hpp"
#include "scene/yaml_map.hpp"

namespace dinam {

// Reads the point cache `motion` names into object.pin_motion (its samples placed as the mesh
// is, object.placement): those of the scene's `frames` (duration × fps) and the next, where the
// file holds more. Throws UserError at the key where the file is missing, broken, not of this
// mesh, or its samples would take more memory than the machine has; warns where its first sample
// is not the mesh as placed (the pins would jump at t = 0).
void read_pin_track(YamlMap& motion, const std::filesystem::path& scene_folder, double frames,
                    ObjectDesc& object, std::vector<std::string>& warnings);

}  // namespace dinam
