#include "solver/implicit_newton.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/line_search.hpp"
#include "solver/stiffness_matrix.hpp"

namespace dinam {
namespace {

using Vector = Eigen::VectorXd;

// Newton iterations a step may take before it is split.
constexpr int kMostIterations = 25;
// The line search's least step length before the step is split instead (its sufficient decrease
// is the equilibrium's: line_search.hpp).
constexpr double kLeastLength = 1.0 / 1024;
// The Newton step's linear solve (conjugate gradients preconditioned with the kept factorisation):
// the share of the gradient its residual is cut to, and the iterations it may take before the
// Hessian is factorised again. (An iteration costs a solve with the factor and a force
// evaluation, about 1.3 ms on the Wuson; a factorisation 60 to 130 ms.)
constexpr double kForcing = 0.01;
constexpr int kMostSolveIterations = 30;
// Times a step's solve goes on with the friction of nodes that landed within it
// (ImplicitFriction::add_new_touches): a node that lands where the last round had it above the
// plane needs another.
constexpr int kMostLandingRounds = 3;

// The Newton step s, H s = −g, and how its solve ended.
struct NewtonStep {
  Vector step;
  bool solved = false;     // to the tolerance
  bool exhausted = false;  // stopped at kMostSolveIterations
};

}  // namespace

bool minimise_step(std::vector<Vec3>& x, const FreeDofs& dofs, const Vector& mass, double h,
                   double bar, const StepPotential& potential, bool& factored,
                   NewtonCounts& counts) {
  const std::size_t n = x.size();
  const double converged =  // m/s², a node's |g|/m
      std::min(kConvergedShare * bar / (h * h), kConvergedAcceleration);
  const double small_step = converged * h * h;  // m
  Vector g;
  potential.gradient(g);
  double e = potential.energy();
  // The largest out-of-balance acceleration of a residual, m/s²: what convergence is judged by.
  auto worst_of = [&](const Vector& r) {
    double worst = 0.0;
    for (Index d = 0; d < dofs.count; ++d) {
      worst = std::max(worst, std::abs(r[d]) / mass[d]);
    }
    return worst;
  };
  // H v, the incremental potential's Hessian at x along v, from the gradient there (`g`) and at
  // x + ε v: exact for the inertia and dampers, and to about 1e-7 for the springs (the
  // difference step, √(rounding × extent × bar), balances the gradient's rounding against the
  // springs' curvature over the step).
  double extent = 1.0;
  for (const Vec3& at : x) {
    extent = std::max(extent, at.lpNorm<Eigen::Infinity>());
  }
  const double difference_step =
      std::sqrt(std::numeric_limits<double>::epsilon() * extent * bar);  // m
  Vector g_moved;
  std::vector<Vec3> x_iterate;
  auto hessian_times = [&](const Vector& v, Vector& product) {
    double furthest = 0.0;
    for (Index d = 0; d < dofs.count; d += 3) {
      furthest = std::max(furthest, v.segment<3>(d).norm());
    }
    if (furthest == 0.0) {
      product.setZero(dofs.count);
      return;
    }
    const double epsilon = difference_step / furthest;
    x_iterate = x;
    for (std::size_t i = 0; i < n; ++i) {
      const Index d = dofs.first_dof[i];
      if (d >= 0) {
        x[i] += epsilon * Vec3(v.segment<3>(d));
      }
    }
    potential.gradient(g_moved);
    x = x_iterate;
    product = (g_moved - g) / epsilon;
  };
  // The Newton step s, H s = −g, by conjugate gradients preconditioned with the kept factorised
  // Hessian P (an earlier iterate's or step's; exactly H for a linear problem, where the first
  // iteration is the whole step). A node that met the ground or a spring that turned since P was
  // factorised is an eigenvalue of P⁻¹H away from 1, which costs the solve an iteration or two,
  // where factorising again costs dozens. Stops once the residual is kForcing of g's (an inexact
  // Newton step, which still converges fast) or below half the convergence tolerance; at a
  // direction of negative curvature (the structure is unstable there: the step so far still goes
  // downhill, and the first iteration's P⁻¹(−g) does, P being positive definite); or after
  // kMostSolveIterations, where P no longer describes H and is factorised again at the next
  // iterate.
  Vector residual, preconditioned, direction, product;
  auto newton_step = [&]() {
    NewtonStep result;
    result.step.setZero(dofs.count);
    residual = -g;
    const double target = std::max(kForcing * worst_of(g), 0.5 * converged);
    // Nothing out of balance at all (a body in free flight without gravity, where x̂ is exact):
    // the step is zero, and solved. (A residual however small is solved for: a slow motion would
    // otherwise stop where x̂ put it.)
    if (worst_of(residual) == 0.0) {
      result.solved = true;
      return result;
    }
    preconditioned = potential.precondition(residual);
    direction = preconditioned;
    double along = residual.dot(preconditioned);
    for (int k = 0; k < kMostSolveIterations; ++k) {
      counts.solve_iterations += 1;
      hessian_times(direction, product);
      const double curvature = direction.dot(product);
      if (!(curvature > 0.0)) {
        if (k == 0) {
          result.step = direction;
        }
        return result;
      }
      const double length = along / curvature;
      result.step += length * direction;
      residual -= length * product;
      if (worst_of(residual) <= target) {
        result.solved = true;
        return result;
      }
      preconditioned = potential.precondition(residual);
      const double along_next = residual.dot(preconditioned);
      direction = preconditioned + (along_next / along) * direction;
      along = along_next;
    }
    result.exhausted = true;
    return result;
  };
  // The factorised Hessian is kept from iterate to iterate and from step to step (assembling and
  // factorising it costs far more than a force), and factorised again where the solve above
  // exhausts its iterations, where a step with it finds no descent, and where h changes.
  // `fresh`: it was factorised at this iterate.
  bool fresh = false;
  auto factor_here = [&] {
    counts.factorizations += 1;
    fresh = true;
    return potential.factor();
  };
  // Found, unless a node landed within the step: then its friction joins and the step goes on.
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
    // At least one Newton step: from x̂ alone a slow motion would pass the test unsolved (a
    // linear step is exact after one).
    if (iteration > 0 && worst_of(g) <= converged && found()) {
      return true;
    }
    counts.iterations += 1;
    if (!factored && !factor_here()) {
      return false;
    }
    const NewtonStep newton = newton_step();
    const Vector& step = newton.step;
    double largest = 0.0;  // m, the step's longest move of a node
    for (Index d = 0; d < dofs.count; d += 3) {
      largest = std::max(largest, step.segment<3>(d).norm());
    }
    const double slope = g.dot(step);  // < 0 for a descent direction
    // No descent left to take, and none needed (a structure at rest with nothing moving it: the
    // gradient is zero and so is the step).
    if (slope >= 0.0 && newton.solved && largest <= small_step && found()) {
      return true;
    }
    const std::vector<Vec3> from = x;
    double length = 1.0;
    bool accepted = false;
    while (slope < 0.0 && length >= kLeastLength) {
      for (std::size_t i = 0; i < n; ++i) {
        const Index d = dofs.first_dof[i];
        if (d >= 0) {
          x[i] = from[i] + length * Vec3(step.segment<3>(d));
        }
      }
      const double trial = potential.energy();
      if (trial <= e + kSufficientDecrease * length * slope ||
          std::abs(trial - e) <= kEnergyRounding * std::abs(e)) {
        e = trial;
        accepted = true;
        break;
      }
      length *= 0.5;
    }
    if (!accepted) {
      x = from;
      // A step this short that lowers no energy the rounding can see: the residual left is
      // rounding's (a stiff bar's axial force, to a fraction of a picometre), not an unsolved step.
      if (newton.solved && largest <= small_step) {
        if (found()) {
          return true;
        }
        continue;  // a node landed: solve on with its friction
      }
      if (fresh) {
        return false;  // not even the Hessian of this iterate gives a step: split it
      }
      factored = false;  // a kept Hessian: factorise it here and try again
      continue;
    }
    // Nodes that went below the plane with this step hold by friction from the next iterate on,
    // rather than only once the step has converged without them (which restarted the
    // convergence, once for every round of landings).
    if (potential.join_new_touches()) {
      e = potential.energy();
    }
    potential.gradient(g);
    // A whole Newton step that moved no node further than `small_step`: the next would move them
    // far less.
    if (length == 1.0 && largest <= small_step && newton.solved && found()) {
      return true;
    }
    fresh = false;
    if (newton.exhausted) {
      factored = false;
    }
  }
  return false;
}

}  // namespace dinam
