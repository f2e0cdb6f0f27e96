#include "solver/quasi_newton.hpp"

#include <algorithm>
#include <cmath>

#include "core/stop_request.hpp"
#include "dynamics/free_dofs.hpp"
#include "solver/sufficient_decrease.hpp"

namespace dinam {
namespace {

using Vector = Eigen::VectorXd;

// Curvature pairs kept (Liu et al. keep 5; more cost a little more a solve and help little).
constexpr int kMemory = 5;
// Iterations a step may take before it is split.
constexpr int kMostIterations = 60;
// Halvings of the line search before the step is split.
constexpr int kMostHalvings = 12;
// Times a step's solve goes on with the friction of nodes that landed within it (as Newton's).
constexpr int kMostLandingRounds = 3;

}  // namespace

bool minimise_quasi_newton(std::vector<Vec3>& x, const FreeDofs& dofs, const Vector& mass, double h,
                           double bar, const StepPotential& potential, QuasiNewtonCounts& counts,
                           QuasiNewtonWorkspace& work) {
  const std::size_t n = x.size();
  const int memory = kMemory;
  const double converged =  // m/s², a node's |g|/m
      std::min(kConvergedShare * bar / (h * h), kConvergedAcceleration);
  if (static_cast<int>(work.s.size()) != memory) {
    work.s.assign(memory, Vector());
    work.y.assign(memory, Vector());
    work.rho.assign(memory, 0.0);
    work.alpha.assign(memory, 0.0);
    work.forget();
  }
  auto worst_of = [&](const Vector& r) {
    double worst = 0.0;
    for (Index d = 0; d < dofs.count; ++d) {
      worst = std::max(worst, std::abs(r[d]) / mass[d]);
    }
    return worst;
  };
  Vector& g = work.g;
  potential.gradient(g);
  double e = potential.energy();
  counts.energies += 1;
  int landings = 0;
  auto found = [&] {
    if (landings < kMostLandingRounds && potential.add_new_touches()) {
      landings += 1;
      potential.gradient(g);
      e = potential.energy();
      return false;
    }
    return true;
  };
  for (int iteration = 0; iteration < kMostIterations; ++iteration) {
    if (iteration > 0 && worst_of(g) <= converged && found()) {
      return true;
    }
    counts.iterations += 1;
    stop_if_asked();
    // The direction, −H g, by L-BFGS's two loops about the constant matrix's solve.
    Vector& q = work.q;
    q = g;
    for (int k = 0, at = work.newest; k < work.pairs; ++k, at = (at + memory - 1) % memory) {
      work.alpha[at] = work.rho[at] * work.s[at].dot(q);
      q -= work.alpha[at] * work.y[at];
    }
    Vector& r = work.r;
    potential.precondition(q, r);
    for (int k = 0, at = (work.newest - work.pairs + 1 + memory) % memory; k < work.pairs;
         ++k, at = (at + 1) % memory) {
      const double beta = work.rho[at] * work.y[at].dot(r);
      r += (work.alpha[at] - beta) * work.s[at];
    }
    Vector& direction = work.direction;
    direction = -r;
    double slope = g.dot(direction);
    if (slope >= 0.0) {  // not downhill: the pairs mislead; start again from the constant matrix
      work.forget();
      potential.precondition(g, r);
      direction = -r;
      slope = g.dot(direction);
      if (slope >= 0.0) {
        return false;
      }
    }
    // Backtracking from the whole step until the energy falls by enough.
    work.from = x;
    double step = 1.0;
    bool accepted = false;
    for (int halving = 0; halving <= kMostHalvings; ++halving) {
      for (std::size_t i = 0; i < n; ++i) {
        const Index d = dofs.first_dof[i];
        if (d >= 0) {
          x[i] = work.from[i] + step * Vec3(direction.segment<3>(d));
        }
      }
      const double trial = potential.energy();
      counts.energies += 1;
      const bool rounding = std::abs(trial - e) <= kEnergyRounding * std::abs(e);
      if (rounding || trial <= e + kSufficientDecrease * step * slope) {
        e = trial;
        accepted = true;
        break;
      }
      step *= 0.5;
    }
    if (!accepted) {
      x = work.from;
      return false;
    }
    if (potential.join_new_touches()) {
      e = potential.energy();
      work.forget();
    }
    Vector& g_new = work.g_new;
    potential.gradient(g_new);
    // The curvature pair, kept where it is one (sᵀy > 0: the energy curves up along the move).
    const int next = (work.newest + 1) % memory;
    work.s[next] = step * direction;
    work.y[next] = g_new - g;
    const double curvature = work.s[next].dot(work.y[next]);
    if (curvature > 1e-12 * work.s[next].norm() * work.y[next].norm()) {
      work.rho[next] = 1.0 / curvature;
      work.newest = next;
      work.pairs = std::min(work.pairs + 1, memory);
    }
    std::swap(g, g_new);
  }
  return false;
}

}  // namespace dinam
