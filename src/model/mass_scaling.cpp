#include "model/mass_scaling.hpp"

#include <algorithm>
#include <cmath>

#include "model/model.hpp"

namespace dinam {

double moving_mass(const Model& model) {
  double mass = 0.0;
  for (Index i = 0; i < model.node_count(); ++i) {
    mass += model.pinned(i) ? 0.0 : model.node_mass[i];
  }
  return mass;
}

std::vector<double> masses_for_frequency(const Model& model, const NodeFrequencyRows& rows,
                                         double omega_squared) {
  std::vector<double> mass = model.node_mass;
  for (std::size_t i = 0; i < mass.size(); ++i) {
    const double own = rows.own[i];
    const double coupling = rows.coupling[i];
    if (model.pinned(static_cast<Index>(i)) || own + coupling <= omega_squared) {
      continue;
    }
    // With u = √(m_i / m): own u² + coupling u = ω², the positive root.
    const double u =
        own > 0.0
            ? (std::sqrt(coupling * coupling + 4.0 * own * omega_squared) - coupling) / (2.0 * own)
            : omega_squared / coupling;
    mass[i] = model.node_mass[i] / (u * u);
  }
  return mass;
}

double mass_needed_for(const Model& model, const NodeFrequencyRows& rows, double omega_squared) {
  const std::vector<double> mass = masses_for_frequency(model, rows, omega_squared);
  double added = 0.0;
  for (std::size_t i = 0; i < mass.size(); ++i) {
    added += mass[i] - model.node_mass[i];
  }
  return added;
}

MassScaling scale_masses_to(Model& model, const NodeFrequencyRows& rows, double omega_squared) {
  MassScaling scaling;
  scaling.mass_before = moving_mass(model);
  double omega_squared_before = 0.0;  // the bound itself, from the rows already at hand
  for (std::size_t i = 0; i < rows.own.size(); ++i) {
    omega_squared_before = std::max(omega_squared_before, rows.own[i] + rows.coupling[i]);
  }
  const std::vector<double> mass = masses_for_frequency(model, rows, omega_squared);
  for (std::size_t i = 0; i < mass.size(); ++i) {
    if (mass[i] > model.node_mass[i]) {
      scaling.added_mass += mass[i] - model.node_mass[i];
      ++scaling.nodes;
      model.node_mass[i] = mass[i];
      model.node_inv_mass[i] = 1.0 / mass[i];  // only free nodes take mass
    }
  }
  if (scaling.nodes > 0) {
    scaling.step_gain = std::sqrt(omega_squared_before / max_frequency_squared_bound(model, false));
  }
  return scaling;
}

std::optional<DefaultScaling> default_scaling_frequency(const Model& model,
                                                        const NodeFrequencyRows& rows,
                                                        double max_fraction) {
  std::vector<double> row;
  for (std::size_t i = 0; i < rows.own.size(); ++i) {
    if (!model.pinned(static_cast<Index>(i))) {
      row.push_back(rows.own[i] + rows.coupling[i]);
    }
  }
  if (row.empty()) {
    return std::nullopt;
  }
  const double highest = *std::max_element(row.begin(), row.end());
  const auto middle = row.begin() + static_cast<std::ptrdiff_t>(row.size() / 2);
  std::nth_element(row.begin(), middle, row.end());
  double omega_squared = kMassScalingTypicalRatio * kMassScalingTypicalRatio * *middle;
  const double allowed = max_fraction * moving_mass(model);
  const bool capped = mass_needed_for(model, rows, omega_squared) > allowed;
  if (capped) {
    // The mass needed falls as ω² rises: bisect (in log ω²) for the lowest ω² within the limit.
    double lo = omega_squared;
    double hi = highest;
    for (int k = 0; k < 60 && hi > lo * (1.0 + 1e-6); ++k) {
      const double mid = std::sqrt(lo * hi);
      (mass_needed_for(model, rows, mid) > allowed ? lo : hi) = mid;
    }
    omega_squared = hi;
  }
  // The step grows as 1/ω.
  if (highest < kMassScalingMinGain * kMassScalingMinGain * omega_squared) {
    return std::nullopt;
  }
  return DefaultScaling{omega_squared, capped};
}

}  // namespace dinam
