#pragma once
// Steihaug–Toint truncated conjugate gradients: a Newton step in a trust region. Minimises the
// quadratic model
//   m(s) = gᵀs + ½ sᵀHs
// from s = 0 by conjugate gradients preconditioned with P (a factorised positive definite
// approximation of H), and ends where the residual g + Hs is small enough (the Newton step),
// where a direction of negative curvature turns up (H is indefinite: the structure buckles), or
// where the iterate leaves the region |s|_P ≤ Δ. The iterates' norms in P, |s|²_P = sᵀPs, grow
// monotonically along the path and come from recurrences of the solve (Conn, Gould and Toint,
// Trust-Region Methods, §7.5.1), so the region costs no product with P. A direction of negative
// curvature is kept to be followed to whatever edge is asked.
//
// The path is kept: where the energy disagrees with the model and the region shrinks, the step
// in the smaller region is cut from the same path without new products with H (each costs a
// force evaluation).
#include <Eigen/Core>
#include <vector>

#include "core/function_ref.hpp"

namespace dinam {

class TruncatedCg {
 public:
  using Vector = Eigen::VectorXd;
  // Referred to, not kept: each must outlive the build it is given to.
  struct Operators {
    FunctionRef<void(const Vector& v, Vector& product)> hessian_times;  // H v
    FunctionRef<void(const Vector& r, Vector& solved)> precondition;    // P⁻¹ r
    // Whether a residual r = g + Hs is small enough to end the path (the caller knows the g it
    // built the path for).
    FunctionRef<bool(const Vector& r)> solved;
  };
  // A point of the path.
  struct Point {
    Vector step;           // s
    double model = 0.0;    // m(s)
    double norm = 0.0;     // |s|_P
    bool at_edge = false;  // cut at the region's edge rather than at the path's end
  };

  // Builds the path from s = 0 for the gradient g, ending as above, once it passes the region's
  // edge, or after `most` products with H. The region is `radius`, or with `widen` at least
  // |P⁻¹g|_P, the whole Newton step's norm where P is H (region() says which). Returns the
  // products taken. Allocates only where g's size or `most` is larger than any before.
  int build(const Vector& g, double radius, bool widen, int most, const Operators& operators);

  // The path's point at |s|_P = radius, or its end where the path ends inside (a path that stopped
  // at its region's edge ends there), into `point` (its step reused).
  void at(double radius, Point& point) const;
  Point at(double radius) const {
    Point point;
    at(radius, point);
    return point;
  }

  double region() const { return region_; }
  bool solved() const { return solved_; }        // ended at the Newton step
  bool exhausted() const { return exhausted_; }  // ended after `most` products

 private:
  // The path's piece from s_k along d_k: s_{k+1} = s_k + length d_k (length ∞: negative
  // curvature, followed to the edge), with what a point s_k + τ d_k needs:
  // |s_k + τ d_k|²_P = s_norm² + 2τ s_dot_d + τ² d_norm², m = model + τ slope + ½ τ² curvature.
  struct Segment {
    Vector direction;
    double length = 0.0;
    double s_norm2 = 0.0, s_dot_d = 0.0, d_norm2 = 0.0;  // in P
    double model = 0.0, slope = 0.0, curvature = 0.0;
  };
  Segment& next_segment();

  std::vector<Segment> segments_;  // the first used_ are the path
  std::size_t used_ = 0;
  double region_ = 0.0;
  bool solved_ = false;
  bool exhausted_ = false;
  bool past_edge_ = false;  // stopped where it left the region
  Vector residual_, preconditioned_, direction_, product_;
};

}  // namespace dinam
