#include "dynamics/contact/object_contact_implicit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/closest_points.hpp"
#include "dynamics/contact/capped_stick_spring.hpp"
#include "dynamics/contact/contact_closest.hpp"
#include "dynamics/contact/contact_pairs.hpp"
#include "dynamics/contact/ground_restitution.hpp"
#include "dynamics/contact/object_contact.hpp"
#include "dynamics/free_dofs.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// The pairs' kinds, by their keys: the search's node–triangle pairs (bit 63) and bar–bar pairs
// (neither top bit), and the node–bar pairs of bars' ends made here (both: node ids stay below
// 2³⁰, so bit 62 is free in the others).
constexpr std::uint64_t kNodeBarBits = (std::uint64_t{1} << 63) | (std::uint64_t{1} << 62);
enum class PairKind { kNodeTriangle, kBarBar, kNodeBar };

PairKind kind_of(std::uint64_t key) {
  if ((key & kNodeBarBits) == kNodeBarBits) {
    return PairKind::kNodeBar;
  }
  return (key >> 63) == kBarBarContact ? PairKind::kBarBar : PairKind::kNodeTriangle;
}

std::uint64_t node_bar_key(Index node, Index bar) {
  return kNodeBarBits | static_cast<std::uint64_t>(node) << 32 | static_cast<std::uint64_t>(bar);
}

// The element of `sorted` (by key) with `key`, or null.
template <class Element>
const Element* find_key(const std::vector<Element>& sorted, std::uint64_t key) {
  const auto at = std::lower_bound(sorted.begin(), sorted.end(), key,
                                   [](const Element& e, std::uint64_t k) { return e.key < k; });
  return at != sorted.end() && at->key == key ? &*at : nullptr;
}

template <class Element>
void sort_by_key(std::vector<Element>& list) {
  std::sort(list.begin(), list.end(),
            [](const Element& a, const Element& b) { return a.key < b.key; });
}

// IPC's edge–edge mollifier of s = |e_A × e_B|² against ε = 1e-3 |ē_A|² |ē_B|² (the rest
// lengths'): (2 − s/ε) s/ε below ε, 1 from there (sin² of the angle between the bars 1e-3, 1.8°),
// once differentiable; and its gradient on the bars' four nodes.
struct Mollifier {
  double value = 1.0;
  std::array<Vec3, 4> gradient{Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
};

constexpr double kParallelShare = 1e-3;

Mollifier mollifier(const std::array<Vec3, 4>& at, double threshold) {
  const Vec3 ea = at[1] - at[0];
  const Vec3 eb = at[3] - at[2];
  const Vec3 across = ea.cross(eb);
  const double s = across.squaredNorm();
  Mollifier m;
  if (s >= threshold) {
    return m;
  }
  const double r = s / threshold;
  m.value = (2.0 - r) * r;
  const double slope = (2.0 - 2.0 * r) / threshold;     // dm/ds
  const Vec3 along_a = 2.0 * slope * eb.cross(across);  // dm/de_A
  const Vec3 along_b = 2.0 * slope * across.cross(ea);  // dm/de_B
  m.gradient = {-along_a, along_a, -along_b, along_b};
  return m;
}

// A touching pair's push at x: its energy, the forces on its nodes, the normal along which it
// pushes side A and how hard (N, for friction's cap), the slope of that push with the penetration
// (N/m, for the preconditioner), and the stiffness friction's stick spring takes.
struct PairPush {
  double energy = 0.0;
  std::array<Vec3, 4> force{Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  Vec3 normal = Vec3::UnitZ();
  double push = 0.0;
  double slope = 0.0;
  double stick_stiffness = 0.0;
  double reach = 0.0;  // m, the sum of the pair's radii
};

// The sum of the pair's radii, m.
double pair_reach(const Model& model, const ContactPoint& point) {
  const ObjectContact& contact = model.contact;
  if (kind_of(point.key) == PairKind::kNodeBar) {
    return contact.point_radius[point.nodes[0]] + contact.bar_radius[contact_side_b(point.key)];
  }
  return contact_reach(contact, point.key);
}

PairPush evaluate(const Model& model, const ContactPoint& point, const std::vector<Vec3>& x) {
  PairPush result;
  result.reach = pair_reach(model, point);
  ContactPenalty penalty;
  double penetration = 0.0;
  double scale = 1.0;  // the mollifier, for two bars
  if (kind_of(point.key) == PairKind::kNodeBar) {
    const Index node = point.nodes[0];
    const double reach = result.reach;
    penalty = contact_penalty_between(
        model, model.node_inv_mass[node],
        std::max(model.node_inv_mass[point.nodes[1]], model.node_inv_mass[point.nodes[2]]), reach);
    const double distance = point.separation.norm();
    if (distance > 1e-12 * reach) {
      result.normal = point.separation / distance;
    } else {  // on the bar's axis: across it
      const Vec3 along = x[point.nodes[2]] - x[point.nodes[1]];
      result.normal = along.cross(kWorldUp).squaredNorm() > 0.0 ? along.cross(kWorldUp).normalized()
                                                                : Vec3::UnitX();
    }
    penetration = reach - distance;
  } else {
    const ContactPush push = contact_push(model, point, x);
    penalty = push.penalty;
    penetration = push.penetration;
    result.normal = push.normal;
  }
  Mollifier m;
  if (kind_of(point.key) == PairKind::kBarBar) {
    const Index a = contact_side_a(point.key);
    const Index b = contact_side_b(point.key);
    const double la = model.bar_rest_length[a];
    const double lb = model.bar_rest_length[b];
    m = mollifier({x[point.nodes[0]], x[point.nodes[1]], x[point.nodes[2]], x[point.nodes[3]]},
                  kParallelShare * la * la * lb * lb);
    scale = m.value;
  }
  const double energy = penalty.energy(penetration);
  const double force = penalty.force(penetration);
  result.energy = scale * energy;
  result.push = scale * force;
  result.slope = scale * penalty.slope(penetration);
  result.stick_stiffness = penalty.soft;
  for (int j = 0; j < 4; ++j) {
    result.force[j] = (point.weights[j] * result.push) * result.normal - energy * m.gradient[j];
  }
  return result;
}

void add_block(const FreeDofs& dofs, const std::array<Index, 4>& nodes,
               const std::array<double, 4>& weights, const Mat3& block,
               std::vector<Eigen::Triplet<double>>& triplets) {
  for (int i = 0; i < 4; ++i) {
    const Index di = dofs.first_dof[nodes[i]];
    for (int j = 0; j < 4; ++j) {
      const Index dj = dofs.first_dof[nodes[j]];
      const double weight = weights[i] * weights[j];
      if (di < 0 || dj < 0 || weight == 0.0) {
        continue;
      }
      for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col) {
          triplets.emplace_back(di + row, dj + col, weight * block(row, col));
        }
      }
    }
  }
}

}  // namespace

