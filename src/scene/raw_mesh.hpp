#pragma once
// A mesh as read from a file or made by a generator, before it becomes a structure: vertices,
// closed polygon faces and open polylines. Vertices are not yet welded, so a triangle soup may
// hold the same point many times; model/ welds them and extracts the unique edges.
#include <filesystem>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"

namespace dinam {

struct RawMesh {
  std::vector<Vec3> vertices;             // (n_vertices), metres, in world space
  std::vector<std::vector<Index>> faces;  // closed loops of vertex ids: every side is an edge
  std::vector<std::vector<Index>> lines;  // open chains of vertex ids: every segment is an edge
  std::filesystem::path texture;     // the diffuse texture a mesh file's material names, if any
  std::vector<Eigen::Vector2d> uvs;  // (n_vertices) texture coordinates, v from the top; or empty

  bool has_edges() const;
};

// Object-to-world placement, applied to a mesh as scale, then rotation, then translation.
struct Transform {
  Vec3 scale = Vec3::Ones();
  Vec3 rotation_degrees = Vec3::Zero();  // about x, then y, then z (world axes)
  Vec3 translation = Vec3::Zero();       // metres

  Mat3 rotation() const;
  Vec3 world_from_object(const Vec3& p) const;
};

void apply_transform(const Transform& transform, RawMesh& mesh);

// Throws UserError at `where` unless every face and line refers to vertices the mesh has, every
// vertex is finite and within 10⁶ m of the origin, and there are at most 50 million: a NaN in a
// file or a mesh in the wrong units is found at the mesh's line, not as a "diverged" step later.
// `what` names the mesh in the message.
void check_mesh_values(const RawMesh& mesh, const FileLoc& where, const std::string& what);

}  // namespace dinam
