#pragma once
// The vertex order of an OBJ file, which its `v` lines give and which a z-up program's object has
// (Blender writes one `v` line per vertex of the mesh, in the mesh's order). assimp hands a mesh
// back with a vertex per face corner, in the order of its faces, so the file's own numbering is
// found again here by position: the model numbers its nodes in that order, and a point cache
// written in it moves the artist's own object, not only dinam's rest mesh.
#include <filesystem>
#include <vector>

#include "core/types.hpp"

namespace dinam {

// For each of `vertices` (as assimp read `file`, before any placement), the 0-based number of the
// OBJ `v` line at its position (the first such line when several share it), or −1 where none is
// within a millionth of the mesh's size. `vertex_count` receives the number of `v` lines.
std::vector<Index> obj_source_vertices(const std::filesystem::path& file,
                                       const std::vector<Vec3>& vertices, Index& vertex_count);

}  // namespace dinam