double contact_envelope(const Model& model) {
  const ObjectContact& contact = model.contact;
  double smallest = std::numeric_limits<double>::infinity();
  if (!contact.enabled) {
    return smallest;
  }
  for (const Index b : contact.bars) {
    smallest = std::min(smallest, contact.bar_radius[b]);
  }
  for (const Index p : contact.points) {
    smallest = std::min(smallest, contact.point_radius[p]);
  }
  for (const double r : contact.triangle_radius) {
    smallest = std::min(smallest, r);
  }
  return 0.5 * smallest;
}

double contact_envelope_steps(const Model& model, double duration) {
  const double envelope = contact_envelope(model);
  if (!std::isfinite(envelope) || envelope <= 0.0 || model.node_count() == 0) {
    return 0.0;
  }
  const double g = model.gravity.norm();
  const Vec3 down = g > 0.0 ? Vec3(model.gravity / g) : Vec3::Zero();
  double fastest = 0.0;
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  for (Index i = 0; i < model.node_count(); ++i) {
    fastest = std::max(fastest, model.node_initial_v[i].norm());
    const double depth = down.dot(model.node_initial_x[i]);
    low = std::min(low, depth);
    high = std::max(high, depth);
  }
  return duration * (fastest + std::sqrt(2.0 * g * (high - low))) / envelope;
}

