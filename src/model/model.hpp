#pragma once
// The physical model: built once from a scene, then only read (`const Model&`). Everything that
// changes during a run lives in dynamics' State. Arrays are flat and indexed by element id; each
// comment gives the shape and the unit.
#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "model/mass_scaling.hpp"
#include "model/wind_load.hpp"
#include "scene/scene_description.hpp"

namespace dinam {

// The kinds of spring that stand on a bar, as Model::bar_springs encodes them (3 × id + kind).
inline constexpr Index kTornBend = 0;
inline constexpr Index kTornTorsion = 1;
inline constexpr Index kTornClamp = 2;

// What one scene object became: a contiguous range of nodes and of bars.
struct ModelObject {
  std::string name;
  Index first_node = 0;
  Index node_count = 0;
  Index first_bar = 0;
  Index bar_count = 0;
  double wire_radius = 0.0;   // m; 0 when the section was given by its area
  double section_area = 0.0;  // m²
  Vec3f color{0.8f, 0.8f, 0.8f};
  double render_radius = 0.0;     // m; 0 means "choose from the wire radius and the scene size"
  bool has_uvs = false;           // its mesh gave texture coordinates (Model::node_uv)
  Index source_vertex_count = 0;  // vertices of its mesh file's own list (node_source_vertex)
  std::vector<MeshElementOrigin> origins;  // its mesh file's materials and groups (face_origin)
};

// A field force resolved to node ids.
struct FieldForce {
  Vec3 value = Vec3::Zero();  // m/s² when per_unit_mass, else N on each node
  bool per_unit_mass = true;
  std::vector<Index> nodes;  // (n_targets)
  TimeProfile profile;
};

// Pinned nodes that follow a prescribed path: x(t) = x_0 + displacement × profile(t), or, where
// `track` holds samples, each node's own track, linear between samples `interval` apart from
// t = 0 and held at the last (dynamics/pin_motion.hpp).
struct PinMotion {
  std::vector<Index> nodes;  // (n_driven) pinned node ids
  Vec3 displacement = Vec3::Zero();
  TimeProfile profile;
  std::vector<Vec3> track;  // (n_samples × n_driven) m, or empty
  double interval = 0.0;    // s between samples
};

// The settling phase before t = 0 (SettleDesc): gravity alone, until the out-of-balance force on
// every free node is below `residual` of its weight.
struct SettlePhase {
  bool enabled = false;
  SettleMethod method = SettleMethod::kNewton;
  double duration = 0.0;          // s, the longest relaxation may take
  double residual = 0.0;          // of each node's weight
  std::optional<double> damping;  // 1/s, of relaxation's first, viscous stage; empty: automatic
  FileLoc loc;  // of the scene's `settle`, for the message when it does not converge
};

// The ground as the dynamics sees it: a rigid half-space with penalty contact and friction.
struct GroundContact {
  bool enabled = false;
  Vec3 point = Vec3::Zero();
  Vec3 normal = kWorldUp;
  std::vector<double> node_stiffness;  // (n_nodes) N/m, normal and tangential (stick) penalty
  std::vector<double> node_damping;    // (n_nodes) N·s/m, normal direction only
  // rad²/s², ω_c² of the automatic penalty (node_stiffness = m ω_c² at every node); empty where
  // the scene gives the stiffness. A stepper whose steps are far longer than an impact softens it
  // (soften_ground, contact_builder.hpp).
  std::optional<double> automatic_frequency_squared;
  double damping_ratio = 0.0;  // of the contact oscillation: node_damping = 2 ζ √(k m)
  // (n_nodes) m: where each node meets the plane, its contact radius (the largest of its bars',
  // as in contact between objects), so that a wire rests on the ground, not half in it.
  std::vector<double> node_radius;
  double static_friction = 0.5;   // μs
  double kinetic_friction = 0.4;  // μk
  bool stick = false;             // never slide

