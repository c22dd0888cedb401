#include "membra/model/formula.hpp"

#include <numbers>
#include <stdexcept>

#include <muParser.h>

#include "membra/core/units.hpp"

namespace membra {

// The parser holds pointers to the variables, so both live together and never move.
struct Formula::Impl {
  mu::Parser parser;
  double x = 0.0, y = 0.0, r = 0.0, w = 0.0, h = 0.0, a = 0.0;
  Vec2 center;
};

Formula::Formula(const std::string& expression, const FormulaContext& context)
    : impl_(std::make_unique<Impl>()), expression_(expression) {
  Impl& m = *impl_;
  m.w = context.size.x() / units::mm;
  m.h = context.size.y() / units::mm;
  m.a = context.a;
  m.center = context.center;
  try {
    m.parser.DefineVar("x", &m.x);
    m.parser.DefineVar("y", &m.y);
    m.parser.DefineVar("r", &m.r);
    m.parser.DefineVar("w", &m.w);
    m.parser.DefineVar("h", &m.h);
    m.parser.DefineVar("a", &m.a);
    m.parser.DefineConst("pi", std::numbers::pi);
    m.parser.DefineConst("e", std::numbers::e);
    m.parser.SetExpr(expression);
    m.parser.Eval();  // parsing is lazy: this reports syntax errors and unknown names now
    if (m.parser.GetNumResults() != 1)
      throw std::invalid_argument("'" + expression + "' gives " +
                                  std::to_string(m.parser.GetNumResults()) +
                                  " values; a formula gives one");
  } catch (const mu::Parser::exception_type& e) {
    throw std::invalid_argument("cannot parse '" + expression + "': " + e.GetMsg());
  }
}

Formula::~Formula() = default;

double Formula::operator()(const Vec2& p) const {
  Impl& m = *impl_;
  m.x = p.x() / units::mm;
  m.y = p.y() / units::mm;
  m.r = (p - m.center).norm() / units::mm;
  try {
    return m.parser.Eval();
  } catch (const mu::Parser::exception_type& e) {
    throw std::invalid_argument("cannot evaluate '" + expression_ + "': " + e.GetMsg());
  }
}

}  // namespace membra
