#pragma once
// From a resin density (0..1 over the frame) to a stencil that can be cut: a square cell grid,
// one centred square of resin per cell with the cell's density as its area share. Squares
// smaller than the minimum feature are left out, and gaps narrower than it are closed (the cell
// is filled), so every piece and every gap of the stencil is at least that wide.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "membra/model/pattern.hpp"
#include "membra/model/pattern_spec.hpp"

namespace membra {

struct StencilLayout {
  double cell = 0.02;          // m, pitch of the cell grid (frame coordinates)
  double min_feature = 0.004;  // m, the narrowest piece or gap the stencil may have
  // "squares" (a square per cell, below) or "darts" (resin everywhere but a few wedges of bare
  // latex, for domes: dart_layout.hpp), and how many darts.
  std::string kind = "squares";
  int darts = 6;
  // Darts: their centres (m, target coordinates from the footprint's centre); empty: the centre.
  std::vector<Vec2> centres = {};
  bool auto_centres = false;  // darts: the centres are where the target's curvature peaks
  // Darts of either kind (one piece of resin whose darts' scale a search moves).
  bool has_darts() const { return kind != "squares"; }
};

// One piece of a laid-out stencil: a rectangle of its cell's shape, centred in the cell.
struct StencilSquare {
  Vec2 centre = Vec2::Zero();  // m, frame coordinates
  Vec2 cell = Vec2::Zero();    // m, the cell's sides
  double scale = 1.0;          // the piece's sides over the cell's (1: a filled cell)
  int face = +1;               // the face it is laid on (+1 top, -1 bottom; resin_face.hpp)
  bool operator==(const StencilSquare&) const = default;
};

struct Stencil {
  PatternPtr pattern;        // nullptr when no cell gets resin
  PatternSpec spec;          // its description (the squares as polygons), when not empty
  double resin_share = 0.0;  // of the frame area inside the outline
  int pieces = 0;            // squares of resin
  // From layout_stencil: its pieces, and the area of the cells inside the outline.
  std::vector<StencilSquare> squares;
  double outline_area = 0.0;  // m^2
  // A stencil not made of squares (darts) with resin on both faces: the bottom face's (`spec`
  // and `pattern` are then the top's, either may be empty).
  PatternSpec spec_bottom = {};
  PatternPtr pattern_bottom = nullptr;

  // Pieces laid on the bottom face: squares, or a darts stencil's bottom part.
  int pieces_bottom() const;
};

// `density(p)` at each cell centre p (frame coordinates, m); cells whose centre is not
// `inside` (the sheet's outline on the frame) stay empty. Throws std::invalid_argument when the
// cell is narrower than twice the minimum feature (then no density but 0 or 1 is possible).
Stencil layout_stencil(const std::function<double(const Vec2&)>& density, const Box2& frame,
                       const StencilLayout& layout,
                       const std::function<bool(const Vec2&)>& inside = {});

// A stencil of the given squares (corners in frame coordinates, m): one polygon each.
Stencil stencil_of(const std::vector<std::array<Vec2, 4>>& squares);
// The stencil of laid-out pieces within cells of `outline_area` (its resin share over that).
Stencil stencil_of(const std::vector<StencilSquare>& squares, double outline_area);

}  // namespace membra
