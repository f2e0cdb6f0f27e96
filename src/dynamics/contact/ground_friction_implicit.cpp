#include "dynamics/contact/ground_friction_implicit.hpp"

#include <algorithm>
#include <limits>

#include "dynamics/contact/capped_stick_spring.hpp"
#include "dynamics/free_dofs.hpp"
#include "model/model.hpp"

namespace dinam {

void ImplicitFriction::start_step(const Model& model, const State& state) {
  nodes_.clear();
  held_from_start_ = 0;
  held_.assign(static_cast<std::size_t>(model.node_count()), 0);
  anchor_.clear();
  stiffness_.clear();
  cap_.clear();
  const GroundContact& ground = model.ground;
  if (!ground.enabled) {
    return;
  }
  normal_ = ground.normal;
  // Room for every node on the ground, so that nodes landing within a step allocate nothing.
  const auto n = static_cast<std::size_t>(model.node_count());
  nodes_.reserve(n);
  anchor_.reserve(n);
  stiffness_.reserve(n);
  cap_.reserve(n);
  for (Index i = 0; i < model.node_count(); ++i) {
    const double depth = -ground.clearance(i, state.x[i]);
    if (depth <= 0.0 || model.pinned(i)) {
      continue;
    }
    const double k = ground.node_stiffness[i];
    const bool kept = !state.contact_touching.empty() && state.contact_touching[i] != 0;
    const double mu = !state.contact_sliding.empty() && state.contact_sliding[i] != 0
                          ? ground.kinetic_friction
                          : ground.static_friction;
    hold(i, kept ? state.contact_anchor[i] : ground.foot(state.x[i]), k,
         ground.stick ? std::numeric_limits<double>::infinity() : mu * k * depth);
  }
  held_from_start_ = nodes_.size();
}

void ImplicitFriction::hold(Index node, const Vec3& anchor, double stiffness, double cap) {
  held_[node] = 1;
  nodes_.push_back(node);
  anchor_.push_back(anchor);
  stiffness_.push_back(stiffness);
  cap_.push_back(cap);
}

bool ImplicitFriction::join_new_touches(const Model& model, const std::vector<Vec3>& x_start,
                                        const std::vector<Vec3>& x) {
  const GroundContact& ground = model.ground;
  if (!ground.enabled) {
    return false;
  }
  bool joined = false;
  for (Index i = 0; i < model.node_count(); ++i) {
    if (held_[i] != 0) {
      continue;
    }
    const double depth = -ground.clearance(i, x[i]);
    if (depth <= 0.0 || model.pinned(i)) {
      continue;
    }
    const double k = ground.node_stiffness[i];
    hold(i, ground.foot(x_start[i]), k,
         ground.stick ? std::numeric_limits<double>::infinity()
                      : ground.static_friction * k * depth);
    joined = true;
  }
  return joined;
}

bool ImplicitFriction::add_new_touches(const Model& model, const std::vector<Vec3>& x_start,
                                       const std::vector<Vec3>& x) {
  const GroundContact& ground = model.ground;
  if (!ground.enabled) {
    return false;
  }
  // A node that joined within the step but is above the plane at its solution holds nothing.
  bool left = false;
  for (std::size_t s = held_from_start_; s < nodes_.size(); ++s) {
    if (cap_[s] > 0.0 && ground.clearance(nodes_[s], x[nodes_[s]]) >= 0.0) {
      cap_[s] = 0.0;
      left = true;
    }
  }
  return join_new_touches(model, x_start, x) || left;
}

namespace {

// u = P (x − a), the spring's stretch along the plane.
Vec3 stretch(const Vec3& normal, const Vec3& x, const Vec3& anchor) {
  const Vec3 d = x - anchor;
  return d - d.dot(normal) * normal;
}

}  // namespace

double ImplicitFriction::energy(const std::vector<Vec3>& x) const {
  double energy = 0.0;
  for (std::size_t s = 0; s < nodes_.size(); ++s) {
    energy += capped_spring_energy(stiffness_[s], cap_[s],
                                   stretch(normal_, x[nodes_[s]], anchor_[s]).norm());
  }
  return energy;
}

void ImplicitFriction::add_forces(const std::vector<Vec3>& x, std::vector<Vec3>& force) const {
  for (std::size_t s = 0; s < nodes_.size(); ++s) {
    force[nodes_[s]] -=
        capped_spring_gradient(stiffness_[s], cap_[s], stretch(normal_, x[nodes_[s]], anchor_[s]));
  }
}

void ImplicitFriction::add_hessian(const FreeDofs& dofs, const std::vector<Vec3>& x,
                                   std::vector<Eigen::Triplet<double>>& triplets) const {
  const Mat3 across = Mat3::Identity() - normal_ * normal_.transpose();
  for (std::size_t s = 0; s < nodes_.size(); ++s) {
    const Index d = dofs.first_dof[nodes_[s]];
    if (d < 0) {
      continue;
    }
    const Mat3 block = capped_spring_hessian(stiffness_[s], cap_[s],
                                             stretch(normal_, x[nodes_[s]], anchor_[s]), across);
    for (int row = 0; row < 3; ++row) {
      for (int col = 0; col < 3; ++col) {
        triplets.emplace_back(d + row, d + col, block(row, col));
      }
    }
  }
}

void ImplicitFriction::finish_step(const Model& model, State& state) const {
  const GroundContact& ground = model.ground;
  if (!ground.enabled || state.contact_touching.empty()) {
    return;
  }
  // Every node as it stands now; then the held ones' anchors from their springs.
  for (Index i = 0; i < model.node_count(); ++i) {
    const double depth = -ground.clearance(i, state.x[i]);
    const bool touching = depth > 0.0 && !model.pinned(i);
    if (touching && state.contact_touching[i] == 0) {
      state.contact_anchor[i] = ground.foot(state.x[i]);
    }
    state.contact_touching[i] = touching ? 1 : 0;
    state.contact_sliding[i] = 0;
  }
  for (std::size_t s = 0; s < nodes_.size(); ++s) {
    const Index i = nodes_[s];
    if (state.contact_touching[i] == 0) {
      continue;
    }
    const Vec3 u = stretch(normal_, state.x[i], anchor_[s]);
    const double r = u.norm();
    const bool slid = r * stiffness_[s] > cap_[s];
    // The stretch the spring keeps: at most the cap of this step, and at most the cap the next
    // step will have (μ times the normal force at x_{n+1}, with the μ of what it did): a node
    // pressed hard at x_n (a landing) may not carry the stretch that allowed into a step in which
    // it presses lightly, where it would count as sliding.
    const double next_mu = slid ? ground.kinetic_friction : ground.static_friction;
    const double next_reach = ground.stick ? std::numeric_limits<double>::infinity()
                                           : next_mu * -ground.clearance(i, state.x[i]);
    const double kept = std::min({r, cap_[s] / stiffness_[s], next_reach});
    state.contact_anchor[i] = kept < r ? Vec3(anchor_[s] + ((r - kept) / r) * u) : anchor_[s];
    state.contact_sliding[i] = slid ? 1 : 0;
  }
}

}  // namespace dinam
