#include "solver/implicit_energy.hpp"

namespace dinam {

double free_kinetic_energy(const Eigen::VectorXd& mass, const Eigen::VectorXd& v) {
  return 0.5 * mass.dot(v.cwiseProduct(v));
}

EnergyAccounts implicit_step_accounts(const ImplicitStepEnds& ends) {
  const Eigen::VectorXd move = ends.x_end - ends.x_start;      // Δx = x_{n+1} − x_n
  const Eigen::VectorXd from_base = ends.x_end - ends.x_base;  // x_{n+1} − x_b
  const Eigen::VectorXd jump = ends.v_end - ends.v_base;       // v_{n+1} − v_b
  EnergyAccounts step;
  step.damping_work = ends.damper_force.dot(move);
  for (const ImplicitStepEnds::Load& load : ends.loads) {
    step.*load.work += load.force.dot(move);
  }
  // The friction springs are part of P within the step and start afresh at the next: what they
  // gained over the step is what friction took.
  step.friction_work = ends.friction_start - ends.friction_end;
  step.support_work = ends.support_work;
  Eigen::VectorXd outside = ends.damper_force;
  for (const ImplicitStepEnds::Load& load : ends.loads) {
    outside += load.force;
  }
  step.numerical_dissipation = free_kinetic_energy(ends.mass, ends.v_start) -
                               free_kinetic_energy(ends.mass, ends.v_base) +
                               free_kinetic_energy(ends.mass, jump) + ends.potential_start -
                               ends.potential_end - ends.potential_force.dot(from_base) +
                               outside.dot(ends.x_base - ends.x_start) + ends.support_work;
  return step;
}

}  // namespace dinam
