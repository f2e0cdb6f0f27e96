#pragma once
// The ground's Coulomb friction inside an implicit step: the stick spring of central differences'
// contact (dynamics/contact/ground_contact.hpp), as a potential of the positions that Newton's
// method minimises with the rest. Each node below the plane at x_n keeps its anchor a on the plane
// and is held by the tangential spring k u, u = P (x − a) (P the projection onto the plane, k the
// ground's penalty stiffness), up to the cap μ N (μs while it sticks, μk while it slides; N =
// k × its depth at x_n, lagged), beyond which it slides at the cap (capped_stick_spring.hpp):
// convex and once differentiable, so the step stays a minimisation. A node that sticks moves
// only by the spring's give, μN/k at most, however long the step: it does not creep. After the
// step a node that slid drags its anchor to r_c behind its foot, as central differences do; one
// that first touched within the step is anchored at its foot. With `stick` the cap is infinite.
#include <Eigen/SparseCore>
#include <cstdint>
#include <vector>

#include "core/types.hpp"
#include "dynamics/state.hpp"

namespace dinam {

struct Model;
struct FreeDofs;

class ImplicitFriction {
 public:
  // The springs of the nodes below the plane at state.x (x_n), from the state's contact history.
  void start_step(const Model& model, const State& state);

  // Nodes below the plane at `x` (an iterate of the step) that were above it at `x_start` (x_n)
  // join, anchored at x_n's foot on the plane, their cap μs times the normal force at x: a node
  // that lands within the step is held from its start, as it would be by central differences'
  // short steps (else a block set down on a slope slides freely for its first step and lands
  // too fast to stick). True where any joined. Called at every iterate, so that a landing node
  // holds from the next one on.
  bool join_new_touches(const Model& model, const std::vector<Vec3>& x_start,
                        const std::vector<Vec3>& x);
  // At the step's solution `x`: the nodes that joined within the step but are above the plane at
  // x let go (their cap 0), and any new touches joined. True where either happened: the step is
  // to be solved on. The others keep the cap they joined with, μs times their normal force at
  // the iterate they joined at, for this step, as the nodes held from the step's start keep
  // theirs from x_n: taking it again from x and solving on wherever it moved by a tenth cost the
  // Wuson's fall a quarter of its Newton iterations (bench/notes/implicit-integrator.md).
  bool add_new_touches(const Model& model, const std::vector<Vec3>& x_start,
                       const std::vector<Vec3>& x);

  bool empty() const { return nodes_.empty(); }
  double energy(const std::vector<Vec3>& x) const;                              // J
  void add_forces(const std::vector<Vec3>& x, std::vector<Vec3>& force) const;  // N, −∇E
  // The Hessian of E at x, 3 × 3 blocks on the free nodes' diagonal.
  void add_hessian(const FreeDofs& dofs, const std::vector<Vec3>& x,
                   std::vector<Eigen::Triplet<double>>& triplets) const;

  // After an accepted step to state.x: anchors dragged where a node slid, new touches anchored
  // at their feet, nodes that left the plane forgotten (State::contact_*).
  void finish_step(const Model& model, State& state) const;

 private:
  // Adds a spring on `node` from `anchor`.
  void hold(Index node, const Vec3& anchor, double stiffness, double cap);

  Vec3 normal_ = Vec3::UnitZ();
  std::vector<Index> nodes_;         // those below the plane at x_n, then those that joined
  std::size_t held_from_start_ = 0;  // how many of nodes_ were below the plane at x_n
  std::vector<std::uint8_t> held_;   // (nodes) 1 where the node is in nodes_
  std::vector<Vec3> anchor_;         // m, on the plane
  std::vector<double> stiffness_;    // N/m
  std::vector<double> cap_;          // N, μ N; infinite with `stick`
};

}  // namespace dinam
