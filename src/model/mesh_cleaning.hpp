#pragma once
// What a mesh as it comes from a file gives the structure, once its vertices are welded: real
// files carry faces with a repeated corner, corners that weld together, and faces listed twice.
// None of them carries structure (a degenerate face adds no edge a neighbour lacks; a duplicate
// adds none at all), so they are dropped and counted for a warning rather than refusing the mesh.
#include <string>
#include <vector>

#include "core/types.hpp"
#include "scene/raw_mesh.hpp"

namespace dinam {

struct CleanedMesh {
  // The faces kept: vertex ids as in the mesh, consecutive corners on different welded vertices.
  std::vector<std::vector<Index>> faces;
  std::vector<Index> kept_face;  // (mesh faces) its index among the kept, or −1
  // The lines kept, with the segments whose ends welded together taken out.
  std::vector<std::vector<Index>> lines;
  std::vector<Index> kept_line;  // (mesh lines) its index among the kept, or −1

  Index degenerate_faces = 0;           // fewer than three distinct welded corners
  Index duplicate_faces = 0;            // the same welded corners as an earlier face
  Index collapsed_sides = 0;            // sides of kept faces and segments of lines of zero length
  Index degenerate_lines = 0;           // lines left with fewer than two distinct welded vertices
  Index isolated_vertices = 0;          // welded vertices on no kept face or line
  std::vector<Index> dropped_examples;  // the first few dropped faces' mesh ids

  bool changed() const {
    return degenerate_faces + duplicate_faces + collapsed_sides + degenerate_lines +
               isolated_vertices >
           0;
  }
  // "dropped 2 degenerate faces (fewer than three distinct corners), …", for a warning.
  std::string summary() const;
};

// `welded[v]` is the welded vertex of mesh vertex v.
CleanedMesh clean_mesh(const RawMesh& mesh, const std::vector<Index>& welded);

}  // namespace dinam
