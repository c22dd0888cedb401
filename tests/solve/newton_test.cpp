// The Newton solver's Hessian and its equilibria.
#include <random>

#include <gtest/gtest.h>

#include "membra/model/forces.hpp"
#include "membra/model/sheet.hpp"
#include "membra/solve/newton_solver.hpp"

namespace membra {
namespace {

class NewtonHessian : public ::testing::TestWithParam<bool> {};

// With springs, and with bending alone (its entries are ~1e4x smaller than the springs', so
// checked on their own).
TEST_P(NewtonHessian, MatchesFiniteDifferencesOfTheForces) {
  SheetOptions o;
  o.stretch = o.shear = GetParam();
  Sheet sheet = build_sheet({0.02, 0.02, 5, 5}, o);
  Model m = sheet.model;
  for (auto& l0 : m.springs.rest_length) l0 *= 0.9;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Points x = m.reference;
  for (Eigen::Index i = 0; i < x.size(); ++i) x.data()[i] += 0.001 * u(rng);
  const Eigen::MatrixXd h = Eigen::MatrixXd(potential_hessian(m, x));
  const double step = 1e-7;
  double err = 0.0;
  for (Eigen::Index c = 0; c < x.size(); ++c) {
    Points xp = x, xm = x, fp, fm;
    xp.data()[c] += step;
    xm.data()[c] -= step;
    compute_static_forces(m, xp, fp);
    compute_static_forces(m, xm, fm);
    for (Eigen::Index r = 0; r < x.size(); ++r)
      err = std::max(err, std::abs(-(fp.data()[r] - fm.data()[r]) / (2 * step) - h(r, c)));
  }
  EXPECT_LT(err / h.cwiseAbs().maxCoeff(), 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Springs, NewtonHessian, ::testing::Values(true, false));

}  // namespace
}  // namespace membra
