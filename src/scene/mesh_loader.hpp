#pragma once
// Reads a mesh file with assimp (OBJ with line elements 'l', PLY, STL, glTF 2.0, FBX and the rest
// of what assimp knows) into a RawMesh, keeping polygons as polygons: triangulating would add
// diagonals that are not edges of the model.
#include <filesystem>
#include <string>

#include "core/error.hpp"
#include "scene/raw_mesh.hpp"

namespace dinam {

// The file's extension in lower case (".obj").
std::string lower_extension(const std::filesystem::path& path);

// Node transforms inside the file (glTF, FBX) are applied, so the mesh comes back in the file's
// own space. `where` locates the scene key that named the file, for error messages.
// The file is imported in a child process (isolated_import.hpp), and its mesh checked
// (check_mesh_values) and required to have edges. An OBJ file's vertices get their numbers in the
// file (obj_vertex_order.hpp).
RawMesh load_mesh_file(const std::filesystem::path& path, const FileLoc& where);

}  // namespace dinam