  // m, the height of node i's lowest point (x − r n) above the plane: < 0 when it touches.
  double clearance(Index i, const Vec3& x) const {
    return (x - point).dot(normal) - node_radius[i];
  }
  // The point of the plane below (or above) x: where a node touching at x is anchored.
  Vec3 foot(const Vec3& x) const { return x - (x - point).dot(normal) * normal; }
};

// Contact between objects and within one, as the dynamics sees it
// (dynamics/contact/object_contact.hpp): the bars as capsules and the faces, fanned into triangles,
// as shells, of each object's contact radius; which objects touch which; and the penalty. Empty
// when the scene asks for no contact.
struct ObjectContact {
  bool enabled = false;
  std::vector<std::uint8_t> object_between;  // (n_objects) 1: touches other objects
  std::vector<std::uint8_t> object_self;     // (n_objects) 1: touches itself
  std::vector<Index> bars;                   // bars of objects with contact, increasing
  std::vector<double> bar_radius;            // (n_bars) m, as a capsule; 0 without contact
  std::vector<Index> points;                 // nodes that meet triangles (objects with contact)
  std::vector<double> point_radius;          // (n_nodes) m: the largest of its bars'
  std::vector<Index> triangles;              // (n_triangles × 3) node ids
  std::vector<Index> triangle_face;          // (n_triangles) the face each was fanned from
  std::vector<double> triangle_radius;       // (n_triangles) m, half the shell's thickness
  // The nodes each node of the contact is joined to by a bar, increasing: pairs with a node of
  // one joined to a node of the other are neighbours in the mesh, and never touch.
  std::vector<Index> neighbour_offsets;  // (n_nodes + 1) into neighbours
  std::vector<Index> neighbours;
  double skin = 0.0;  // m: the candidate pairs are those within reach + 2 skin
  // Pairs between objects tied to each other (`attach`) that touch at the start where a tied node
  // is (a rope's end on its hook, a tie's loop around its pole): left out, as neighbours in a mesh
  // are, sorted (model/tied_contact.hpp).
  std::vector<std::array<Index, 2>> tied_bar_pairs;        // (bar, bar), the lower first
  std::vector<std::array<Index, 2>> tied_point_triangles;  // (node, triangle)

  bool tied_at_rest_bars(Index a, Index b) const {
    return std::binary_search(tied_bar_pairs.begin(), tied_bar_pairs.end(),
                              std::array<Index, 2>{std::min(a, b), std::max(a, b)});
  }
  bool tied_at_rest_point(Index node, Index triangle) const {
    return std::binary_search(tied_point_triangles.begin(), tied_point_triangles.end(),
                              std::array<Index, 2>{node, triangle});
  }
  bool joined(Index u, Index v) const {
    const auto first = neighbours.begin() + neighbour_offsets[u];
    const auto last = neighbours.begin() + neighbour_offsets[u + 1];
    return std::binary_search(first, last, v);
  }
  // Each contact's stiffness: omega_squared / (1/m_A + 1/m_B), m_X the lightest free node of
  // primitive X, so that no contact oscillates faster than √omega_squared (auto); or `stiffness`.
  double omega_squared = 0.0;  // 1/s²; 0 when the stiffness is given
  double stiffness = 0.0;      // N/m, when given
  double damping_ratio = 0.3;
  double static_friction = 0.5;   // μs
  double kinetic_friction = 0.4;  // μk
};

// Wind as the dynamics sees it: the field's parameters and what it drags on (wind_load.hpp).
struct WindLoad {
  WindDesc field;
  std::array<TurbulenceWave, 3 * kTurbulenceWaves> waves{};  // when field.turbulence ≠ 0
  std::vector<Index> faces;  // (n_wind_faces) face ids that feel pressure drag, ascending
  std::vector<Index> bars;   // (n_wind_bars) bars on no such face, which feel cross-flow drag
  // The nodes of those faces and bars, ascending, and at each the drag items that act on it:
  // node_items[node_item_offsets[k] .. node_item_offsets[k + 1]) are the positions in `faces`
  // (s) and in `bars` (faces.size() + s) of node k's faces, then its bars, each ascending. A
  // node adds its items' forces in that order, which is the order in which a serial loop over the
  // faces and then the bars would add them, whatever the thread count.
  std::vector<Index> nodes;              // (n_wind_nodes)
  std::vector<Index> node_item_offsets;  // (n_wind_nodes + 1)
  std::vector<Index> node_items;         // (Σ nodes per face + 2 n_wind_bars)
};

// A kind of spring none of which can yield keeps no yield limits (its `*_yield_*` array is empty),
// and the state keeps no plastic sets for it: for a million bars that is 16 bytes a spring.
// These read either way.
inline double yield_limit(const std::vector<double>& yield, Index i) {
  return yield.empty() ? kNoYield : yield[i];
}
inline double plastic_set_of(const std::vector<double>& plastic_set, Index i) {
  return plastic_set.empty() ? 0.0 : plastic_set[i];
}

// Attachments (`attach`): each tie holds a free node at its start offset from a point of another
// object, a fixed mix of up to three of that object's nodes (a bar's two ends or a triangle's
// corners, the point nearest the node at the start: model/tie_builder.hpp); a tie that swings, at
// its start distance from the point instead (its offset then nil).
struct Ties {
  std::vector<Index> nodes;         // (n_ties × 4) the tied node, then the point's three nodes
  std::vector<double> weights;      // (n_ties × 3) the point's weights of its nodes, summing to 1
  std::vector<Vec3> offset;         // (n_ties) m, the node's from the point at the start, or 0
  std::vector<double> rest_length;  // (n_ties) m, a swinging tie's distance at the start, or 0
  std::vector<double> stiffness;    // (n_ties) N/m, a rigid tie's as stiff as the step allows
  std::vector<std::uint8_t> rigid;  // (n_ties) 1: rigid (a constraint under `integrator: xpbd`)
  std::vector<double> break_force;  // (n_ties) N, or kNoYield
  bool can_break = false;           // some tie has a break_force

