#include "model/frequency_bound.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/thread_team.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// Accumulates the diagonal blocks (N/m) and the scaled couplings (1/s²) of the bound.
struct GershgorinSums {
  std::vector<Mat3> diagonal;    // (n_nodes) Σ k g_i g_iᵀ, or an isotropic upper bound of it
  std::vector<double> coupling;  // (n_nodes) Σ k |g_i| |g_j| / √(m_i m_j) over free j ≠ i

  explicit GershgorinSums(Index n) : diagonal(n, Mat3::Zero()), coupling(n, 0.0) {}

  // A spring k over `count` nodes whose gradient blocks have norms at most `norms`. A pinned
  // node (inverse mass 0) neither couples nor is coupled to: its terms are exactly 0.
  void add(const Model& model, double k, const Index* nodes, const double* norms, int count) {
    double root[4][4];  // √(1/m_p · 1/m_q), symmetric: one square root per pair
    for (int p = 0; p < count; ++p) {
      for (int q = p + 1; q < count; ++q) {
        root[p][q] = root[q][p] =
            std::sqrt(model.node_inv_mass[nodes[p]] * model.node_inv_mass[nodes[q]]);
      }
    }
    for (int p = 0; p < count; ++p) {
      Mat3& block = diagonal[nodes[p]];
      const double isotropic = k * norms[p] * norms[p];
      for (int d = 0; d < 3; ++d) {
        block(d, d) += isotropic;
      }
      for (int q = 0; q < count; ++q) {
        if (q != p) {
          coupling[nodes[p]] += k * norms[p] * norms[q] * root[p][q];
        }
      }
    }
  }
};

}  // namespace

