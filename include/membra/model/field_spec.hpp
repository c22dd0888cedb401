#pragma once
// A scalar field's description over the paper sheet (docs/scene.md, "Fields"): a number, a
// formula, a named preset with its amplitude, or a grey image with a value range. make_field()
// builds the function; the description is kept so that a scene can be written back.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "membra/core/grey_image.hpp"
#include "membra/model/formula.hpp"

namespace membra {

using ScalarField = std::function<double(const Vec2&)>;  // at a paper position, m

struct FieldSpec {
  enum class Kind { constant, formula, preset, image };
  Kind kind = Kind::constant;
  double value = 1.0;      // constant
  std::string formula;     // formula: the expression (variables in mm, formula.hpp)
  std::string preset;      // preset: sin2_x | sin2_y | radial
  double amplitude = 0.3;  // preset: its `a`
  // image: grey 0..1 mapped onto [range lo, range hi], bilinear
  std::string file;  // as the scene names it (relative to the scene)
  GreyImage image;
  Vec2 range = Vec2(0.0, 1.0);
  std::optional<Vec2> origin, size;  // placement on the paper, m (default: the whole sheet)
};

// The formula a preset stands for (with `a` its amplitude), or "" if there is no such preset.
std::string field_preset(const std::string& name);

// The field a description stands for, in the context's sheet size and centre. Throws
// std::invalid_argument with muparser's message for a formula that does not parse.
ScalarField make_field(const FieldSpec& spec, const FormulaContext& context);

}  // namespace membra
