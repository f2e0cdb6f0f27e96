// The turbulence of the wind against what its definition (dynamics/wind_field.hpp,
// docs/scene-format.md) says of it: the RMS of each component, the correlation length, and
// advection by the mean wind; and the sine it is evaluated with against the C library's.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "core/fast_sine.hpp"
#include "dynamics/wind_field.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

WindLoad turbulent_wind(std::uint32_t seed, double amplitude, double scale, const Vec3& mean) {
  WindLoad wind;
  wind.field.enabled = true;
  wind.field.velocity = mean;
  wind.field.turbulence = amplitude;
  wind.field.turbulence_scale = scale;
  wind.field.seed = seed;
  wind.waves = make_turbulence_waves(seed, scale);
  return wind;
}

// The turbulent part of the wind at x and t.
Vec3 gust_at(const WindLoad& wind, const Vec3& x, double t) {
  return wind_at(wind, turbulence_phases(wind, t), uniform_wind_velocity(wind.field, t), x) -
         wind.field.velocity;
}

TEST(FastSine, AgreesWithTheLibrarySine) {
  // Rounding in the reduction and in Horner's rule, and the Taylor remainder (2.5e-16): a few
  // units in the last place of a value of magnitude 1, wherever the angle lies up to 1e5 rad.
  std::mt19937 rng(3);
  double worst = 0.0;
  for (const double range : {1.0, 10.0, 1e3, 1e5}) {
    std::uniform_real_distribution<double> angle(-range, range);
    for (int i = 0; i < 200000; ++i) {
      const double theta = angle(rng);
      worst = std::max(worst, std::abs(fast_sin(theta) - std::sin(theta)));
    }
  }
  EXPECT_LT(worst, 1e-15);
  // Exact where the sine is: 0 at 0, and odd.
  EXPECT_EQ(fast_sin(0.0), 0.0);
  EXPECT_EQ(fast_sin(-1.234), -fast_sin(1.234));
}

// A point computed in a SIMD lane among 37 and the same point alone (wind_at: the loop's
// scalar path) give the same bits, as fast_sin promises.
TEST(Turbulence, PointsInSimdLanesGiveTheBitsOfOnePoint) {
  const WindLoad wind = turbulent_wind(7, 1.2, 0.8, Vec3(6, 0, 0));
  const double t = 3.7;
  const TurbulencePhases phases = turbulence_phases(wind, t);
  const Vec3 uniform = uniform_wind_velocity(wind.field, t);
  constexpr int kPoints = 37;  // not a multiple of the vector width: the loop's tail too
  std::vector<double> x(kPoints), y(kPoints), z(kPoints), u(kPoints), v(kPoints), w(kPoints);
  for (int p = 0; p < kPoints; ++p) {
    x[static_cast<std::size_t>(p)] = 0.31 * p - 4.0;
    y[static_cast<std::size_t>(p)] = std::sin(p) * 2.0;
    z[static_cast<std::size_t>(p)] = 1.0 + 0.07 * p;
  }
  wind_at_points(wind, phases, uniform, x.data(), y.data(), z.data(), kPoints, u.data(), v.data(),
                 w.data());
  for (std::size_t p = 0; p < kPoints; ++p) {
    const Vec3 one = wind_at(wind, phases, uniform, Vec3(x[p], y[p], z[p]));
    EXPECT_EQ(one, Vec3(u[p], v[p], w[p])) << "point " << p;
  }
}

TEST(Turbulence, EachComponentHasTheRmsAskedFor) {
  // Over a region of 50 scales and 20 s, the mean square of a sine of a wave is ½ and the cross
  // terms of different waves vanish: the RMS of a component is the amplitude. With 30 000
  // samples the estimate of a mean square varies by about 1 %; 3 % is three of those.
  const double amplitude = 1.5;
  const WindLoad wind = turbulent_wind(11, amplitude, 0.8, Vec3(5, 0, 0));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> place(-20.0, 20.0);
  std::uniform_real_distribution<double> time(0.0, 20.0);
  Vec3 sum_squares = Vec3::Zero();
  constexpr int kSamples = 30000;
  for (int i = 0; i < kSamples; ++i) {
    const Vec3 g = gust_at(wind, Vec3(place(rng), place(rng), place(rng)), time(rng));
    sum_squares += g.cwiseProduct(g);
  }
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(std::sqrt(sum_squares[c] / kSamples) / amplitude, 1.0, 0.03) << "component " << c;
  }
}