void ImplicitObjectContact::find_pairs(const Model& model, State& state) {
  const ObjectContact& contact = model.contact;
  ObjectContactWorkspace& work = state.object_contact;
  const std::vector<Vec3>& x = state.x;
  find_touching_pairs(model, state, PairMerging::kEveryPair);
  pairs_.assign(work.touching.begin(), work.touching.end());
  // A node is pushed off a triangle on the side it is on (no crossing to remember: the speed
  // envelope keeps a step from carrying it through the middle).
  for (ContactPoint& point : pairs_) {
    if (kind_of(point.key) == PairKind::kNodeTriangle) {
      point.side = triangle_side(
          {x[point.nodes[0]], x[point.nodes[1]], x[point.nodes[2]], x[point.nodes[3]]});
    }
  }
  // Each end of a bar against the other bar of every pair of bars the search found near.
  node_bar_keys_.clear();
  for (const ContactCandidate& pair : work.candidates) {
    if ((pair.key >> 63) != kBarBarContact) {
      continue;
    }
    const Index a = contact_side_a(pair.key);
    const Index b = contact_side_b(pair.key);
    if (bar_broken(state, a) || bar_broken(state, b)) {
      continue;
    }
    node_bar_keys_.insert(node_bar_keys_.end(),
                          {node_bar_key(pair.nodes[0], b), node_bar_key(pair.nodes[1], b),
                           node_bar_key(pair.nodes[2], a), node_bar_key(pair.nodes[3], a)});
  }
  std::sort(node_bar_keys_.begin(), node_bar_keys_.end());
  node_bar_keys_.erase(std::unique(node_bar_keys_.begin(), node_bar_keys_.end()),
                       node_bar_keys_.end());
  for (const std::uint64_t key : node_bar_keys_) {
    const Index node = contact_side_a(key & ~kNodeBarBits);
    const Index bar = contact_side_b(key);
    const Index b0 = model.bar_nodes[2 * bar];
    const Index b1 = model.bar_nodes[2 * bar + 1];
    if (model.pinned(node) && model.pinned(b0) && model.pinned(b1)) {
      continue;
    }
    const double t = closest_points_of_segments(x[node], x[node], x[b0], x[b1]).t;
    const Vec3 separation = x[node] - ((1.0 - t) * x[b0] + t * x[b1]);
    const double reach = contact.point_radius[node] + contact.bar_radius[bar];
    if (separation.squaredNorm() >= reach * reach) {
      continue;
    }
    ContactPoint& point = pairs_.emplace_back();
    point.key = key;
    point.features = {ContactFeatures::kNodeEdge, node, std::min(b0, b1), std::max(b0, b1)};
    point.nodes = {node, b0, b1, b1};
    point.weights = {1.0, t - 1.0, -t, 0.0};
    point.separation = separation;
  }
  sort_by_key(pairs_);
}

void ImplicitObjectContact::start_step(const Model& model, State& state) {
  const ObjectContact& contact = model.contact;
  springs_.clear();
  at_start_.clear();
  if (!contact.enabled) {
    return;
  }
  if (contact_nodes_.empty()) {
    for (const Index b : contact.bars) {
      contact_nodes_.push_back(model.bar_nodes[2 * b]);
      contact_nodes_.push_back(model.bar_nodes[2 * b + 1]);
    }
    contact_nodes_.insert(contact_nodes_.end(), contact.points.begin(), contact.points.end());
    std::sort(contact_nodes_.begin(), contact_nodes_.end());
    contact_nodes_.erase(std::unique(contact_nodes_.begin(), contact_nodes_.end()),
                         contact_nodes_.end());
  }
  x_start_ = state.x;
  // The history: the pairs touching at x_n when the last step ended, by key.
  const std::vector<ContactPoint>& history = state.object_contact.previous;
  find_pairs(model, state);
  for (const ContactPoint& point : pairs_) {
    const PairPush push = evaluate(model, point, state.x);
    if (push.push <= 0.0) {
      continue;
    }
    const ContactPoint* before = find_key(history, point.key);
    Spring spring;
    spring.key = point.key;
    spring.nodes = point.nodes;
    spring.weights = point.weights;
    spring.normal = push.normal;
    spring.stiffness = push.stick_stiffness;
    const bool sliding = before != nullptr && before->sliding;
    spring.cap = (sliding ? contact.kinetic_friction : contact.static_friction) * push.push;
    if (before != nullptr) {
      spring.carried = before->slip - before->slip.dot(push.normal) * push.normal;
    }
    springs_.push_back(spring);
  }
  at_start_ = pairs_;
}

Vec3 ImplicitObjectContact::stretch(const Spring& spring, const std::vector<Vec3>& x) const {
  Vec3 moved = Vec3::Zero();
  for (int j = 0; j < 4; ++j) {
    const Index node = spring.nodes[j];
    moved += spring.weights[j] * (x[node] - x_start_[node]);
  }
  return spring.carried + moved - moved.dot(spring.normal) * spring.normal;
}

void ImplicitObjectContact::add_forces(const Model& model, State& state) {
  if (!model.contact.enabled) {
    return;
  }
  find_pairs(model, state);
  for (const ContactPoint& point : pairs_) {
    const PairPush push = evaluate(model, point, state.x);
    for (int j = 0; j < 4; ++j) {
      state.force[point.nodes[j]] += push.force[j];
    }
  }
  for (const Spring& spring : springs_) {
    const Vec3 on_a =
        -capped_spring_gradient(spring.stiffness, spring.cap, stretch(spring, state.x));
    for (int j = 0; j < 4; ++j) {
      state.force[spring.nodes[j]] += spring.weights[j] * on_a;
    }
  }
}

