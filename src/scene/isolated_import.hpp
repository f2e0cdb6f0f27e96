#pragma once
// A mesh file read by assimp in a child process. assimp reads dozens of formats, and a malformed
// file can crash it (fuzzing found such files), make it loop for ever or make it reserve memory for
// billions of vertices: in a child, each is a clear error about this file instead of the end of
// dinam. The child sends the mesh back in mesh_wire.hpp's form. The fork costs about a
// millisecond per mesh file.
#include <filesystem>

#include "core/error.hpp"
#include "scene/raw_mesh.hpp"

namespace dinam {

// The mesh of `path` in the file's own space (node transforms applied), unchecked. Throws
// UserError at `where` when assimp cannot read it, crashes, or runs past its processor time (2 s
// plus 2 s per megabyte of file; $DINAM_MESH_IMPORT_TIMEOUT replaces the 2) or, waiting without
// computing, a minute more than that on the clock; RuntimeError when the child cannot be started
// or sends what is not a mesh.
RawMesh import_in_child(const std::filesystem::path& path, const FileLoc& where);

}  // namespace dinam
