#pragma once
// An object's rest mesh as Wavefront OBJ, the mesh a point cache moves: one vertex per node in
// node order (so the cache's points and the mesh's vertices match one to one), the object's faces
// as `f` with their texture coordinates (`vt`) and the mesh file's groups and materials (`g`,
// `usemtl`), and its bars on no face as `l` line elements. Blender, Houdini, Maya and 3ds Max
// import it with its loose edges.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "scene/raw_mesh.hpp"

namespace dinam {

struct Model;

struct RestMesh {
  std::string name;
  std::vector<Vec3f> vertices;              // (n_nodes) m
  std::vector<std::vector<Index>> faces;    // vertex ids, 0-based
  std::vector<std::array<Index, 2>> lines;  // vertex ids, 0-based
  // (sum of face sizes) each face corner's texture coordinates, v up as OBJ has them; empty when
  // the object's mesh has none.
  std::vector<Eigen::Vector2f> corner_uvs;
  // The mesh file's material and groups of each face: (faces) into `origins`, −1 for none; empty
  // when the file named none.
  std::vector<Index> face_origin;
  std::vector<MeshElementOrigin> origins;
};

// Object `object` of the model at its initial positions (before any settling), its vertex ids
// counted from the object's first node.
RestMesh rest_mesh(const Model& model, std::size_t object);

// Writes `mesh` as OBJ with 1-based ids; coordinates are written so that they read back as the
// same float32 values. Throws RuntimeError when the file cannot be written.
void write_obj(const std::filesystem::path& path, const RestMesh& mesh);

}  // namespace dinam
