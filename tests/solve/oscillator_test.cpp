// Spring-mass oscillator: period, convergence order and energy behaviour of every integrator.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "membra/model/forces.hpp"
#include "membra/solve/integrator.hpp"

namespace membra {
namespace {

constexpr double kMass = 0.2, kStiffness = 50.0, kRest = 1.0, kAmplitude = 0.1;
const double kOmega = std::sqrt(kStiffness / kMass);
const double kPeriod = 2.0 * std::numbers::pi / kOmega;

// A particle on a spring whose other end is pinned at the origin, displaced along x.
Model oscillator() {
  Model m;
  const int anchor = m.add_particle(1.0, Vec3::Zero());
  const int bob = m.add_particle(kMass, Vec3(kRest, 0, 0));
  m.pin(anchor);
  m.springs.add(anchor, bob, kRest, kStiffness, 0.0, SpringFamily::stretch);
  return m;
}

State displaced(const Model& m) {
  State s = State::at_rest(m);
  s.x(0, 1) += kAmplitude;
  return s;
}

// Phase-space error |(dx, dv / w)| at t = 5.125 periods (an eighth past a turning point, where
// neither first-order term of symplectic Euler vanishes), against x = A cos(w t). (Position alone
// would hide the phase error at the turning points.)
double error_at_five_periods(const std::string& method, double dt) {
  const Model m = oscillator();
  State s = displaced(m);
  auto integ = make_integrator(method);
  const long n = std::lround(5.125 * kPeriod / dt);
  for (long i = 0; i < n; ++i) integ->step(m, s, dt);
  const double dx = (s.x(0, 1) - kRest) - kAmplitude * std::cos(kOmega * s.time);
  const double dv = s.v(0, 1) + kAmplitude * kOmega * std::sin(kOmega * s.time);
  return std::hypot(dx, dv / kOmega);
}

TEST(Oscillator, Rk4PeriodMatchesTwoPiRootMOverK) {
  const Model m = oscillator();
  State s = displaced(m);
  auto rk4 = make_rk4();
  const double dt = kPeriod / 2000.0;
  // Downward zero crossings of the displacement, located by linear interpolation (the
  // displacement is nearly linear there, so the interpolation error is O(dt^3)).
  std::vector<double> crossings;
  double prev = s.x(0, 1) - kRest;
  while (crossings.size() < 6) {
    const double t0 = s.time;
    rk4->step(m, s, dt);
    const double cur = s.x(0, 1) - kRest;
    if (prev > 0.0 && cur <= 0.0) crossings.push_back(t0 + dt * prev / (prev - cur));
    prev = cur;
  }
  const double period = (crossings.back() - crossings.front()) / 5.0;
  EXPECT_NEAR(period / kPeriod, 1.0, 1e-6);
}

struct OrderCase {
  const char* method;
  double expected_ratio;  // 2^order
  double lo, hi;
};

class IntegratorOrder : public ::testing::TestWithParam<OrderCase> {};

TEST_P(IntegratorOrder, ErrorFallsWithTheMethodsOrderWhenTheStepHalves) {
  const auto c = GetParam();
  const double h = 0.05 / kOmega;  // w h = 0.05
  const double ratio = error_at_five_periods(c.method, h) / error_at_five_periods(c.method, h / 2);
  EXPECT_GT(ratio, c.lo) << c.method;
  EXPECT_LT(ratio, c.hi) << c.method;
}

INSTANTIATE_TEST_SUITE_P(AllIntegrators, IntegratorOrder,
                         ::testing::Values(OrderCase{"rk4", 16.0, 12.0, 20.0},
                                           OrderCase{"symplectic_euler", 2.0, 1.6, 2.4}),
                         [](const auto& p) { return std::string(p.param.method); });

// Largest |E(t) - E(0)| over 20 undamped periods.
double max_energy_drift(const std::string& method, double dt) {
  const Model m = oscillator();
  State s = displaced(m);
  auto integ = make_integrator(method);
  const double e0 = potential_energy(m, s.x) + kinetic_energy(m, s.v);
  double drift = 0.0;
  const long n = std::lround(20.0 * kPeriod / dt);
  for (long i = 0; i < n; ++i) {
    integ->step(m, s, dt);
    drift = std::max(drift, std::abs(potential_energy(m, s.x) + kinetic_energy(m, s.v) - e0));
  }
  return drift / e0;
}

TEST(Oscillator, Rk4DriftsLessEnergyThanSymplecticEuler) {
  const double dt = 0.05 / kOmega;
  const double rk4 = max_energy_drift("rk4", dt);
  const double se = max_energy_drift("symplectic_euler", dt);
  EXPECT_LT(rk4, se);
  // Orders of magnitude: RK4 loses ~ (w h)^6 / 144 per step; symplectic Euler's energy error
  // oscillates with amplitude ~ w h / 2.
  EXPECT_LT(rk4, 1e-6);
  EXPECT_NEAR(se, 0.025, 0.01);
}

TEST(Oscillator, PinnedParticleNeverMoves) {
  for (auto name : integrator_names()) {
    const Model m = oscillator();
    State s = displaced(m);
    auto integ = make_integrator(name);
    for (int i = 0; i < 100; ++i) integ->step(m, s, 1e-3);
    EXPECT_EQ(s.x.col(0).norm(), 0.0) << name;
    EXPECT_EQ(s.v.col(0).norm(), 0.0) << name;
  }
}

TEST(Oscillator, GlobalDampingDecaysAmplitudeAtRateDOverTwo) {
  Model m = oscillator();
  m.velocity_damping = 0.4;  // D, 1/s
  State s = displaced(m);
  auto rk4 = make_rk4();
  const double dt = kPeriod / 1000.0;
  // Energy envelope decays as exp(-D t); compare at whole periods (same phase).
  for (int i = 0; i < 10000; ++i) rk4->step(m, s, dt);
  const double e = potential_energy(m, s.x) + kinetic_energy(m, s.v);
  const double e0 = 0.5 * kStiffness * kAmplitude * kAmplitude;
  EXPECT_NEAR(std::log(e / e0) / s.time, -0.4, 0.01);
}

}  // namespace
}  // namespace membra