NodeFrequencyRows node_frequency_rows(const Model& model, bool include_contact) {
  const Index n = model.node_count();
  GershgorinSums sums(n);
  const auto& x = model.node_initial_x;

  // Bars: g = (−n, n), exact blocks k n nᵀ.
  for (Index b = 0; b < model.bar_count(); ++b) {
    const Index n0 = model.bar_nodes[2 * b];
    const Index n1 = model.bar_nodes[2 * b + 1];
    const double k = model.bar_axial_stiffness[b];
    const Vec3 direction = (x[n1] - x[n0]).normalized();
    sums.diagonal[n0] += k * direction * direction.transpose();
    sums.diagonal[n1] += k * direction * direction.transpose();
    if (!model.pinned(n0) && !model.pinned(n1)) {
      const double c = k * std::sqrt(model.node_inv_mass[n0] * model.node_inv_mass[n1]);
      sums.coupling[n0] += c;
      sums.coupling[n1] += c;
    }
  }
  // Bending: |∂θ/∂x_a| = 1/L1, |∂θ/∂x_b| = 1/L2, |∂θ/∂x_c| ≤ 1/L1 + 1/L2.
  for (Index s = 0; s < model.bend_count(); ++s) {
    const Index* nodes = &model.bend_nodes[3 * s];
    const double l1 = (x[nodes[0]] - x[nodes[1]]).norm();
    const double l2 = (x[nodes[2]] - x[nodes[1]]).norm();
    const double norms[3] = {1.0 / l1, 1.0 / l1 + 1.0 / l2, 1.0 / l2};
    sums.add(model, model.bend_stiffness[s], nodes, norms, 3);
  }
  // Clamps: a bending spring whose other two points are held, |∂θ/∂x_a| = 1/L.
  for (Index s = 0; s < model.clamp_count(); ++s) {
    const Index a = model.clamp_nodes[2 * s + 1];
    const double norm = 1.0 / model.clamp_ghost_offset[s].norm();
    sums.add(model, model.clamp_stiffness[s], &a, &norm, 1);
  }
  // Torsion: |∂φ/∂x_a| = 1/(|b1| sin θ1), |∂φ/∂x_b| = 1/(|b3| sin θ2), and the axis nodes'
  // blocks are combinations of those: |g_i| ≤ (1 + |b1|/|b2|) |g_a| + |b3|/|b2| |g_b|. The
  // spring's stiffness in φ is its weight sin²θ1 sin²θ2 times torsion_stiffness.
  for (Index s = 0; s < model.torsion_count(); ++s) {
    const Index* nodes = &model.torsion_nodes[4 * s];
    const Vec3 b1 = x[nodes[1]] - x[nodes[0]];
    const Vec3 b2 = x[nodes[2]] - x[nodes[1]];
    const Vec3 b3 = x[nodes[3]] - x[nodes[2]];
    const double ga = b2.norm() / b1.cross(b2).norm();
    const double gb = b2.norm() / b2.cross(b3).norm();
    const double r1 = b1.norm() / b2.norm();
    const double r3 = b3.norm() / b2.norm();
    const double norms[4] = {ga, (1 + r1) * ga + r3 * gb, (1 + r3) * gb + r1 * ga, gb};
    const double weight = b1.cross(b2).squaredNorm() / (b1.squaredNorm() * b2.squaredNorm()) *
                          b2.cross(b3).squaredNorm() / (b3.squaredNorm() * b2.squaredNorm());
    sums.add(model, weight * model.torsion_stiffness[s], nodes, norms, 4);
  }
  // Contact: the normal and stick penalties act on each node alone.
  if (include_contact && model.ground.enabled) {
    for (Index i = 0; i < n; ++i) {
      sums.diagonal[i] += model.ground.node_stiffness[i] * Mat3::Identity();
    }
  }

  // Contact between objects: a contact's stiffness is at most omega_squared times the lightest
  // free mass it moves (or the given stiffness); the bound allows two at once on every node.
  if (include_contact && model.contact.enabled) {
    const ObjectContact& contact = model.contact;
    for (Index i = 0; i < n; ++i) {
      if (contact.point_radius[i] > 0.0) {
        const double k = contact.omega_squared > 0.0 ? contact.omega_squared * model.node_mass[i]
                                                     : contact.stiffness;
        sums.diagonal[i] += 2.0 * k * Mat3::Identity();
      }
    }
  }

  NodeFrequencyRows rows;
  rows.own.assign(n, 0.0);
  rows.coupling.assign(n, 0.0);
  // Each node on its own: on every thread of the team, for a model large enough to pay for it.
  thread_team().run(
      [&](const TeamMember& member) {
        const auto [first, last] = member.share(n, 8);
        for (Index i = first; i < last; ++i) {
          if (model.pinned(i)) {
            continue;
          }
          Eigen::SelfAdjointEigenSolver<Mat3> solver;
          solver.computeDirect(sums.diagonal[i], Eigen::EigenvaluesOnly);
          rows.own[i] = solver.eigenvalues().maxCoeff() * model.node_inv_mass[i];
          rows.coupling[i] = sums.coupling[i];
        }
      },
      n < 4096);
  return rows;
}

double max_frequency_squared_bound(const Model& model, bool include_contact) {
  const NodeFrequencyRows rows = node_frequency_rows(model, include_contact);
  double bound = 0.0;
  for (std::size_t i = 0; i < rows.own.size(); ++i) {
    bound = std::max(bound, rows.own[i] + rows.coupling[i]);
  }
  return bound;
}

double max_damping_rate_bound(const Model& model) {
  const Index n = model.node_count();
  std::vector<double> rate(n, model.global_damping);  // α m / m
  for (Index b = 0; b < static_cast<Index>(model.bar_damping.size()); ++b) {
    const double c = model.bar_damping[b];
    if (c == 0.0) {
      continue;
    }
    const Index n0 = model.bar_nodes[2 * b];
    const Index n1 = model.bar_nodes[2 * b + 1];
    const double coupling = c * std::sqrt(model.node_inv_mass[n0] * model.node_inv_mass[n1]);
    rate[n0] += c * model.node_inv_mass[n0] + coupling;
    rate[n1] += c * model.node_inv_mass[n1] + coupling;
  }
  if (model.ground.enabled) {
    for (Index i = 0; i < n; ++i) {
      rate[i] += model.ground.node_damping[i] * model.node_inv_mass[i];
    }
  }
  double bound = 0.0;
  for (Index i = 0; i < n; ++i) {
    if (!model.pinned(i)) {
      bound = std::max(bound, rate[i]);
    }
  }
  return bound;
}

}  // namespace dinam
