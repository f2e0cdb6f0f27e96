#pragma once
// What assimp read becomes a RawMesh: every mesh of every node, moved by the node transforms,
// polygons kept as polygons and 2-index faces as lines, each element's material and groups, the
// texture a material names and the file's unit where it states one.
#include <filesystem>

#include "scene/raw_mesh.hpp"

struct aiScene;

namespace dinam {

// The mesh a file's scene holds; a diffuse texture named by the first material that has one, as
// a PNG file in `folder` (none when `folder` is empty).
RawMesh mesh_from_scene(const aiScene& scene, const std::filesystem::path& folder);

}  // namespace dinam
