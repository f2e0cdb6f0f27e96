#pragma once
// Contact between objects and within one (dynamics/contact/object_contact.hpp) inside an implicit
// step, as potentials of the positions that Newton's method minimises with the rest.
//
// Normal: the penalty's energy E_p(δ) summed over the pairs of primitives touching at the
// iterate, δ their penetration, found again at every iterate (a pair that comes within reach
// during the step pushes from that iterate on). The sum must be continuous with a continuous
// gradient, or Newton's line search stalls where the pairs change; so, unlike central
// differences' contact:
//  - every pair of primitives is its own contact: merging those that name the same features
//    (contact_pairs.hpp) made a node that moves off a vertex by a rounding error go from one
//    contact to two;
//  - two bars' pair is weighed by IPC's mollifier m(|e_A × e_B|²) (Li et al. 2020), 0 for
//    parallel bars and 1 from 1.8° apart, since the closest points of parallel segments are not
//    unique, and a wire lying along another rested on a kink of the energy, which no Newton step
//    gets off; instead each end of either bar is pushed off the other bar (a node–bar pair, its
//    distance smooth), which holds parallel wires apart.
// A node over a vertex or an edge, or a bar's end on another bar, is therefore pushed by each
// primitive there, and sinks less under a load (the penalty's sag, micrometres, divided by their
// number); friction, μ times each pair's own push, is the same in sum. A node is pushed off a
// triangle on the side it is on: central differences remember the side a node came from, for a
// node that crosses a shell's middle within a step beyond their speed envelope, but here no step
// may pass the envelope (below), and a side remembered from the step's start flipped for a node
// that came round a triangle's edge, which made its energy jump by a whole reach's penalty (the
// draped chair's cloth at 0.39 s). The contact's damper is not used: a pair rebounds with its
// damping ratio's restitution instead (rebound_pairs).
//
// Friction, lagged: the pairs touching at x_n, with their closest points' weights w_j and normal
// n at x_n, each hold by a stick spring on the pair's tangential motion within the step,
//   u = u_0 + P Σ w_j (x_j − x_n,j),   P = I − n nᵀ,
// u_0 the stretch carried from the steps before, up to the cap μ N (N the pair's push at x_n; μs
// while it sticks, μk while it slides) beyond which it slides at the cap: the ground's capped
// quadratic (capped_stick_spring.hpp), convex and once differentiable. A pair that first touches
// within a step holds by friction from the next step on. After the step each pair's stretch is
// kept for the next, at most its cap's reach, in the state (ObjectContactWorkspace::previous).
//
// No step may carry a node of the contact further than half the smallest contact radius: two
// primitives then close by less than the smaller radius within a step, central differences'
// speed envelope, within which none passes through another. A step that would is split (first
// from its prediction x̂, before any solve, then from its solution), whatever its depth: a body
// in contact moves a few millimetres a step, where the ground lets it move centimetres. `info`
// does not know how fast bodies will move: it counts a fall through the scene's height
// (contact_envelope_steps).
#include <Eigen/SparseCore>
#include <array>
#include <cstdint>
#include <vector>

#include "core/types.hpp"
#include "dynamics/state.hpp"

namespace dinam {

struct Model;
struct FreeDofs;

// The largest distance a node of the contact may move in a step, m: half the smallest contact
// radius (infinite without contact between objects).
double contact_envelope(const Model& model);

// The most steps the speed envelope may split a run of `duration` into: every node of the contact
// at the speed of a fall through the model's height along gravity, on top of its fastest initial
// speed, for the whole run. An estimate from above: a body falls that fast only at the end of its
// fall (the paper's ball in the trampoline's net, 4 s: 17 668 estimated, 5 844 taken).
double contact_envelope_steps(const Model& model, double duration);

class ImplicitObjectContact {
 public:
  // The pairs touching at state.x (x_n) and their friction springs, from the history.
  void start_step(const Model& model, State& state);

