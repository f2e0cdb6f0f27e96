#pragma once
// What an object's faces add to its bars, before the bars are built: a sheet material's
// stiffness, mass and limits spread over its faces' bars and nodes, and each face's resistance to
// shear in its plane, as springs on its corner angles (docs/scene-format.md, `material`).
//
// A sheet (SheetDesc) is orthotropic with its grain along a quad's sides: ½ S (ε_uu² + ε_vv²) +
// ½ G γ² per area, bending B per width. A face of area A and n sides gives each side of length L
// the width w = A / (n/2) / L it stands for: E A = S w, E I = G J = B w; each corner a spring
// G A / n on its angle and the mass ρ_A A / n. Exact for uniform strain of rectangles at any size.
// Two triangles that make a rectangle are that rectangle (their shared side has no stiffness);
// other triangles take w = A / L (a triangle lattice: S in every direction on an equilateral mesh,
// but the shear of its sides, 3/8 S, not G; warned). A wire material's faces of four sides or more
// get the corner springs of G = E A / (2 L_d), L_d the diagonal: what a diagonal wire would give,
// whichever diagonal; its triangles keep their bars alone; `faces: net` takes the corners away.
#include <string>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "model/mesh_cleaning.hpp"
#include "model/vertex_welding.hpp"
#include "scene/scene_description.hpp"

namespace dinam {

using Edge = std::pair<Index, Index>;  // welded ids, first < second

// An angle spring at a face's corner c between its sides c–a and c–b (welded ids).
struct CornerSpring {
  Index a = 0;
  Index c = 0;
  Index b = 0;
  double stiffness = 0.0;  // N·m/rad
};

struct FaceSprings {
  // (n_edges) the material each edge's bar is built with: its own for wires, else one of
  // `sheet_bars` (a sheet's values spread onto that bar).
  std::vector<const MaterialDesc*> edge_material;
  std::vector<MaterialDesc> sheet_bars;
  std::vector<double> vertex_mass;  // (n_welded) kg from sheet faces
  std::vector<CornerSpring> corners;
  std::vector<std::string> warnings;
};

// `edge_material` (n_edges) is each edge's material as the object and its parts give it;
// `edges` the object's unique edges, sorted.
FaceSprings face_springs(const ObjectDesc& object, const CleanedMesh& clean, const WeldResult& weld,
                         const std::vector<Edge>& edges,
                         std::vector<const MaterialDesc*> edge_material);

}  // namespace dinam
