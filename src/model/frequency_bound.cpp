#include "model/frequency_bound.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/thread_team.hpp"
#include "model/model.hpp"
#include "model/model_spring_kinds.hpp"

namespace dinam {

void GershgorinSums::add(const Model& model, double k, const Index* nodes, const double* norms,
                         int count) {
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

bool bars_left_out(const Model& model, BarsIn bars) {
  return bars == BarsIn::kConstraints ||
         (bars == BarsIn::kTheModelsWay && model.bars_are_constraints());
}

NodeFrequencyRows node_frequency_rows(const Model& model, bool include_contact, BarsIn bars) {
  const Index n = model.node_count();
  GershgorinSums sums(n);
  sums.bars_held = bars_left_out(model, bars);
  for (const ModelSpringKind* kind : kModelSpringKinds) {
    kind->add_frequency_terms(model, sums);  // in the list's order: the bound's bits
  }
  // Ties (`attach`): a spring along the line from the node to its point, whose length's gradient
  // is the unit direction at the node and −w of it at the point's nodes. Held as constraints
  // with the bars (`integrator: xpbd`), they bound no step.
  if (!sums.bars_held) {
    const Ties& ties = model.ties;
    for (Index t = 0; t < ties.count(); ++t) {
      const double* w = &ties.weights[3 * static_cast<std::size_t>(t)];
      const double norms[4] = {1.0, w[0], w[1], w[2]};
      sums.add(model, ties.stiffness[t], &ties.nodes[4 * static_cast<std::size_t>(t)], norms, 4);
    }
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

double max_frequency_squared_bound(const Model& model, bool include_contact, BarsIn bars) {
  const NodeFrequencyRows rows = node_frequency_rows(model, include_contact, bars);
  double bound = 0.0;
  for (std::size_t i = 0; i < rows.own.size(); ++i) {
    bound = std::max(bound, rows.own[i] + rows.coupling[i]);
  }
  return bound;
}

double max_damping_rate_bound(const Model& model, BarsIn bars, bool include_contact) {
  const Index n = model.node_count();
  std::vector<double> rate(n, model.global_damping);  // α m / m
  // Bars held as constraints take their dampers into their projection.
  const Index dampers =
      bars_left_out(model, bars) ? 0 : static_cast<Index>(model.bar_damping.size());
  for (Index b = 0; b < dampers; ++b) {
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
  if (model.ground.enabled && include_contact) {
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