  // The normal penalty's and the friction's forces at state.x, added to state.force.
  void add_forces(const Model& model, State& state);
  // Their energy at state.x, J.
  double energy(const Model& model, State& state);
  // The friction springs' share of it at x, J.
  double friction_energy(const std::vector<Vec3>& x) const;
  // Their energy at x_n, the step's start (the pairs touching there, the friction springs as they
  // are now), J: the energy ledger's, without moving the state back.
  double energy_at_start(const Model& model) const;
  // A positive semi-definite approximation of their Hessian at state.x, for the preconditioner:
  // each touching pair's penalty slope along its normal, w_i w_j k n nᵀ, and each friction
  // spring's exact Hessian; 3 × 3 blocks over each pair's nodes.
  void add_hessian(const Model& model, State& state, const FreeDofs& dofs,
                   std::vector<Eigen::Triplet<double>>& triplets);

  // The longest move of a node of the contact between x_n and `x`, m.
  double longest_move(const Model& model, const std::vector<Vec3>& x) const;

  // True where the pairs touching at state.x (a step's solution) differ from those at x_n: a step
  // with an impact, whose jump in acceleration is no error a shorter step would remove.
  bool touching_changed(const Model& model, State& state);
  // After an accepted step of h to state.x, v_{n+1} in state.velocity, and before finish_step: the
  // restitution of the contact's damping ratio (the ground's law, ground_restitution.hpp, on a
  // pair's relative motion along its normal). A pair that parts within the step, its impact not
  // yet over (two of the half periods backward Euler gives the penalty, π/atan(ω h) steps of h,
  // since it struck; a pair that came to rest and lifts off later is not thrown), leaves with e(ζ)
  // times the speed it struck at, by an impulse on the pair: backward Euler spreads an impact over
  // the steps it lasts and damps it by its own measure, not the damper's (a wire thrown at 1 m/s
  // at a pinned one parted at 0.22 m/s, and one on a soft contact of a given stiffness at 0.82,
  // whatever ζ). A pair
  // that meets within the step takes its rebound at once where the penalty's half period is shorter
  // than the step: the step swallowed the impact and left the pair at rest in the penalty, as at
  // the ground. True where a velocity changed.
  bool rebound_pairs(const Model& model, const std::vector<Vec3>& v_start, double h, State& state);
  // After an accepted step to state.x: the pairs touching there, with the stretch each keeps, go
  // to the history.
  void finish_step(const Model& model, double h, State& state);

 private:
  // The pairs touching at state.x, by key, into pairs_: the search's node–triangle and bar–bar
  // pairs and the node–bar pairs of the bars' ends.
  void find_pairs(const Model& model, State& state);

  // One friction spring: a pair touching at x_n.
  struct Spring {
    std::uint64_t key = 0;  // of the pair
    std::array<Index, 4> nodes{};
    std::array<double, 4> weights{};
    Vec3 normal = Vec3::UnitZ();
    Vec3 carried = Vec3::Zero();  // m, u_0
    double stiffness = 0.0;       // N/m
    double cap = 0.0;             // N, μ N
  };
  // u at x.
  Vec3 stretch(const Spring& spring, const std::vector<Vec3>& x) const;

  // A pair that met in the step rebound_pairs judged, by key: the speed it struck at (m/s) and
  // its penalty's ω (rad/s).
  struct Struck {
    std::uint64_t key = 0;
    double speed = 0.0;
    double omega = 0.0;
  };

  std::vector<ContactPoint> pairs_;           // touching at the last find_pairs, by key
  std::vector<ContactPoint> at_start_;        // the pairs touching at x_n, by key
  std::vector<Spring> springs_;               // by key
  std::vector<std::uint64_t> node_bar_keys_;  // scratch: the node–bar pairs to check
  std::vector<Vec3> x_start_;                 // m, x_n
  std::vector<Index> contact_nodes_;          // the nodes of the contact's bars and points
  std::vector<Struck> struck_;                // by key
};

}  // namespace dinam
