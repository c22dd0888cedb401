// Formulas of the paper position: values, variables, and errors a user can act on.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "membra/model/formula.hpp"

namespace membra {
namespace {

TEST(Formula, EvaluatesTheSinSquaredFieldInMillimetres) {
  const Formula f("1 + 0.3*sin(pi*x/200)^2", {});
  EXPECT_NEAR(f(Vec2(0.1, 0.0)), 1.3, 1e-12);  // x = 100 mm
  EXPECT_NEAR(f(Vec2(0.0, 0.05)), 1.0, 1e-12);
  EXPECT_NEAR(f(Vec2(0.05, 0.0)), 1.0 + 0.3 * 0.5, 1e-12);
}

TEST(Formula, KnowsRadiusSheetSizeAndParameter) {
  FormulaContext c;
  c.size = Vec2(0.3, 0.1);
  c.center = Vec2(0.01, 0.02);
  c.a = 2.5;
  const Formula f("r + w + h + a + e", c);
  EXPECT_NEAR(f(Vec2(0.04, 0.06)), 50.0 + 300.0 + 100.0 + 2.5 + std::numbers::e, 1e-9);
}

TEST(Formula, RejectsSyntaxErrorsUnknownNamesAndSeveralValues) {
  auto message = [](const std::string& text) {
    try {
      Formula f(text, {});
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(message("1 +* x").find("position"), std::string::npos) << message("1 +* x");
  EXPECT_NE(message("1 + z").find("\"z\""), std::string::npos) << message("1 + z");
  EXPECT_NE(message("x, y").find("gives 2 values"), std::string::npos) << message("x, y");
  EXPECT_NE(message("").find("cannot parse"), std::string::npos);
}

}  // namespace
}  // namespace membra