  Index count() const { return static_cast<Index>(rest_length.size()); }
};

struct Model {
  // What building it found worth telling the user, who may want to fix the input (a mesh's
  // degenerate faces, dropped): one line each, "file:line:column: warning: …" as errors read.
  std::vector<std::string> warnings;
  // The mass added so that a few short stiff bars do not set the step (`timestep`); nothing when
  // added_mass is 0. node_mass includes it.
  MassScaling mass_scaling;

  // Nodes: point masses without rotational inertia.
  std::vector<Vec3> node_initial_x;      // (n_nodes) m
  std::vector<Vec3> node_initial_v;      // (n_nodes) m/s
  std::vector<double> node_mass;         // (n_nodes) kg; half of every incident bar's mass
  std::vector<double> node_inv_mass;     // (n_nodes) 1/kg; 0 for pinned nodes, which never move
  std::vector<Index> node_object;        // (n_nodes) object id
  std::vector<Eigen::Vector2f> node_uv;  // (n_nodes) texture coordinates, for drawing only
  // (n_nodes) the node's 0-based vertex number in its object's mesh file (an OBJ's `v` lines), −1
  // where the file has no such list. Nodes of such a file are numbered in that order.
  std::vector<Index> node_source_vertex;

  // Bars: one per unique mesh edge, an axial spring k = EA/L0 and a damper between n0 and n1.
  std::vector<Index> bar_nodes;             // (n_bars × 2) n0, n1
  std::vector<double> bar_rest_length;      // (n_bars) m
  std::vector<double> bar_axial_stiffness;  // (n_bars) N/m, EA / L0
  std::vector<double> bar_yield_force;      // (n_bars, or 0 if none yields) N; ∞ when elastic
  std::vector<double> bar_damping;  // (n_bars; 0 without dampers) N·s/m, on the axial velocity
  bool any_bar_damping = false;     // some bar_damping is not 0
  std::vector<double> bar_radius;   // (n_bars) m, of the round section of equal area
  std::vector<std::uint8_t> bar_on_face;  // (n_bars) 1 when an edge of a mesh face
  // (n_bars, or 0 unless the bars are constraints) the order their projection's sweeps take them
  // in (dynamics/bar_constraints.hpp): by colour, the bars of a colour sharing no node.
  std::vector<Index> bar_sweep_order;

  // Bending springs: at node c between bars c–a and c–b, on the angle θ between them.
  std::vector<Index> bend_nodes;          // (n_bends × 3) a, c, b
  std::vector<double> bend_rest_angle;    // (n_bends) rad, in [0, π]
  std::vector<double> bend_stiffness;     // (n_bends) N·m/rad, 2 E I / (L_ca + L_cb)
  std::vector<double> bend_yield_moment;  // (n_bends, or 0 if none yields) N·m; ∞: elastic

  // Torsion springs: on bar i–j, the dihedral angle between the planes (a, i, j) and (i, j, b)
  // of its reference neighbours i–a and j–b, weighted by the sines squared of the references'
  // angles with the bar, q_a q_b (torsion_spring.hpp).
  std::vector<Index> torsion_nodes;          // (n_torsions × 4) a, i, j, b
  std::vector<double> torsion_rest_angle;    // (n_torsions) rad, in (−π, π]
  std::vector<double> torsion_stiffness;     // (n_torsions) N·m/rad, G J / (L0 q_a0 q_b0)
  std::vector<double> torsion_yield_moment;  // (n_torsions, or 0 if none yields) N·m
  Index bars_without_torsion = 0;            // bars with no usable reference neighbours

