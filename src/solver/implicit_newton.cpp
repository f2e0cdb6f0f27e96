#include "solver/implicit_newton.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/stop_request.hpp"
#include "solver/stiffness_matrix.hpp"
#include "solver/sufficient_decrease.hpp"
#include "solver/truncated_cg.hpp"

namespace dinam {
namespace {

using Vector = Eigen::VectorXd;

// Newton iterations a step may take before it is split.
constexpr int kMostIterations = 25;
// The Newton step's linear solve (truncated conjugate gradients preconditioned with the kept
// factorisation): the share of the gradient its residual is cut to, and the iterations it may
// take before the Hessian is factorised again. (An iteration costs a solve with the factor and a
// force evaluation, about 1.3 ms on the Wuson; a factorisation 60 to 130 ms.)
constexpr double kForcing = 0.01;
constexpr int kMostSolveIterations = 30;
// The trust region (Nocedal and Wright, Algorithm 4.1): shrunk to a quarter of the step tried
// where the energy fell by less than a quarter of what the quadratic model promised, doubled
// where it fell by more than three quarters of it at the region's edge.
constexpr double kPoorAgreement = 0.25;
constexpr double kGoodAgreement = 0.75;
// Regions tried at one iterate before the step is split (each a quarter of the last at most:
// 16 take it below 1e-9 of the first).
constexpr int kMostShrinks = 16;
// Times a step's solve goes on with the friction of nodes that landed within it
// (ImplicitFriction::add_new_touches): a node that lands where the last round had it above the
// plane needs another.
constexpr int kMostLandingRounds = 3;

}  // namespace

bool minimise_step(std::vector<Vec3>& x, const FreeDofs& dofs, const Vector& mass, double h,
                   double bar, const StepPotential& potential, bool& factored, double& radius,
                   NewtonCounts& counts, NewtonWorkspace& work) {
  const std::size_t n = x.size();
  const double converged =  // m/s², a node's |g|/m
      std::min(kConvergedShare * bar / (h * h), kConvergedAcceleration);
  const double small_step = converged * h * h;  // m
  Vector& g = work.g;
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
  // The longest move of a node in a step over the free dofs, m.
  auto longest_move = [&](const Vector& step) {
    double longest = 0.0;
    for (Index d = 0; d < dofs.count; d += 3) {
      longest = std::max(longest, step.segment<3>(d).norm());
    }
    return longest;
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
  double solve_target = 0.0;  // m/s², the path's end for the gradient it is built for
  Vector& g_moved = work.g_moved;
  std::vector<Vec3>& x_iterate = work.x_iterate;
  auto hessian_times = [&](const Vector& v, Vector& product) {
    const double furthest = longest_move(v);
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
  auto solved = [&](const Vector& r) { return worst_of(r) <= solve_target; };
  // The Newton step's path (truncated_cg.hpp), preconditioned with the kept factorised Hessian P
  // (an earlier iterate's or step's; exactly H for a linear problem, where the first iteration
  // is the whole step). A node that met the ground or a spring that turned since P was
  // factorised is an eigenvalue of P⁻¹H away from 1, which costs the solve an iteration or two,
  // where factorising again costs dozens. The path ends once its residual is kForcing of g's (an
  // inexact Newton step, which still converges fast) or below half the convergence tolerance; at
  // a direction of negative curvature (the structure buckles there), which it follows to the
  // region's edge; at the region's edge; or after kMostSolveIterations, where P no longer
  // describes H and is factorised again at the next iterate.
  TruncatedCg& path = work.path;
  const TruncatedCg::Operators operators{
      .hessian_times = hessian_times,
      .precondition = potential.precondition,
      .solved = solved,
  };
  // The factorised Hessian is kept from iterate to iterate and from step to step (assembling and
  // factorising it costs far more than a force), and factorised again where the solve above
  // exhausts its iterations, where no region at an iterate gives a step, and where h changes.
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
  // The trust region's radius, in P's norm |s|_P = √(sᵀ P s) (whose square is twice the energy a
  // step would store in the kept Hessian), carried from the step before: no smaller than the norm
  // of the first preconditioned gradient step P⁻¹g, which is the whole Newton step where P is H,
  // so that a step the model describes well is never cut by a region that an earlier, harder
  // step shrank.
  bool region_set = false;
  std::vector<Vec3>& from = work.from;
  for (int iteration = 0; iteration < kMostIterations; ++iteration) {
    // At least one Newton step: from x̂ alone a slow motion would pass the test unsolved (a
    // linear step is exact after one).
    if (iteration > 0 && worst_of(g) <= converged && found()) {
      return true;
    }
    counts.iterations += 1;
    stop_if_asked();  // a large model's iteration takes seconds
    if (!factored && !factor_here()) {
      return false;
    }
    solve_target = std::max(kForcing * worst_of(g), 0.5 * converged);
    counts.solve_iterations += path.build(g, radius, !region_set, kMostSolveIterations, operators);
    radius = path.region();
    region_set = true;
    // Steps within ever smaller regions, until one lowers the energy by enough of what the model
    // promised.
    from = x;
    bool accepted = false;
    TruncatedCg::Point& point = work.point;
    double longest = 0.0;
    for (int shrink = 0; shrink < kMostShrinks && !accepted; ++shrink) {
      path.at(radius, point);
      longest = longest_move(point.step);
      for (std::size_t i = 0; i < n; ++i) {
        const Index d = dofs.first_dof[i];
        if (d >= 0) {
          x[i] = from[i] + Vec3(point.step.segment<3>(d));
        }
      }
      const double trial = potential.energy();
      const double promised = -point.model;
      // Energies equal within rounding say nothing of the model: the step is taken, the region
      // kept, and the step judged by the out-of-balance force.
      const bool rounding = std::abs(trial - e) <= kEnergyRounding * std::abs(e);
      const double agreement = promised > 0.0 ? (e - trial) / promised : -1.0;
      if (!rounding && agreement < kPoorAgreement) {
        radius = kPoorAgreement * point.norm;
      } else if (!rounding && agreement > kGoodAgreement && point.at_edge) {
        radius *= 2.0;
      }
      if (rounding || agreement > kSufficientDecrease) {
        e = trial;
        accepted = true;
      } else if (longest <= small_step) {
        break;  // no step this short lowers the energy the rounding can see
      }
    }
    if (!accepted) {
      x = from;
      // A step this short that lowers no energy the rounding can see: the residual left is
      // rounding's (a stiff bar's axial force, to a fraction of a picometre), not an unsolved step.
      if (path.solved() && longest <= small_step) {
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
    if (!point.at_edge && path.solved() && longest <= small_step && found()) {
      return true;
    }
    fresh = false;
    if (path.exhausted()) {
      factored = false;
    }
  }
  return false;
}

}  // namespace dinam
