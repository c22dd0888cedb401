#pragma once
// The continuum sheet seen from above (docs/deformation.md, "Cuts after the sheet has moved"):
// which point of the natural sheet lies under a point of the plane, where the sheet is now. A
// cut drawn on a released sheet is drawn on this view, as the lattice's cuts are; pulled back
// through it, it becomes a boundary the natural sheet's mesh can follow. Where layers of a
// folded sheet overlap, the topmost one is seen (the one a laser from above meets first).
#include <optional>
#include <string>
#include <vector>

#include "membra/geometry/triangle_locator.hpp"
#include "membra/model/membrane.hpp"

namespace membra {

class TopView {
 public:
  // The continuum sheet's triangles at their present positions. Throws std::invalid_argument for
  // a lattice sheet or one without triangles.
  explicit TopView(const Membrane& m);

  // The natural-sheet (paper) point under plane point q, interpolated over the topmost triangle
  // holding q (its barycentric weights within -1e-9); none where no triangle lies under q.
  std::optional<Vec2> paper_at(const Vec2& q) const;

  // The box the sheet covers seen from above.
  const Vec2& lo() const { return lo_; }
  const Vec2& hi() const { return hi_; }
  // For messages: " (seen from above, the sheet now lies within x .. to .. mm, y .. to .. mm)".
  std::string extent() const;

 private:
  const Membrane& m_;
  TriangleLocator locator_;
  Vec2 lo_, hi_;
};

// A polyline drawn on the view, pulled back to the natural sheet: every segment sampled at most
// `spacing` apart, each sample's paper point; where the line runs off the sheet, the end is the
// crossing of the sheet's edge (found by bisection). Throws std::invalid_argument when no sample
// lies on the sheet or the line leaves and comes back (it would cut two slits).
std::vector<Vec2> pull_back_line(const TopView& view, const std::vector<Vec2>& line,
                                 double spacing);

// A closed polygon drawn on the view, pulled back: its edges sampled at most `spacing` apart.
// Throws std::invalid_argument when a sample lies off the sheet.
std::vector<Vec2> pull_back_polygon(const TopView& view, const std::vector<Vec2>& polygon,
                                    double spacing);

}  // namespace membra
