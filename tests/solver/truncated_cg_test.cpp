// Steihaug's truncated conjugate gradients (src/solver/truncated_cg.hpp) on small quadratics
// whose answers come from dense linear algebra: the Newton step −H⁻¹g, the model gᵀs + ½ sᵀHs
// evaluated directly, and the norm √(sᵀPs) of the preconditioner.
#include "solver/truncated_cg.hpp"

#include <gtest/gtest.h>

#include <functional>

#include <Eigen/Dense>

namespace dinam {
namespace {

using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;

// Products with H and solves with P, counted; the path ends where the residual is 1e-12 of the
// gradient's, `size`.
struct Quadratic {
  Matrix h, p;
  int products = 0;
  double size = 1.0;
  // The operators refer to these, which live as long as the quadratic.
  std::function<void(const Vector&, Vector&)> times = [this](const Vector& v, Vector& product) {
    ++products;
    product = h * v;
  };
  std::function<void(const Vector&, Vector&)> solve = [this](const Vector& r, Vector& solved) {
    solved = p.ldlt().solve(r);
  };
  std::function<bool(const Vector&)> small = [this](const Vector& r) {
    return r.norm() <= 1e-12 * size;
  };
  TruncatedCg::Operators operators() {
    return {.hessian_times = times, .precondition = solve, .solved = small};
  }
  double model(const Vector& g, const Vector& s) const { return g.dot(s) + 0.5 * s.dot(h * s); }
  double norm(const Vector& s) const { return std::sqrt(s.dot(p * s)); }
};

// A symmetric positive definite matrix of size n with eigenvalues from 1 to `condition`.
Matrix definite(int n, double condition, unsigned seed) {
  std::srand(seed);
  const Eigen::HouseholderQR<Matrix> qr(Matrix::Random(n, n));
  const Matrix q = qr.householderQ();
  const Vector eigenvalues = Vector::LinSpaced(n, 1.0, condition);
  return q * eigenvalues.asDiagonal() * q.transpose();
}

// Exact arithmetic's bound on conjugate gradients: the Newton step in at most n products; with
// P = H, in one.
TEST(TruncatedCg, EndsAtTheNewtonStepWhereTheRegionHoldsIt) {
  const int n = 8;
  Quadratic q{definite(n, 100.0, 1), Matrix::Identity(n, n)};
  const Vector g = Vector::LinSpaced(n, -1.0, 2.0);
  const Vector newton = -q.h.ldlt().solve(g);
  TruncatedCg path;
  const int products = path.build(g, 1e3 * newton.norm(), false, 30, q.operators());
  EXPECT_TRUE(path.solved());
  EXPECT_LE(products, n);
  const TruncatedCg::Point end = path.at(path.region());
  EXPECT_FALSE(end.at_edge);
  EXPECT_LE((end.step - newton).norm(), 1e-10 * newton.norm());
  EXPECT_NEAR(end.model, q.model(g, end.step), 1e-12 * std::abs(end.model));
  EXPECT_NEAR(end.norm, q.norm(end.step), 1e-10 * end.norm);

  Quadratic exact{q.h, q.h};
  TruncatedCg one;
  EXPECT_EQ(one.build(g, 1e3 * newton.norm(), false, 30, exact.operators()), 1);
  EXPECT_TRUE(one.solved());
  EXPECT_LE((one.at(one.region()).step - newton).norm(), 1e-10 * newton.norm());
}

// Within a region smaller than the Newton step, the point is on the edge in P's norm (the
// recurrences against √(sᵀPs) with a P that is not the identity), the model there is the
// quadratic's, and it lowers the model, more in a larger region.
TEST(TruncatedCg, CutsThePathAtTheEdgeInThePreconditionersNorm) {
  const int n = 10;
  Quadratic q{definite(n, 1e3, 2), definite(n, 30.0, 3)};
  const Vector g = Vector::Ones(n);
  const Vector newton = -q.h.ldlt().solve(g);
  const double newton_norm = q.norm(newton);
  TruncatedCg path;
  path.build(g, 10.0 * newton_norm, false, 30, q.operators());
  ASSERT_TRUE(path.solved());
  double last_model = 0.0;
  for (const double share : {0.05, 0.2, 0.5, 0.9}) {
    const TruncatedCg::Point point = path.at(share * newton_norm);
    EXPECT_TRUE(point.at_edge);
    EXPECT_NEAR(q.norm(point.step), share * newton_norm, 1e-9 * newton_norm) << share;
    EXPECT_NEAR(point.model, q.model(g, point.step), 1e-9 * std::abs(point.model)) << share;
    EXPECT_LT(point.model, last_model) << share;
    last_model = point.model;
  }
  // Built with the region itself, the path stops at its edge with the same point.
  TruncatedCg stopped;
  stopped.build(g, 0.2 * newton_norm, false, 30, q.operators());
  EXPECT_FALSE(stopped.solved());
  EXPECT_FALSE(stopped.exhausted());
  EXPECT_LE((stopped.at(0.2 * newton_norm).step - path.at(0.2 * newton_norm).step).norm(),
            1e-12 * newton.norm());
}

// An indefinite H (a structure that buckles): along the first direction of negative curvature the
// model falls without bound, and the step follows it to the region's edge, whatever the radius.
// `widen` makes the region at least the preconditioned gradient step, |P⁻¹g|_P.
TEST(TruncatedCg, FollowsNegativeCurvatureToTheEdge) {
  const int n = 6;
  Matrix h = definite(n, 10.0, 4);
  h(0, 0) -= 30.0;  // now indefinite, and the gradient below has a part along it
  ASSERT_LT(Eigen::SelfAdjointEigenSolver<Matrix>(h).eigenvalues().minCoeff(), 0.0);
  Quadratic q{h, Matrix::Identity(n, n)};
  const Vector g = Vector::Ones(n);
  TruncatedCg widened;
  widened.build(g, 1e-3, true, 30, q.operators());
  EXPECT_DOUBLE_EQ(widened.region(), g.norm());  // |P⁻¹g|_P = |g| with P = I
  TruncatedCg path;
  path.build(g, 1e6, false, 30, q.operators());
  EXPECT_FALSE(path.solved());
  EXPECT_FALSE(path.exhausted());
  for (const double radius : {0.5, 5.0, 50.0}) {
    const TruncatedCg::Point point = path.at(radius);
    EXPECT_TRUE(point.at_edge) << radius;
    EXPECT_NEAR(point.step.norm(), radius, 1e-9 * radius) << radius;
    EXPECT_NEAR(point.model, q.model(g, point.step), 1e-9 * std::abs(point.model)) << radius;
    EXPECT_LT(point.model, 0.0) << radius;
  }
}

// Nothing out of balance: no product, a zero step, solved.
TEST(TruncatedCg, AZeroGradientIsAZeroStep) {
  Quadratic q{definite(4, 5.0, 5), Matrix::Identity(4, 4)};
  TruncatedCg path;
  EXPECT_EQ(path.build(Vector::Zero(4), 1.0, true, 30, q.operators()), 0);
  EXPECT_TRUE(path.solved());
  const TruncatedCg::Point point = path.at(1.0);
  EXPECT_TRUE(point.step.isZero(0.0));
  EXPECT_EQ(point.model, 0.0);
}

}  // namespace
}  // namespace dinam