  // Clamps: at a clamped pinned node c, each bar c–a to a free node a keeps its rest direction, as
  // a beam built in there: a bending spring on the angle at c between c–a and the fixed ghost
  // point g = c + (c₀ − a₀) (the bar continued straight through the support), rest angle π,
  // k = 2 E I / L_ca. With the tributary half-length of beam a clamped end has, this is the
  // ghost-node condition of the beam equation (w₋₁ = w₁), which converges at second order.
  std::vector<Index> clamp_nodes;          // (n_clamps × 2) c, a
  std::vector<Vec3> clamp_ghost_offset;    // (n_clamps) m, g − c
  std::vector<double> clamp_stiffness;     // (n_clamps) N·m/rad
  std::vector<double> clamp_yield_moment;  // (n_clamps, or 0 if none yields) N·m; ∞: elastic

  // Tearing (model/tearing.cpp), empty when no material can break: a bar breaks for good once its
  // strain or tension reaches its limit, and every spring standing on it goes with it, as does
  // every face it is an edge of.
  std::vector<double> bar_breaking_strain;  // (n_bars) infinite when it cannot break
  std::vector<double> bar_breaking_force;   // (n_bars) N; infinite when it cannot break
  std::vector<Index> bar_spring_offsets;    // (n_bars + 1) into bar_springs
  std::vector<Index> bar_springs;           // 3 × id + kind (kTornBend, kTornTorsion, kTornClamp)
  std::vector<Index> bar_face_offsets;      // (n_bars + 1) into bar_faces
  std::vector<Index> bar_faces;             // face ids
  bool can_tear() const { return !bar_breaking_strain.empty(); }

  // Mesh faces as loops of node ids (for drawing surfaces and for wind later):
  // face k has nodes face_nodes[face_offsets[k] .. face_offsets[k + 1]).
  std::vector<Index> face_offsets;  // (n_faces + 1)
  std::vector<Index> face_nodes;    // (sum of face sizes)
  // (sum of face sizes, or 0 when no object has texture coordinates) each corner's, v from the
  // top; zeros in objects without. A node on a texture seam has a different one in each face.
  std::vector<Eigen::Vector2f> face_uv;
  std::vector<Index> face_origin;  // (n_faces) into its object's `origins`, or −1

  // Whether some spring of each kind can flow plastically (else its yield array is empty).
  bool bars_yield = false;
  bool bends_yield = false;
  bool torsions_yield = false;
  bool clamps_yield = false;

  std::vector<ModelObject> objects;
  Vec3 gravity = Vec3::Zero();  // m/s²
  double global_damping = 0.0;  // 1/s: every free node feels −α m v
  IntegratorKind integrator = IntegratorKind::kCentralDifference;
  ImplicitScheme implicit_scheme = ImplicitScheme::kBackwardEuler;
  std::vector<FieldForce> fields;
  std::vector<PinMotion> pin_motions;
  SettlePhase settle;
  WindLoad wind;
  GroundContact ground;
  ObjectContact contact;
  Ties ties;

  Index node_count() const { return static_cast<Index>(node_mass.size()); }
  Index bar_count() const { return static_cast<Index>(bar_rest_length.size()); }
  Index bend_count() const { return static_cast<Index>(bend_rest_angle.size()); }
  Index torsion_count() const { return static_cast<Index>(torsion_rest_angle.size()); }
  Index clamp_count() const { return static_cast<Index>(clamp_stiffness.size()); }
  Index face_count() const { return static_cast<Index>(face_offsets.size()) - 1; }
  bool pinned(Index node) const { return node_inv_mass[node] == 0.0; }
  // Whether the bars are held as constraints (`integrator: xpbd`, dynamics/bar_constraints.hpp)
  // rather than by their axial springs: then they bound no step.
  bool bars_are_constraints() const { return integrator == IntegratorKind::kXpbd; }
  double total_mass() const;
};

// Builds the model: welds coincident vertices of each object, turns every unique edge into a bar
// and lumps the bar masses onto the nodes. Throws UserError for a zero-length bar or a pinned
// vertex that is on no edge, naming the object and its mesh key.
Model build_model(const SceneDescription& scene);

}  // namespace dinam