double ImplicitObjectContact::energy(const Model& model, State& state) {
  if (!model.contact.enabled) {
    return 0.0;
  }
  find_pairs(model, state);
  double energy = friction_energy(state.x);
  for (const ContactPoint& point : pairs_) {
    energy += evaluate(model, point, state.x).energy;
  }
  return energy;
}

double ImplicitObjectContact::energy_at_start(const Model& model) const {
  if (!model.contact.enabled) {
    return 0.0;
  }
  double energy = friction_energy(x_start_);  // summed in energy()'s order
  for (const ContactPoint& point : at_start_) {
    energy += evaluate(model, point, x_start_).energy;
  }
  return energy;
}

double ImplicitObjectContact::friction_energy(const std::vector<Vec3>& x) const {
  double energy = 0.0;
  for (const Spring& spring : springs_) {
    energy += capped_spring_energy(spring.stiffness, spring.cap, stretch(spring, x).norm());
  }
  return energy;
}

void ImplicitObjectContact::add_hessian(const Model& model, State& state, const FreeDofs& dofs,
                                        std::vector<Eigen::Triplet<double>>& triplets) {
  if (!model.contact.enabled) {
    return;
  }
  find_pairs(model, state);
  for (const ContactPoint& point : pairs_) {
    const PairPush push = evaluate(model, point, state.x);
    add_block(dofs, point.nodes, point.weights, push.slope * push.normal * push.normal.transpose(),
              triplets);
  }
  for (const Spring& spring : springs_) {
    // ∂u/∂x_j = w_j P, so the block (i, j) is w_i w_j P H_u P (u lies in the plane).
    const Mat3 across = Mat3::Identity() - spring.normal * spring.normal.transpose();
    add_block(dofs, spring.nodes, spring.weights,
              capped_spring_hessian(spring.stiffness, spring.cap, stretch(spring, state.x), across),
              triplets);
  }
}

double ImplicitObjectContact::longest_move(const Model& model, const std::vector<Vec3>& x) const {
  double longest = 0.0;
  if (!model.contact.enabled) {
    return longest;
  }
  for (const Index node : contact_nodes_) {
    longest = std::max(longest, (x[node] - x_start_[node]).norm());
  }
  return longest;
}

bool ImplicitObjectContact::touching_changed(const Model& model, State& state) {
  if (!model.contact.enabled) {
    return false;
  }
  find_pairs(model, state);
  return !std::equal(pairs_.begin(), pairs_.end(), at_start_.begin(), at_start_.end(),
                     [](const ContactPoint& a, const ContactPoint& b) { return a.key == b.key; });
}

namespace {

// The pair's relative motion along n: how fast its points close (m/s, along −n) at velocities v,
// and 1 over the mass the contact point moves, Σ w_j²/m_j (1/kg).
struct PairMotion {
  double closing = 0.0;
  double inverse_mass = 0.0;
};
PairMotion pair_motion(const Model& model, const ContactPoint& point, const Vec3& n,
                       const std::vector<Vec3>& v) {
  PairMotion motion;
  for (int j = 0; j < 4; ++j) {
    const Index node = point.nodes[j];
    const double w = point.weights[j];
    motion.closing -= w * v[node].dot(n);
    motion.inverse_mass += w * w * model.node_inv_mass[node];
  }
  return motion;
}

// Sets the pair's separating speed along n to `wanted`, by an impulse along n shared out to its
// nodes by their weights: equal and opposite on the two sides, so momentum is kept. True where a
// velocity changed.
bool set_separating_speed(const Model& model, const ContactPoint& point, const Vec3& n,
                          double wanted, std::vector<Vec3>& v) {
  const PairMotion motion = pair_motion(model, point, n, v);
  if (-motion.closing == wanted || motion.inverse_mass <= 0.0) {
    return false;
  }
  const double impulse = (wanted + motion.closing) / motion.inverse_mass;
  for (int j = 0; j < 4; ++j) {
    const Index node = point.nodes[j];
    v[node] += (point.weights[j] * impulse * model.node_inv_mass[node]) * n;
  }
  return true;
}

}  // namespace

