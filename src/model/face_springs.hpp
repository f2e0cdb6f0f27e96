#pragma once
// What an object's faces add to its bars, before the bars are built: a sheet material's
// stiffness, mass and limits spread over the bars and nodes of its faces, and each face's
// resistance to shear in its plane, as springs on the angle at its corners.
//
// A sheet (SheetDesc) is an orthotropic membrane with the grain along a quad's sides: energy per
// area ½ S (ε_uu² + ε_vv²) + ½ G γ², and bending B per width. A face of area A and n sides gives
// each side of length L the width w = A / (n/2) / L of sheet it stands for (a rectangle's two
// sides along u share its u-stretch), so the side's bar has E A = S w, E I = B w (and G J = B w,
// the plate's twist); each corner a shear spring of stiffness G A / n on its angle (a rectangle's
// corner angles change by ±γ under shear, so four give ½ G γ² A); and each corner the mass
// ρ_A A / n. These are exact for any uniform strain of a grid of rectangles, whatever its size.
// Triangles in pairs that make a rectangle (a quad mesh triangulated) are that rectangle, their
// shared side a bar of no stiffness. Other triangles are a triangle lattice: w = A / L on each
// side gives the stretch S exactly on an equilateral mesh, in every direction, but its shear
// follows from the sides (3/8 S), not G: such a sheet is isotropic (warned).
//
// A face with a wire material (the bars have their own stiffness and mass) and four sides or more
// gets the corner springs of G = E A_bar / (2 L_d), L_d its diagonal: the shear that a diagonal bar
// of the same wire would give it, whichever diagonal a triangulation would have chosen. Its
// triangles keep their bars alone; `faces: net` takes the corner springs away.
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
  double sheet_thickness = 0.0;  // m, the thickest sheet's (0 without one)
  std::vector<std::string> warnings;
};

// `edge_material` (n_edges) is each edge's material as the object and its parts give it;
// `edges` the object's unique edges, sorted.
FaceSprings face_springs(const ObjectDesc& object, const CleanedMesh& clean, const WeldResult& weld,
                         const std::vector<Edge>& edges,
                         std::vector<const MaterialDesc*> edge_material);

}  // namespace dinam
