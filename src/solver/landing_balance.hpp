#pragma once
// Whether each free piece of a structure comes to rest where it lands, judged before the run from
// the mesh as it starts: what `info` needs to tell a structure that lands and lies still from one
// that lands and goes on moving, which costs the implicit integrator 1.7 times the solve
// iterations and three times the factorisations a step (bench/notes/implicit-integrator.md, "Pieces that
// land off balance"). A piece that no pin holds falls along gravity as it starts (its initial
// velocities aside) and lands on its lowest nodes: its base, the convex hull of those nodes seen
// along gravity. Where the line of its weight through its centre of mass passes inside the base,
// with room for the little a landing tips it by, it stands. Where it passes outside or at the
// edge, the piece tips over the edge; where the next face it tips onto is a few degrees away (a
// round base: a letter C on its back, a ring on its rim, a log on its side), it rocks and rolls
// from face to face, each landing a small impact that takes little of its motion, for seconds;
// where it is far (a box on its edge), it lands once on a face and lies still.
#include <optional>
#include <vector>

#include "core/types.hpp"

namespace dinam {

struct Model;
struct MeshPieces;

// A base's nodes: those within this share of the piece's size (its bounding box's diagonal) of
// its lowest. A flat face lies level to rounding, a round one rises by r (1 − cos Δθ) from its
// lowest node to the next, a millimetre for a letter of 6 cm radius cut in 32 sides: 1e-3 takes
// the one and not the other.
inline constexpr double kBaseTolerance = 1e-3;
// The least angle a piece must tilt by before its centre of mass passes over its base's edge for
// it to stand. A landing straight down tips it by little: a sphere cut in 2 562 nodes (assimp's
// spheres.nff), which lands on a facet it must tilt 3.7° to roll off, lands and lies still. A box
// six times taller than wide tips at 9.5°, a pencil on its end at 2°.
inline constexpr double kLeastTippingDegrees = 3.0;

// The most a piece turns over its base's edge before another of its nodes touches for its base to
// count as round: a curve of s sides turns 360°/s from side to side (11.25° for 32, 20° for 18),
// a box over its edge 90°. A piece that lands off balance on such a base rolls from side to
// side, each landing a small impact that takes little of its motion; one that tips over a corner
// onto a face lands once, and lies still.
inline constexpr double kRoundBaseDegrees = 20.0;

struct PieceLanding {
  Index node = 0;                // its lowest node
  double tipping_degrees = 0.0;  // the tilt that topples it where it lands; < 0: it tips at once
  // How far it turns over its base's edge before another of its nodes touches.
  double next_face_degrees = 0.0;
};

// How each free piece (held by no pin, of more than one node) lands on the ground, in the order of
// the nodes that name the pieces; none where there is no ground or gravity does not pull towards it.
std::vector<PieceLanding> piece_landings(const Model& model, const MeshPieces& pieces);

// Of the free pieces (held by no pin, of more than one node) that land off balance on a round
// base, and so rock or roll, the one that tips most readily; empty where none does, where there
// is no ground, or where gravity does not pull towards it. Contact between objects is not looked
// at: a piece that lands on another is judged as though it fell through to the ground.
std::optional<PieceLanding> rocking_landing(const Model& model, const MeshPieces& pieces);

}  // namespace dinam
