#include "solver/truncated_cg.hpp"
#include "core/stop_request.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dinam {

TruncatedCg::Segment& TruncatedCg::next_segment() {
  return segments_[used_++];
}

int TruncatedCg::build(const Vector& g, double radius, bool widen, int most,
                       const Operators& operators) {
  // Room for the longest path, each direction of g's size: a step's solves then allocate nothing.
  if (segments_.size() < static_cast<std::size_t>(most)) {
    segments_.resize(static_cast<std::size_t>(most));
  }
  for (Segment& segment : segments_) {
    segment.direction.resize(g.size());
  }
  used_ = 0;
  solved_ = exhausted_ = past_edge_ = false;
  region_ = radius;
  residual_ = g;  // g + H s at s = 0
  // Nothing out of balance at all (a body in free flight without gravity, where x̂ is exact): the
  // step is zero. (A residual however small is solved for: a slow motion would otherwise stop
  // where x̂ put it.)
  if (residual_.isZero(0.0)) {
    solved_ = true;
    return 0;
  }
  operators.precondition(residual_, preconditioned_);
  direction_ = -preconditioned_;
  double along = residual_.dot(preconditioned_);  // rᵀP⁻¹r
  if (widen) {
    region_ = std::max(radius, std::sqrt(along));
  }
  double s_norm2 = 0.0;    // |s_k|²_P
  double s_dot_d = 0.0;    // s_kᵀ P d_k
  double d_norm2 = along;  // |d_k|²_P
  double model = 0.0;      // m(s_k)
  for (int k = 0; k < most; ++k) {
    if (k % 64 == 63) {
      stop_if_asked();
    }
    operators.hessian_times(direction_, product_);
    const double curvature = direction_.dot(product_);
    Segment& segment = next_segment();
    segment.direction = direction_;
    segment.s_norm2 = s_norm2;
    segment.s_dot_d = s_dot_d;
    segment.d_norm2 = d_norm2;
    segment.model = model;
    segment.slope = residual_.dot(direction_);
    segment.curvature = curvature;
    if (!(curvature > 0.0)) {
      segment.length = std::numeric_limits<double>::infinity();
      return k + 1;
    }
    const double length = along / curvature;
    segment.length = length;
    const double s_norm2_next = s_norm2 + 2.0 * length * s_dot_d + length * length * d_norm2;
    if (s_norm2_next > region_ * region_) {
      past_edge_ = true;  // a point on the edge is cut from this segment
      return k + 1;
    }
    model += length * segment.slope + 0.5 * length * length * curvature;
    residual_.noalias() += length * product_;
    if (operators.solved(residual_)) {
      solved_ = true;
      return k + 1;
    }
    operators.precondition(residual_, preconditioned_);
    const double along_next = residual_.dot(preconditioned_);
    const double beta = along_next / along;
    s_dot_d = beta * (s_dot_d + length * d_norm2);
    d_norm2 = along_next + beta * beta * d_norm2;
    s_norm2 = s_norm2_next;
    direction_ = -preconditioned_ + beta * direction_;
    along = along_next;
  }
  exhausted_ = true;
  return most;
}

void TruncatedCg::at(double radius, Point& point) const {
  // A path that stopped at its region's edge is known no further.
  if (past_edge_) {
    radius = std::min(radius, region_);
  }
  point.step.setZero(residual_.size());  // the zero step where the path has no segment
  point.model = 0.0;
  point.norm = 0.0;
  point.at_edge = false;
  for (std::size_t k = 0; k < used_; ++k) {
    const Segment& segment = segments_[k];
    const double length = segment.length;
    const double end_norm2 =
        segment.s_norm2 + 2.0 * length * segment.s_dot_d + length * length * segment.d_norm2;
    if (std::isfinite(length) && end_norm2 <= radius * radius) {
      point.step += length * segment.direction;
      point.model =
          segment.model + length * segment.slope + 0.5 * length * length * segment.curvature;
      point.norm = std::sqrt(end_norm2);
      continue;
    }
    // τ ≥ 0 where |s_k + τ d_k|_P = radius: the positive root of d² τ² + 2 (s·d) τ + s² − Δ².
    const double c = segment.s_norm2 - radius * radius;
    const double tau =
        (-segment.s_dot_d +
         std::sqrt(std::max(segment.s_dot_d * segment.s_dot_d - segment.d_norm2 * c, 0.0))) /
        segment.d_norm2;
    point.step += tau * segment.direction;
    point.model = segment.model + tau * segment.slope + 0.5 * tau * tau * segment.curvature;
    point.norm = radius;
    point.at_edge = true;
    return;
  }
}

}  // namespace dinam
