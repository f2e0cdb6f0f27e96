#pragma once
// The flat form in which a mesh travels from the child process that imports a file with assimp
// (isolated_import.hpp) to dinam: each array as its count, then its elements as plain numbers; the
// faces and lines as each loop's length, then its ids; the origins' names zero-ended. The parent
// trusts nothing in it: a child that a malformed file has led astray may send anything.
#include <optional>
#include <string>
#include <string_view>

#include "scene/raw_mesh.hpp"

namespace dinam {

std::string encode_mesh(const RawMesh& mesh);

// The mesh, or nothing when the bytes are not one whole encoding (cut off, a count or a loop
// running past the end, a name without its end, bytes left over). Ids and values are not checked
// here: check_mesh_values does that for every mesh, however read.
std::optional<RawMesh> decode_mesh(std::string_view bytes);

}  // namespace dinam