// The expected autocorrelation at separation r, over the ensemble of waves the definition draws
// and over directions of the separation: a wave of wavenumber k correlates as cos(k·r), whose mean
// over isotropic directions of r is sin(κr)/(κr) for |k| = κ, and κ is uniform on
// [π/L, 3π/L] (2π/L × U(0.5, 1.5)). By the midpoint rule on 2 000 intervals.
double expected_correlation(double r, double scale) {
  const double low = std::numbers::pi / scale;
  const double high = 3.0 * std::numbers::pi / scale;
  constexpr int kIntervals = 2000;
  double sum = 0.0;
  for (int i = 0; i < kIntervals; ++i) {
    const double kappa = low + (high - low) * (i + 0.5) / kIntervals;
    sum += std::sin(kappa * r) / (kappa * r);
  }
  return sum / kIntervals;
}

TEST(Turbulence, CorrelationFallsOffOverTheScale) {
  // Pairs of places a distance r apart in random directions, over 60 seeds (720 waves): the
  // measured correlation against the ensemble's. The seeds' waves are a finite sample of the
  // ensemble, and the places of the directions and points: within 0.004 of it in this run; 0.03.
  const double scale = 0.8;
  std::mt19937 rng(9);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> place(-10.0, 10.0);
  for (const double r : {0.1, 0.2, 0.4}) {
    double product = 0.0;
    double square = 0.0;
    for (std::uint32_t seed = 1; seed <= 60; ++seed) {
      const WindLoad wind = turbulent_wind(seed, 1.0, scale, Vec3::Zero());
      const TurbulencePhases phases = turbulence_phases(wind, 0.0);
      for (int i = 0; i < 200; ++i) {
        const Vec3 direction = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
        const Vec3 x(place(rng), place(rng), place(rng));
        const Vec3 a = wind_at(wind, phases, Vec3::Zero(), x);
        const Vec3 b = wind_at(wind, phases, Vec3::Zero(), x + r * direction);
        product += a.dot(b);
        square += 0.5 * (a.squaredNorm() + b.squaredNorm());
      }
    }
    EXPECT_NEAR(product / square, expected_correlation(r, scale), 0.03) << "r = " << r;
  }
  // The correlation length, where the ensemble's correlation falls to ½, is about a third of the
  // scale: the noise is smooth over a few centimetres and changes over decimetres.
  EXPECT_NEAR(expected_correlation(0.3 * scale, scale), 0.5, 0.05);
}

TEST(Turbulence, IsCarriedAlongByTheMeanWind) {
  // u(x + s ŵ, t + τ) against u(x, t): the waves are functions of x − w̄ t, so the correlation
  // peaks at s = |w̄| τ, where what is left is each wave's slow drift ω = 0.7 (k + 1) rad/s,
  // k = 0..3: the peak is the mean of cos(ω τ) over the four drifts, 0.928 for τ = 0.2 s. (The
  // drift also moves the peak, by Σ k sin(ωτ) / Σ k² cos(ωτ), about 2 cm here: under the
  // grid's spacing of 5 cm.) Without the shift, the gusts have passed on.
  const double speed = 5.0;
  const double lag = 0.2;
  const WindLoad wind = turbulent_wind(4, 1.0, 0.8, Vec3(speed, 0, 0));
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> place(-20.0, 20.0);
  std::vector<Vec3> places;
  places.reserve(4000);
  for (int i = 0; i < 4000; ++i) {
    places.emplace_back(place(rng), place(rng), place(rng));
  }
  auto correlation = [&](double shift) {
    double product = 0.0;
    double square = 0.0;
    for (const Vec3& x : places) {
      const Vec3 a = gust_at(wind, x, 1.0);
      const Vec3 b = gust_at(wind, x + Vec3(shift, 0, 0), 1.0 + lag);
      product += a.dot(b);
      square += 0.5 * (a.squaredNorm() + b.squaredNorm());
    }
    return product / square;
  };
  double best_shift = 0.0;
  double best = -1.0;
  for (int i = 0; i <= 60; ++i) {
    const double shift = 0.05 * i;
    const double c = correlation(shift);
    if (c > best) {
      best = c;
      best_shift = shift;
    }
  }
  EXPECT_NEAR(best_shift, speed * lag, 0.051);
  double peak = 0.0;
  for (int k = 0; k < kTurbulenceWaves; ++k) {
    peak += std::cos(0.7 * (k + 1) * lag) / kTurbulenceWaves;
  }
  EXPECT_NEAR(best, peak, 0.03);
  EXPECT_LT(correlation(0.0), 0.5);
}

}  // namespace
}  // namespace dinam
