#include "dynamics/energy.hpp"

#include "dynamics/force_kinds.hpp"
#include "model/model.hpp"

namespace dinam {

double kinetic_energy(const Model& model, const std::vector<Vec3>& v) {
  double energy = 0.0;
  for (Index i = 0; i < model.node_count(); ++i) {
    if (!model.pinned(i)) {
      energy += 0.5 * model.node_mass[i] * v[i].squaredNorm();
    }
  }
  return energy;
}

double gravitational_energy(const Model& model, const std::vector<Vec3>& x) {
  double energy = 0.0;
  for (Index i = 0; i < model.node_count(); ++i) {
    energy -= model.node_mass[i] * model.gravity.dot(x[i]);
  }
  return energy;
}

EnergyReport energy_report(const Model& model, const State& state,
                           const std::vector<Vec3>& v_whole) {
  EnergyReport report;
  report.time = state.time;
  report.kinetic = kinetic_energy(model, v_whole);
  // Every kind that stores energy, on its line (clamps are booked with the bending springs).
  for (const ForceKind* kind : kForceKinds) {
    if (kind->report_energy != nullptr) {
      kind->report_energy(model, state, report);
    }
  }
  report.accounts = state.energy;
  const EnergyAccounts& a = report.accounts;
  report.total = report.kinetic + report.axial + report.bending + report.torsion +
                 report.gravitational + report.contact + a.plastic_dissipation +
                 a.numerical_dissipation - a.damping_work - a.friction_work -
                 a.contact_damping_work - a.wind_work - a.field_work - a.support_work;
  return report;
}

}  // namespace dinam
