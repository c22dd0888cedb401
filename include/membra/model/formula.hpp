#pragma once
// A scalar formula of the paper position, such as "1 + 0.3*sin(pi*x/200)^2", parsed once and
// evaluated many times (muparser). Variables, all in mm: x, y (paper coordinates, origin at the
// sheet's lower-left corner), r (distance from `center`), w and h (the sheet's size); constants
// pi and e; and `a`, a free parameter (a preset's amplitude). Functions: muparser's (sin, cos,
// tan, exp, log, sqrt, abs, min, max, ...), with ^ for powers.
#include <memory>
#include <string>

#include "membra/core/vec.hpp"

namespace membra {

struct FormulaContext {
  Vec2 size{0.2, 0.2};    // sheet w, h, m
  Vec2 center{0.1, 0.1};  // origin of r, m
  double a = 0.0;         // free parameter
};

class Formula {
 public:
  // Parses `expression`. Throws std::invalid_argument with muparser's message (and the position
  // of the problem) if it does not parse, uses an unknown name, or yields more than one value.
  Formula(const std::string& expression, const FormulaContext& context);
  ~Formula();
  Formula(const Formula&) = delete;
  Formula& operator=(const Formula&) = delete;

  // The value at paper position p (m). Not thread-safe: one Formula per thread.
  double operator()(const Vec2& p) const;
  const std::string& expression() const { return expression_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string expression_;
};

}  // namespace membra