bool ImplicitObjectContact::rebound_pairs(const Model& model, const std::vector<Vec3>& v_start,
                                          double h, State& state) {
  struck_.clear();
  const ObjectContact& contact = model.contact;
  if (!contact.enabled) {
    return false;
  }
  const double restitution = spring_dashpot_restitution(contact.damping_ratio);
  const std::vector<ContactPoint>& history = state.object_contact.previous;
  bool any = false;
  // Pairs that were touching at x_n and whose points are out of reach at x_{n+1}: the impact
  // ended within the step.
  for (const ContactPoint& point : history) {
    if (point.struck <= 0.0 ||
        point.impact_phase + std::atan(point.impact_omega * h) > 2.0 * std::numbers::pi) {
      continue;  // no impact, or one long over: a pair that rested and now lifts off
    }
    Vec3 separation = Vec3::Zero();
    for (int j = 0; j < 4; ++j) {
      separation += point.weights[j] * state.x[point.nodes[j]];
    }
    const double distance = separation.norm();
    if (distance < pair_reach(model, point)) {
      continue;  // still touching, though another pair of features may carry it on
    }
    any = set_separating_speed(model, point, separation / distance, restitution * point.struck,
                               state.velocity) ||
          any;
  }
  // Pairs that met within the step: the speed they struck at, for when they part; or, where the
  // step swallowed the impact whole, the rebound now.
  find_pairs(model, state);
  for (const ContactPoint& point : pairs_) {
    if (find_key(history, point.key) != nullptr) {
      continue;
    }
    const PairPush push = evaluate(model, point, state.x);
    const Vec3& n = push.normal;
    double gap = -push.reach;  // the same points at x_n, along n
    double pull = 0.0;         // m/s², gravity on the free ones, along −n
    for (int j = 0; j < 4; ++j) {
      gap += point.weights[j] * x_start_[point.nodes[j]].dot(n);
      if (!model.pinned(point.nodes[j])) {
        pull -= point.weights[j] * model.gravity.dot(n);
      }
    }
    const PairMotion motion = pair_motion(model, point, n, v_start);
    if (push.push <= 0.0 || gap <= 0.0 || motion.inverse_mass <= 0.0) {
      continue;  // no impact: the pair moved on from another pair of features, or holds nothing
    }
    const double struck =
        std::sqrt(motion.closing * motion.closing + 2.0 * std::max(pull, 0.0) * gap);
    const double omega = std::sqrt(push.stick_stiffness * motion.inverse_mass);
    if (omega * h < std::numbers::pi) {
      struck_.push_back({point.key, struck, omega});
    } else {
      any = set_separating_speed(model, point, n, restitution * struck, state.velocity) || any;
    }
  }
  return any;
}

void ImplicitObjectContact::finish_step(const Model& model, double h, State& state) {
  const ObjectContact& contact = model.contact;
  if (!contact.enabled) {
    return;
  }
  ObjectContactWorkspace& work = state.object_contact;
  find_pairs(model, state);
  work.energy = 0.0;
  for (ContactPoint& point : pairs_) {
    const PairPush push = evaluate(model, point, state.x);
    point.energy = push.energy;
    work.energy += point.energy;
    point.slip = Vec3::Zero();
    point.sliding = false;
    const ContactPoint* before = find_key(work.previous, point.key);
    const Struck* met = find_key(struck_, point.key);
    if (before != nullptr) {
      point.struck = before->struck;
      point.impact_omega = before->impact_omega;
      point.impact_phase = before->impact_phase;
    } else if (met != nullptr) {
      point.struck = met->speed;
      point.impact_omega = met->omega;
      point.impact_phase = 0.0;
    } else {
      point.struck = point.impact_omega = point.impact_phase = 0.0;
    }
    point.impact_phase += std::atan(point.impact_omega * h);
    const Spring* spring = find_key(springs_, point.key);
    if (spring == nullptr) {
      continue;
    }
    // The stretch kept: at most this step's cap's reach, and at most the next step's (μ of what
    // it did times the pair's push at x_{n+1}), in the plane at x_{n+1}, as at the ground.
    Vec3 u = stretch(*spring, state.x);
    u -= u.dot(push.normal) * push.normal;
    const double r = u.norm();
    const bool slid = r * spring->stiffness > spring->cap;
    const double next_mu = slid ? contact.kinetic_friction : contact.static_friction;
    const double kept = std::min({r, spring->cap / spring->stiffness,
                                  next_mu * std::max(push.push, 0.0) / push.stick_stiffness});
    point.slip = r > 0.0 ? Vec3((kept / r) * u) : Vec3::Zero();
    point.sliding = slid && push.push > 0.0;
  }
  // The history, by key: what start_step looks pairs up by.
  work.previous = pairs_;
}

}  // namespace dinam
