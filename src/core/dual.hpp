#pragma once
// Forward-mode dual numbers: a value and its gradient with respect to N seeded inputs, carried
// through arithmetic by the chain rule. The force kernels are templates on their scalar, so the
// very code that computes a spring's forces in double also gives, in Dual<3 × nodes>, the
// forces' derivatives with respect to every coordinate of the spring's nodes: its stiffness
// matrix, exactly the Jacobian of the forces the step uses (no second formula to keep in step).
//
// Only what the kernels use is defined. Comparisons look at the value alone, so a kernel's
// selects choose the same branch as in double, and each branch is differentiated as written.
#include <Eigen/Core>
#include <array>
#include <cmath>

namespace dinam {

template <int N>
struct Dual {
  double value = 0.0;
  std::array<double, N> gradient{};  // ∂value/∂input_k

  Dual() = default;
  Dual(double v) : value(v) {}  // NOLINT(google-explicit-constructor): constants mix freely

  // The k-th of the N inputs, at value v.
  static Dual input(double v, int k) {
    Dual d(v);
    d.gradient[static_cast<std::size_t>(k)] = 1.0;
    return d;
  }

  Dual& operator+=(const Dual& b) {
    value += b.value;
    for (int k = 0; k < N; ++k) {
      gradient[k] += b.gradient[k];
    }
    return *this;
  }
  Dual& operator-=(const Dual& b) {
    value -= b.value;
    for (int k = 0; k < N; ++k) {
      gradient[k] -= b.gradient[k];
    }
    return *this;
  }
  Dual& operator*=(const Dual& b) { return *this = *this * b; }
  Dual& operator/=(const Dual& b) { return *this = *this / b; }

  friend Dual operator-(const Dual& a) {
    Dual r(-a.value);
    for (int k = 0; k < N; ++k) {
      r.gradient[k] = -a.gradient[k];
    }
    return r;
  }
  friend Dual operator+(Dual a, const Dual& b) { return a += b; }
  friend Dual operator-(Dual a, const Dual& b) { return a -= b; }
  friend Dual operator*(const Dual& a, const Dual& b) {
    Dual r(a.value * b.value);
    for (int k = 0; k < N; ++k) {
      r.gradient[k] = a.gradient[k] * b.value + a.value * b.gradient[k];
    }
    return r;
  }
  friend Dual operator/(const Dual& a, const Dual& b) {
    const double inverse = 1.0 / b.value;
    Dual r(a.value * inverse);
    for (int k = 0; k < N; ++k) {
      r.gradient[k] = (a.gradient[k] - r.value * b.gradient[k]) * inverse;
    }
    return r;
  }
  // With a constant: no product of gradients to form.
  friend Dual operator*(double a, const Dual& b) {
    Dual r(a * b.value);
    for (int k = 0; k < N; ++k) {
      r.gradient[k] = a * b.gradient[k];
    }
    return r;
  }
  friend Dual operator*(const Dual& a, double b) { return b * a; }

  friend bool operator<(const Dual& a, const Dual& b) { return a.value < b.value; }
  friend bool operator>(const Dual& a, const Dual& b) { return a.value > b.value; }
  friend bool operator<=(const Dual& a, const Dual& b) { return a.value <= b.value; }
  friend bool operator>=(const Dual& a, const Dual& b) { return a.value >= b.value; }
  friend bool operator==(const Dual& a, const Dual& b) { return a.value == b.value; }
  friend bool operator!=(const Dual& a, const Dual& b) { return a.value != b.value; }

  // The functions the kernels call unqualified (`using std::sqrt; sqrt(x)`), found by ADL.
  friend Dual sqrt(const Dual& a) {
    Dual r(std::sqrt(a.value));
    const double half_inverse = r.value > 0.0 ? 0.5 / r.value : 0.0;
    for (int k = 0; k < N; ++k) {
      r.gradient[k] = a.gradient[k] * half_inverse;
    }
    return r;
  }
  friend Dual abs(const Dual& a) { return a.value < 0.0 ? -a : a; }
  // |a| with the sign of b: ±a, so its derivative is ±a's.
  friend Dual copysign(const Dual& a, const Dual& b) {
    return std::signbit(a.value) == std::signbit(b.value) ? a : -a;
  }
  friend Dual floor(const Dual& a) { return Dual(std::floor(a.value)); }
};

// The value of a double or a Dual, to compare with a threshold or to print.
inline double value_of(double x) {
  return x;
}
template <int N>
double value_of(const Dual<N>& x) {
  return x.value;
}

}  // namespace dinam

// Eigen's vectors of Dual (the kernels' 3-vectors) need its traits.
template <int N>
struct Eigen::NumTraits<dinam::Dual<N>> : Eigen::NumTraits<double> {
  using Real = dinam::Dual<N>;
  using NonInteger = dinam::Dual<N>;
  using Nested = dinam::Dual<N>;
  using Literal = dinam::Dual<N>;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = N + 1,
    AddCost = N + 1,
    MulCost = 3 * N + 1
  };
};
