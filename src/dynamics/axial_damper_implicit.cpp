#include "dynamics/axial_damper_implicit.hpp"

#include <tuple>
#include <utility>

#include "dynamics/broken.hpp"
#include "dynamics/state.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

// body(a, b, c, e) for every bar that damps (not broken, c > 0): its nodes, its damper's
// coefficient and its direction at x_n.
template <class Body>
void for_each_damped_bar(const Model& model, const State& state, const std::vector<Vec3>& x_start,
                         const Body& body) {
  for (Index bar = 0; bar < model.bar_count(); ++bar) {
    const double c = model.bar_damping[bar];
    if (c == 0.0 || is_broken(state.bar_broken, bar)) {
      continue;
    }
    const Index a = model.bar_nodes[2 * bar];
    const Index b = model.bar_nodes[2 * bar + 1];
    body(a, b, c, Vec3((x_start[b] - x_start[a]).normalized()));
  }
}

}  // namespace

void add_axial_damper_hessian(const Model& model, const State& state, const FreeDofs& dofs,
                              const std::vector<Vec3>& x_start, double h,
                              std::vector<Eigen::Triplet<double>>& triplets) {
  if (!model.any_bar_damping) {
    return;
  }
  for_each_damped_bar(model, state, x_start, [&](Index a, Index b, double c, const Vec3& e) {
    const Eigen::Matrix3d block = (c / h) * e * e.transpose();
    for (const auto& [p, q, sign] : {std::tuple{a, a, 1.0}, std::tuple{b, b, 1.0},
                                     std::tuple{a, b, -1.0}, std::tuple{b, a, -1.0}}) {
      const Index dp = dofs.first_dof[p];
      const Index dq = dofs.first_dof[q];
      if (dp < 0 || dq < 0) {
        continue;
      }
      for (int r = 0; r < 3; ++r) {
        for (int s = 0; s < 3; ++s) {
          triplets.emplace_back(dp + r, dq + s, sign * block(r, s));
        }
      }
    }
  });
}

void add_axial_damper_support_pull(const Model& model, const State& state, const FreeDofs& dofs,
                                   const std::vector<Vec3>& x_start,
                                   const std::vector<Vec3>& x_base, double h,
                                   Eigen::VectorXd& force) {
  if (!model.any_bar_damping || model.pin_motions.empty()) {
    return;
  }
  for_each_damped_bar(model, state, x_start, [&](Index a, Index b, double c, const Vec3& e) {
    for (const auto& [free, pinned] : {std::pair{a, b}, std::pair{b, a}}) {
      const Index d = dofs.first_dof[free];
      if (d < 0 || dofs.first_dof[pinned] >= 0) {
        continue;
      }
      // −c ((v_free − v_pinned)·e) e: the pinned end's share, with v_pinned = Δx_p / h.
      force.segment<3>(d) += ((c / h) * e.dot(state.x[pinned] - x_base[pinned])) * e;
    }
  });
}

}  // namespace dinam
