#pragma once
// Reads a mesh file with assimp (OBJ with line elements 'l', PLY, STL, glTF 2.0, FBX and the rest
// of what assimp knows) into a RawMesh, keeping polygons as polygons: triangulating would add
// diagonals that are not edges of the model.
#include <cstddef>
#include <filesystem>
#include <string>

#include "core/error.hpp"
#include "scene/raw_mesh.hpp"

namespace dinam {

// Node transforms inside the file (glTF, FBX) are applied, so the mesh comes back in the file's
// own space. `where` locates the scene key that named the file, for error messages.
//
// assimp reads dozens of formats, and a malformed file can crash it (fuzzing found such files);
// so the file is imported in a child process, and a crash there is a clear error about this file
// instead of the end of dinam; so is an import that runs past its time limit (60 s plus 2 s per
// megabyte of file; $DINAM_MESH_IMPORT_TIMEOUT replaces the 60), since a malformed file can also
// make assimp loop for ever. The fork costs about a millisecond per mesh file.
RawMesh load_mesh_file(const std::filesystem::path& path, const FileLoc& where);

// The same from bytes in memory, imported in this process: `extension` ("obj", "ply", "stl",
// "gltf", …) tells assimp the format. For the fuzzer's mesh target and its replay test.
RawMesh load_mesh_bytes(const void* data, std::size_t size, const std::string& extension,
                        const FileLoc& where);

}  // namespace dinam
