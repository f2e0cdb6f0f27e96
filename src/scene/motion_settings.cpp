#include "scene/motion_settings.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string_view>

#include "core/sha256.hpp"

namespace dinam {
namespace {

// Keys read only for drawing. Keep this list short and sure: each entry must be read by no stage
// before render/ (scene_reader.cpp reads them into fields that model/ and dynamics/ never see).
constexpr std::array<std::string_view, 22> kLookOnlyKeys = {
    "name",            // the movie's file name
    "camera",          // the view
    "light",           // the sun's direction and size
    "image",           // size, quality, motion blur (a cache's instants are checked apart)
    "output",          // where frames go
    "movie",           // mp4, gif or none
    "ground.visible",  // drawn or not (contact is `ground.contact`)
    "ground.pattern",
    "ground.color",
    "ground.checker_color",
    "ground.tile",
    "ground.backdrop",
    "sky",  // its colours
    "objects[].color",
    "objects[].render_radius",
    "objects[].style",
    "objects[].joints",
    "objects[].subdivide",
    "objects[].shading",
    "objects[].sharp_angle",
    "objects[].texture",
    "objects[].finish",
};

// Keys that only say where a mesh's vertices come from and where they are placed: the hash of the
// loaded geometry (mesh_geometry_hash) holds their whole effect, so their text is left out, and
// writing a default out (`up_axis: z`, `scale: 1`) or naming another file of the same geometry
// keeps a cache. (`mesh.weld` changes the model, not the geometry, and stays.)
constexpr std::array<std::string_view, 9> kGeometryKeys = {
    "objects[].mesh.file",  "objects[].mesh.up_axis",  "objects[].mesh.scale",
    "objects[].mesh.units", "objects[].mesh.rotation", "objects[].mesh.translation",
    "objects[].mesh.fit",   "objects[].mesh.grid",     "objects[].mesh.polyline",
};

bool is_geometry_key(const std::string& pattern) {
  return std::any_of(kGeometryKeys.begin(), kGeometryKeys.end(), [&](std::string_view key) {
    return pattern.size() >= key.size() && pattern.compare(0, key.size(), key) == 0 &&
           (pattern.size() == key.size() || pattern[key.size()] == '.' ||
            pattern[key.size()] == '[');
  });
}

// "objects[3].color" → "objects[].color".
std::string key_pattern(const std::string& key) {
  std::string pattern;
  pattern.reserve(key.size());
  bool in_index = false;
  for (const char c : key) {
    if (c == '[') {
      in_index = true;
      pattern.push_back(c);
    } else if (c == ']') {
      in_index = false;
      pattern.push_back(c);
    } else if (!in_index) {
      pattern.push_back(c);
    }
  }
  return pattern;
}

void flatten(const YAML::Node& node, const std::string& key, std::vector<MotionSetting>& out) {
  if (!key.empty() && (is_look_only_key(key_pattern(key)) || is_geometry_key(key_pattern(key)))) {
    return;
  }
  switch (node.Type()) {
    case YAML::NodeType::Map:
      for (const auto& entry : node) {
        std::string child = key;
        if (!child.empty()) {
          child += '.';
        }
        child += entry.first.Scalar();
        flatten(entry.second, child, out);
      }
      break;
    case YAML::NodeType::Sequence:
      for (std::size_t i = 0; i < node.size(); ++i) {
        flatten(node[i], fmt::format("{}[{}]", key, i), out);
      }
      break;
    case YAML::NodeType::Scalar:
      out.push_back({key, node.Scalar()});
      break;
    default:  // null or undefined
      out.push_back({key, "~"});
      break;
  }
}

template <typename T>
void hash_value(Sha256& hash, const T& value) {
  hash.update(&value, sizeof(value));
}

// What model/ builds a structure from: vertex positions in world space, faces and lines; not the
// texture coordinates, which only drawing reads.
std::string mesh_geometry_hash(const RawMesh& mesh) {
  Sha256 hash;
  hash_value(hash, static_cast<std::uint64_t>(mesh.vertices.size()));
  for (const Vec3& v : mesh.vertices) {
    hash.update(v.data(), 3 * sizeof(double));
  }
  for (const auto* loops : {&mesh.faces, &mesh.lines}) {
    hash_value(hash, static_cast<std::uint64_t>(loops->size()));
    for (const std::vector<Index>& loop : *loops) {
      hash_value(hash, static_cast<std::uint64_t>(loop.size()));
      hash.update(loop.data(), loop.size() * sizeof(Index));
    }
  }
  return "sha256:" + hash.hex_digest();
}

// The track a point cache gives the pins (PinMotionDesc::track), placed, and its timing: a cache
// exported again under the same name moves the pins otherwise.
std::string pin_track_hash(const PinMotionDesc& motion) {
  Sha256 hash;
  hash_value(hash, motion.frames_per_sample);
  hash_value(hash, static_cast<std::uint64_t>(motion.track.size()));
  for (const Vec3& p : motion.track) {
    hash.update(p.data(), 3 * sizeof(double));
  }
  return "sha256:" + hash.hex_digest();
}

}  // namespace

std::vector<std::string> look_only_keys() {
  return {kLookOnlyKeys.begin(), kLookOnlyKeys.end()};
}

bool is_look_only_key(const std::string& key_pattern) {
  return std::find(kLookOnlyKeys.begin(), kLookOnlyKeys.end(), key_pattern) != kLookOnlyKeys.end();
}

std::vector<MotionSetting> motion_settings(const YAML::Node& root,
                                           const std::vector<ObjectDesc>& objects) {
  std::vector<MotionSetting> settings;
  flatten(root, "", settings);
  for (std::size_t i = 0; i < objects.size(); ++i) {
    settings.push_back(
        {fmt::format("objects[{}].mesh geometry", i), mesh_geometry_hash(objects[i].mesh)});
    if (!objects[i].pin_motion.track.empty()) {
      settings.push_back(
          {fmt::format("objects[{}].pin_motion track", i), pin_track_hash(objects[i].pin_motion)});
    }
  }
  return settings;
}

}  // namespace dinam
