#include "scene/mesh_loader.hpp"

#include <assimp/material.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <system_error>

namespace dinam {
namespace {

// Appends every mesh a node holds, moved by the node's transform, then recurses into its
// children. A mesh used by two nodes is added twice, as the file means.
void add_node(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent_from_node,
              RawMesh& mesh) {
  const aiMatrix4x4 world_from_node = parent_from_node * node.mTransformation;
  for (unsigned k = 0; k < node.mNumMeshes; ++k) {
    const aiMesh* ai_mesh = scene.mMeshes[node.mMeshes[k]];
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
      } else if (ids.size() >= 3) {
        mesh.faces.push_back(std::move(ids));
      }
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    add_node(scene, *node.mChildren[c], world_from_node, mesh);
  }
}

}  // namespace

RawMesh load_mesh_file(const std::filesystem::path& path, const FileLoc& where) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw_user_error(where,
                     "mesh file '{}' not found; mesh paths are relative to the folder of the scene "
                     "file",
                     path.string());
  }
  Assimp::Importer importer;
  // No post-processing at all: triangulating would add diagonals that are not edges of the
  // model, and model/ welds coincident vertices itself. Node transforms are applied below.
  const aiScene* scene = importer.ReadFile(path.string(), 0);
  if (scene == nullptr) {
    throw_user_error(where, "cannot read mesh file '{}': {}", path.string(),
                     importer.GetErrorString());
  }
  RawMesh mesh;
  // A diffuse texture named by the first material that has one, as a PNG file beside the mesh.
  for (unsigned m = 0; m < scene->mNumMaterials && mesh.texture.empty(); ++m) {
    aiString name;
    if (scene->mMaterials[m]->GetTexture(aiTextureType_DIFFUSE, 0, &name) == AI_SUCCESS &&
        name.length > 0 && name.C_Str()[0] != '*') {  // '*n' names a texture embedded in the file
      const std::filesystem::path texture = path.parent_path() / name.C_Str();
      if (std::filesystem::is_regular_file(texture, ec) && texture.extension() == ".png") {
        mesh.texture = texture;
      }
    }
  }
  if (scene->mRootNode != nullptr) {
    add_node(*scene, *scene->mRootNode, aiMatrix4x4(), mesh);
  }
  if (!mesh.has_edges()) {
    throw_user_error(where,
                     "mesh file '{}' has no edges (no faces or line elements); a structure needs "
                     "at least one bar",
                     path.string());
  }
  return mesh;
}

}  // namespace dinam
