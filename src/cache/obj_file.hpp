#pragma once
// An object's rest mesh as Wavefront OBJ, the mesh a point cache moves: one vertex per node in
// node order (so the cache's points and the mesh's vertices match one to one), the object's faces
// as `f` and its bars on no face as `l` line elements. Blender, Houdini, Maya and 3ds Max import
// it with its loose edges.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace dinam {

struct Model;

struct RestMesh {
  std::string name;
  std::vector<Vec3f> vertices;              // (n_nodes) m
  std::vector<std::vector<Index>> faces;    // vertex ids, 0-based
  std::vector<std::array<Index, 2>> lines;  // vertex ids, 0-based
};

// Object `object` of the model at its initial positions (before any settling), its vertex ids
// counted from the object's first node.
RestMesh rest_mesh(const Model& model, std::size_t object);

// Writes `mesh` as OBJ with 1-based ids; coordinates are written so that they read back as the
// same float32 values. Throws RuntimeError when the file cannot be written.
void write_obj(const std::filesystem::path& path, const RestMesh& mesh);

}  // namespace dinam
