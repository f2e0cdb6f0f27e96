#include "scene/assimp_mesh.hpp"

#include <assimp/material.h>
#include <assimp/scene.h>

#include <cmath>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

namespace dinam {
namespace {

// The id in `mesh.origins` of elements of `material` held by `groups`, added if new.
Index origin_id(std::string material, std::vector<std::string> groups, RawMesh& mesh) {
  for (std::size_t k = 0; k < mesh.origins.size(); ++k) {
    if (mesh.origins[k].material == material && mesh.origins[k].groups == groups) {
      return static_cast<Index>(k);
    }
  }
  mesh.origins.push_back({std::move(material), std::move(groups)});
  return static_cast<Index>(mesh.origins.size() - 1);
}

// Appends every mesh a node holds, moved by the node's transform, then recurses into its
// children. A mesh used by two nodes is added twice, as the file means. `groups` holds the names
// of the nodes above this one (an OBJ file's `o` and `g` are nodes below the root).
void add_node(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent_from_node,
              std::vector<std::string> groups, RawMesh& mesh) {
  const aiMatrix4x4 world_from_node = parent_from_node * node.mTransformation;
  if (node.mName.length > 0 && node.mParent != nullptr) {  // the root is named after the file
    groups.emplace_back(node.mName.C_Str());
  }
  for (unsigned k = 0; k < node.mNumMeshes; ++k) {
    const aiMesh* ai_mesh = scene.mMeshes[node.mMeshes[k]];
    std::vector<std::string> mesh_groups = groups;
    if (ai_mesh->mName.length > 0 && (groups.empty() || groups.back() != ai_mesh->mName.C_Str())) {
      mesh_groups.emplace_back(ai_mesh->mName.C_Str());
    }
    aiString material;
    if (ai_mesh->mMaterialIndex < scene.mNumMaterials) {
      scene.mMaterials[ai_mesh->mMaterialIndex]->Get(AI_MATKEY_NAME, material);
    }
    const Index origin = origin_id(material.C_Str(), std::move(mesh_groups), mesh);
    const auto base = static_cast<Index>(mesh.vertices.size());
    for (unsigned v = 0; v < ai_mesh->mNumVertices; ++v) {
      const aiVector3D p = world_from_node * ai_mesh->mVertices[v];
      mesh.vertices.emplace_back(p.x, p.y, p.z);
      // Texture coordinates with v from the top of the picture (assimp's v runs up).
      const aiVector3D uv =
          ai_mesh->HasTextureCoords(0) ? ai_mesh->mTextureCoords[0][v] : aiVector3D(0, 0, 0);
      mesh.uvs.emplace_back(uv.x, 1.0 - uv.y);
    }
    for (unsigned f = 0; f < ai_mesh->mNumFaces; ++f) {
      const aiFace& face = ai_mesh->mFaces[f];
      std::vector<Index> ids;
      ids.reserve(face.mNumIndices);
      for (unsigned i = 0; i < face.mNumIndices; ++i) {
        ids.push_back(base + static_cast<Index>(face.mIndices[i]));
      }
      // assimp stores a line element as a 2-index face and a point as a 1-index face.
      if (ids.size() == 2) {
        mesh.lines.push_back(std::move(ids));
        mesh.line_origin.push_back(origin);
      } else if (ids.size() >= 3) {
        mesh.faces.push_back(std::move(ids));
        mesh.face_origin.push_back(origin);
      }
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    add_node(scene, *node.mChildren[c], world_from_node, groups, mesh);
  }
}

// The length of the file's unit in metres, where the file states it: FBX gives its unit in
// centimetres ("UnitScaleFactor", 1 for a file in cm, 100 for one in m), and assimp leaves the
// coordinates in that unit. glTF is in metres by definition and Collada's <unit> is applied by
// assimp itself, so neither needs a factor here; formats without units give none.
std::optional<double> metres_per_file_unit(const aiScene& scene) {
  if (scene.mMetaData == nullptr) {
    return std::nullopt;
  }
  double as_double = 0.0;
  float as_float = 0.0f;
  double centimetres = 0.0;
  if (scene.mMetaData->Get("UnitScaleFactor", as_double)) {
    centimetres = as_double;
  } else if (scene.mMetaData->Get("UnitScaleFactor", as_float)) {
    centimetres = as_float;
  }
  if (!(centimetres > 0.0) || !std::isfinite(centimetres)) {
    return std::nullopt;
  }
  return 0.01 * centimetres;
}

}  // namespace

RawMesh mesh_from_scene(const aiScene& scene, const std::filesystem::path& folder) {
  RawMesh mesh;
  std::error_code ec;
  for (unsigned m = 0; m < scene.mNumMaterials && mesh.texture.empty() && !folder.empty(); ++m) {
    aiString name;
    if (scene.mMaterials[m]->GetTexture(aiTextureType_DIFFUSE, 0, &name) == AI_SUCCESS &&
        name.length > 0 && name.C_Str()[0] != '*') {  // '*n' names a texture embedded in the file
      const std::filesystem::path texture = folder / name.C_Str();
      if (std::filesystem::is_regular_file(texture, ec) && texture.extension() == ".png") {
        mesh.texture = texture;
      }
    }
  }
  if (scene.mRootNode != nullptr) {
    add_node(scene, *scene.mRootNode, aiMatrix4x4(), {}, mesh);
  }
  // A file without texture coordinates has none, rather than (0, 0) at every vertex.
  bool any_uvs = false;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    any_uvs = any_uvs || scene.mMeshes[m]->HasTextureCoords(0);
  }
  if (!any_uvs) {
    mesh.uvs.clear();
  }
  mesh.metres_per_unit = metres_per_file_unit(scene);
  return mesh;
}

}  // namespace dinam
