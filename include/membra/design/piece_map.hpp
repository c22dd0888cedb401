#pragma once
// Stage 3's design variables: the sizes of a stencil's pieces (design/stencil_layout.hpp). Each
// piece that is neither a filled cell nor absent gets one variable t in [0, 1], its sides
// running from the minimum feature (t = 0) to the cell less the minimum feature (t = 1), so
// every value can be cut. A spring or bending element takes as its resin fraction the share of
// its box — its span on the frame, widened by half a grid spacing each side where it has no
// width — that the pieces cover: the sampled share of the element's segment (what a run uses)
// jumps when a piece's edge passes a row of particles, the box's share moves continuously, so
// the released form is differentiable in the sizes (docs/inverse_design.md, stage 3).
#include <vector>

#include "membra/design/resin_map.hpp"
#include "membra/design/stencil_layout.hpp"

namespace membra {

class PieceMap final : public ResinMap {
 public:
  // `m`: the sheet impregnated everywhere on its frame, `frame_x` its particles there.
  PieceMap(const Stencil& stencil, double min_feature, const Membrane& m, const Points& frame_x);
  Eigen::Index size() const override { return static_cast<Eigen::Index>(free_.size()); }
  void apply(Membrane& m, const Eigen::VectorXd& t) const override;
  Eigen::VectorXd pull_back(const Membrane& m, const Eigen::VectorXd& t, const Points& x,
                            const Points& w) const override;

  // The variables of the stencil's own pieces, and the stencil of variables t.
  Eigen::VectorXd variables() const;
  Stencil stencil(const Eigen::VectorXd& t) const;

  // Each element's fraction at t and its derivatives (piece variable, d fraction / dt).
  struct Coverage {
    double fraction = 0.0;
    std::vector<std::pair<int, double>> rate;
  };
  Coverage spring_coverage(int s, const Eigen::VectorXd& t) const;
  Coverage bend_coverage(int e, const Eigen::VectorXd& t) const;

 private:
  struct Box {
    Vec2 lo, hi;
  };
  Coverage coverage(const Box& box, const std::vector<int>& near, const Eigen::VectorXd& t) const;
  double scale(int square, const Eigen::VectorXd& t) const;

  std::vector<StencilSquare> squares_;
  double outline_area_ = 0.0;
  std::vector<int> variable_;    // per square: its variable, or -1 (a filled cell, fixed)
  std::vector<int> free_;        // per variable: its square
  std::vector<double> lo_, hi_;  // per variable: the scale at t = 0 and t = 1
  std::vector<Box> spring_box_, bend_box_;
  std::vector<std::vector<int>> spring_near_, bend_near_;  // squares whose cell meets the box
  std::vector<bool> added_;                                // springs not part of the sheet
};

}  // namespace membra
