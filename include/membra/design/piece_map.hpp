#pragma once
// Stage 3's design variables: the sizes of a stencil's pieces (design/stencil_layout.hpp). Each
// piece that is neither a filled cell nor absent gets one variable t in [0, 1], its sides
// running from the minimum feature (t = 0) to the cell less the minimum feature (t = 1), so
// every value can be cut. An element takes as its resin fraction the exact share of its
// footprint on the frame inside the pieces (a spring's segment, the mean of a bending element's
// two: model/elements/) — the shares that impregnation samples at 16 and 8 points, so that the
// branch followed
// here is, within that sampling, the real stencil's. The share moves continuously while a
// piece's edge crosses a segment, and jumps when the edge passes a segment parallel to it; the
// gradient is that of the continuous part (docs/inverse_design.md, stage 3).
#include <utility>
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
  // Element i of element set k (Model::for_each_set order: 0 springs, 1 added springs, 2 bending).
  Coverage element_coverage(size_t k, int i, const Eigen::VectorXd& t) const;

 private:
  struct Segment {
    Vec2 a, b;      // m, frame coordinates
    double weight;  // its share of the element's fraction
  };
  struct Element {
    std::vector<Segment> segments;  // none: the design places no resin on it
    std::vector<int> near;          // the squares whose cell meets the element's bounding box
  };
  Coverage coverage(const Element& element, const Eigen::VectorXd& t) const;
  double scale(int square, const Eigen::VectorXd& t) const;

  std::vector<StencilSquare> squares_;
  double outline_area_ = 0.0;
  std::vector<int> variable_;    // per square: its variable, or -1 (a filled cell, fixed)
  std::vector<int> free_;        // per variable: its square
  std::vector<double> lo_, hi_;  // per variable: the scale at t = 0 and t = 1
  std::vector<std::vector<Element>> elements_;  // per element set, per element
};

}  // namespace membra
