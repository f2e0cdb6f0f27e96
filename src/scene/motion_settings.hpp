#pragma once
// Which of a scene's settings decide its motion. A motion cache records them, and a scene is drawn
// from a cache only when its settings are the same: an edit to the look (camera, image, light,
// colours, output) keeps the cache, any other edit asks for a new simulation.
//
// The settings are every scalar of the scene file, flattened to key paths, less the keys listed as
// look-only in motion_settings.cpp, plus a hash of each object's loaded mesh geometry (so an edit
// to a mesh file counts even though the scene's text is unchanged). A key the list does not name
// counts as motion: a new key is safe by default. A key may be listed only if no stage before
// render/ reads it; tests/scene/motion_settings_test.cpp checks that each one leaves the motion
// unchanged bit for bit.
#include <yaml-cpp/yaml.h>

#include <string>
#include <string_view>
#include <vector>

#include "scene/scene_description.hpp"

namespace dinam {

// `root` is the scene file's top-level map and `objects` the objects read from it, in order.
std::vector<MotionSetting> motion_settings(const YAML::Node& root,
                                           const std::vector<ObjectDesc>& objects);

// The look-only keys, list indices written as "[]".
std::vector<std::string> look_only_keys();

// True for a key path (list indices written as "[]", e.g. "objects[].color") that only changes
// how the motion is drawn.
bool is_look_only_key(const std::string& key_pattern);

}  // namespace dinam
