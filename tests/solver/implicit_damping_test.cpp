// The numerical damping and the period error of the implicit integrator's two schemes on a clamped
// steel cantilever vibrating freely in its first mode, at 8 to 64 steps a period (some 10² to 10³
// times central differences' bound), against the closed forms of each scheme on a linear
// oscillator: the first mode of a small vibration is one. In the mode's coordinates u = q − i q̇/ω
// a step multiplies u by backward Euler's 1/(1 − iωh), and, once its start has died out, by
// BDF2's principal root (2 + √(1 + 2iωh))/(3 − 2iωh). |u| falls by the root's modulus a step and
// turns by its argument, so the period the motion shows is 2π/arg per step.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>

#include "dynamics/stability.hpp"
#include "model/model.hpp"
#include "solver/implicit_integrator.hpp"
#include "solver/natural_modes.hpp"
#include "solver_support.hpp"
#include "stepping/time_step.hpp"

namespace dinam {
namespace {

// The first mode's coordinates u = q − i q̇/ω, q = φᵀ M (x − x0) and q̇ = φᵀ M v, φ mass-normalised.
std::complex<double> modal(const Model& model, const NaturalMode& mode, double omega,
                           const State& state) {
  double q = 0.0;
  double q_dot = 0.0;
  for (Index i = 0; i < model.node_count(); ++i) {
    const double m = model.node_mass[i];
    q += m * mode.shape[i].dot(state.x[i] - model.node_initial_x[i]);
    q_dot += m * mode.shape[i].dot(state.velocity[i]);
  }
  return {q, -q_dot / omega};
}

struct Vibration {
  double loss_per_period;  // of the amplitude, over N steps (one period of the true motion)
  double phase_per_step;   // rad
};

// The cantilever thrown in its first (vertical) mode and run for `periods` periods of N steps; the
// loss and the turn are measured over the last period, when BDF2's start has long died out.
Vibration vibrate(const std::string& integrator, int steps_per_period, int periods,
                  double* omega_out = nullptr) {
  const Model model = test::clamped_cantilever(20, "gravity: [0, 0, 0]\nintegrator: " + integrator);
  State rest = make_state(model, false);
  const std::vector<NaturalMode> modes = natural_modes(model, rest, test::static_forces(), 2);
  const NaturalMode& mode = modes[0].mass_share.z() > modes[1].mass_share.z() ? modes[0] : modes[1];
  const double omega = std::sqrt(mode.omega_squared);
  if (omega_out != nullptr) {
    *omega_out = omega;
  }
  const double h = test::kTwoPi / (omega * steps_per_period);
  // Central differences' bound is 7.7 µs here: these steps are 18 (64 a period) to 290 (8 a
  // period) times longer.
  EXPECT_GT(h, 15.0 * critical_timestep(model));
  State state = initial_state(model, h);
  // A tip amplitude of about 0.1 mm: the geometry's nonlinearity, of the order of the slope
  // squared (1e-8), is far below what is measured.
  const double speed = 1e-4 * omega / mode.shape.back().norm();
  for (Index i = 0; i < model.node_count(); ++i) {
    state.velocity[i] = speed * mode.shape[i];
  }
  ImplicitIntegrator integrator_run(model);
  integrator_run.advance(state, h, static_cast<std::int64_t>(periods - 1) * steps_per_period);
  const std::complex<double> start = modal(model, mode, omega, state);
  double turned = 0.0;
  std::complex<double> u = start;
  for (int n = 0; n < steps_per_period; ++n) {
    integrator_run.advance(state, h, 1);
    const std::complex<double> next = modal(model, mode, omega, state);
    turned += std::arg(next / u);
    u = next;
  }
  EXPECT_EQ(integrator_run.stats().splits, 0);
  return {1.0 - std::abs(u) / std::abs(start), turned / steps_per_period};
}

std::complex<double> backward_euler_root(double omega_h) {
  return 1.0 / std::complex<double>(1.0, -omega_h);
}
std::complex<double> bdf2_root(double omega_h) {
  const std::complex<double> z(0.0, omega_h);
  return (2.0 + std::sqrt(1.0 + 2.0 * z)) / (3.0 - 2.0 * z);
}

// The model's first frequency is Euler–Bernoulli's to its discretisation error (−0.21 % at 20
// bars: tests/dynamics/beam_test.cpp), so what is measured here is the schemes' own error.
TEST(ImplicitDamping, TheCantileverLosesPerPeriodWhatEachSchemesClosedFormSays) {
  std::printf(
      "steps a period | backward Euler: loss a period, closed form | period error, closed "
      "form | BDF2: loss, closed form | period error, closed form\n");
  double omega = 0.0;
  double euler_period_error_before = 0.0;
  double bdf2_period_error_before = 0.0;
  for (const int steps : {8, 16, 32, 64}) {
    const double omega_h = test::kTwoPi / steps;
    const Vibration euler = vibrate("implicit", steps, 2, &omega);
    const Vibration bdf2 = vibrate("implicit_bdf2", steps, 3);
    const std::complex<double> re = backward_euler_root(omega_h);
    const std::complex<double> rb = bdf2_root(omega_h);
    const double euler_loss = 1.0 - std::pow(std::abs(re), steps);
    const double bdf2_loss = 1.0 - std::pow(std::abs(rb), steps);
    // The period error: the shown period over the true one, less 1.
    const double euler_period = omega_h / std::arg(re) - 1.0;
    const double bdf2_period = omega_h / std::arg(rb) - 1.0;
    std::printf("%14d | %.4f %.4f | %+.4f %+.4f | %.5f %.5f | %+.4f %+.4f\n", steps,
                euler.loss_per_period, euler_loss, omega_h / euler.phase_per_step - 1.0,
                euler_period, bdf2.loss_per_period, bdf2_loss, omega_h / bdf2.phase_per_step - 1.0,
                bdf2_period);
    // Newton's method stops within 1e-5 of a bar of the solution a step (about 5e-7 m against an
    // amplitude of 1e-4 m at the tip, spread over the mode): the measured losses agree with the
    // closed forms to a few 1e-4 of the amplitude.
    EXPECT_NEAR(euler.loss_per_period, euler_loss, 2e-3) << steps << " steps";
    EXPECT_NEAR(bdf2.loss_per_period, bdf2_loss, 2e-3) << steps << " steps";
    EXPECT_NEAR(euler.phase_per_step, std::arg(re), 1e-3 * std::arg(re)) << steps << " steps";
    EXPECT_NEAR(bdf2.phase_per_step, std::arg(rb), 1e-3 * std::arg(rb)) << steps << " steps";
    // Both schemes' period errors are of second order in the step (halving it divides the error
    // by 3.2 to 3.9 on the way to 4), and BDF2 loses far less amplitude: its loss a period is of
    // third order in the step, backward Euler's of first.
    const double euler_period_error = omega_h / euler.phase_per_step - 1.0;
    const double bdf2_period_error = omega_h / bdf2.phase_per_step - 1.0;
    if (steps > 8) {
      EXPECT_GT(euler_period_error_before / euler_period_error, 3.0);
      EXPECT_GT(bdf2_period_error_before / bdf2_period_error, 3.0);
    }
    euler_period_error_before = euler_period_error;
    bdf2_period_error_before = bdf2_period_error;
    EXPECT_LT(bdf2.loss_per_period, 0.35 * euler.loss_per_period);
  }
  const double euler_bernoulli = 1.8751 * 1.8751 * std::sqrt(8000.0 / 0.785);
  EXPECT_NEAR(omega / euler_bernoulli, 1.0, 0.005);
}

}  // namespace
}  // namespace dinam
