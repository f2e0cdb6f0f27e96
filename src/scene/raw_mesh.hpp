#pragma once
// A mesh as read from a file or made by a generator, before it becomes a structure: vertices,
// closed polygon faces and open polylines. Vertices are not yet welded, so a triangle soup may
// hold the same point many times; model/ welds them and extracts the unique edges.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"

namespace dinam {

// Where in a mesh file an element came from: the name of its material and the names of the
// groups holding it (for OBJ, its `o` and `g` names; for glTF and the rest, its mesh and the nodes
// above it). A scene's `parts` choose materials by these names.
struct MeshElementOrigin {
  std::string material;             // empty when the file names none
  std::vector<std::string> groups;  // outermost first; empty names left out
};

struct RawMesh {
  std::vector<Vec3> vertices;             // (n_vertices), metres, in world space
  std::vector<std::vector<Index>> faces;  // closed loops of vertex ids: every side is an edge
  std::vector<std::vector<Index>> lines;  // open chains of vertex ids: every segment is an edge
  std::filesystem::path texture;     // the diffuse texture a mesh file's material names, if any
  std::vector<Eigen::Vector2d> uvs;  // (n_vertices) texture coordinates, v from the top; or empty
  // (n_vertices) each vertex's 0-based number in the file's own list of vertices (an OBJ's `v`
  // lines), −1 where not found; empty when the file has no such list dinam reads.
  std::vector<Index> source_vertex;
  Index source_vertex_count = 0;  // vertices in that list
  // A file's materials and groups: each face and line names its origin. Empty for generated meshes.
  std::vector<MeshElementOrigin> origins;
  std::vector<Index> face_origin;  // (n_faces) into origins, or empty
  std::vector<Index> line_origin;  // (n_lines) into origins, or empty
  // The length of the file's unit in metres where the file states it (FBX); empty otherwise.
  std::optional<double> metres_per_unit;

  bool has_edges() const;
};

// The two kinds of name a mesh file gives its elements.
enum class MeshNameKind { kMaterial, kGroup };

// The faces and lines of a mesh that carry one name.
struct MeshElementIds {
  std::vector<Index> faces;  // ids into RawMesh::faces, increasing
  std::vector<Index> lines;  // ids into RawMesh::lines, increasing

  bool empty() const { return faces.empty() && lines.empty(); }
};

// The elements whose material is `name` (kMaterial) or that any group named `name` holds (kGroup).
MeshElementIds elements_named(const RawMesh& mesh, MeshNameKind kind, const std::string& name);

// The distinct non-empty material or group names of a mesh's elements, in order of first use.
std::vector<std::string> element_names(const RawMesh& mesh, MeshNameKind kind);

// Object-to-world placement, applied to a mesh as scale, then rotation, then translation.
struct Transform {
  Vec3 scale = Vec3::Ones();
  Vec3 rotation_degrees = Vec3::Zero();  // about x, then y, then z (world axes)
  Vec3 translation = Vec3::Zero();       // metres

  Mat3 rotation() const;
  Vec3 world_from_object(const Vec3& p) const;
};

void apply_transform(const Transform& transform, RawMesh& mesh);

// An affine map p ↦ linear p + offset: how a mesh file's vertices were placed in the world (its
// up axis, units, transform and fit), kept to place what else gives positions in the file's
// coordinates the same way (a point cache its pins follow).
struct Placement {
  Mat3 linear = Mat3::Identity();
  Vec3 offset = Vec3::Zero();

  Vec3 operator()(const Vec3& p) const { return linear * p + offset; }
  // This placement followed by p ↦ a p + b.
  void then(const Mat3& a, const Vec3& b) {
    linear = a * linear;
    offset = a * offset + b;
  }
};

// Scales the mesh so that the largest side of its bounding box is `size` (m) and moves it so that
// the box's bottom centre (lowest along world z) is at the origin: a downloaded model, whatever
// its units and origin, then stands on the ground at the origin, `size` across. Returns the map it
// applied (the identity for a mesh with no extent).
Placement fit_to_size(double size, RawMesh& mesh);

// Throws UserError at `where` unless every face and line refers to vertices the mesh has, every
// vertex is finite and within 10⁶ m of the origin, and there are at most 50 million: a NaN in a
// file or a mesh in the wrong units is found at the mesh's line, not as a "diverged" step later.
// `what` names the mesh in the message.
void check_mesh_values(const RawMesh& mesh, const FileLoc& where, const std::string& what);

}  // namespace dinam
