#pragma once
// The element size a pattern-following mesh asks for at each point (docs/model.md, "Meshes that
// follow the pattern"): small across narrow pieces and gaps, growing away from the boundaries.
// Every boundary sample measures the width of the region on each side of it (a ray along its
// normal to the next boundary); it asks for width / elements_across there, and the size grows
// from each sample at the grading rate, capped at max_edge: h(p) = min(max_edge,
// min over samples s of h_s + grading |p - s|), a size that never jumps.
#include <vector>

#include "membra/core/vec.hpp"

namespace membra {

using Polyline2 = std::vector<Vec2>;

struct SizeFieldOptions {
  double max_edge = 0.01;   // m, the size far from any boundary
  int elements_across = 4;  // elements across the narrowest piece or gap
  double grading = 0.3;     // growth of the size per unit distance from a boundary
};

// The narrowest region the boundaries enclose: its width (m) and where it was measured.
struct NarrowestFeature {
  double width = 0.0;
  Vec2 at = Vec2::Zero();
};

// The narrowest region between the closed `boundaries` that is narrow along some length: per
// boundary, the width below which at least `min_length` of it (at most half its perimeter)
// lies, measured as SizeField does at samples `spacing` apart; the least of these. A pinch
// point (a corner close to another boundary, a wedge where a boundary meets the rim) does not
// count, a strip or a gap along a side does. {0, origin} when no boundary faces another. Throws
// std::invalid_argument for spacing <= 0.
NarrowestFeature narrowest_feature(const std::vector<Polyline2>& boundaries, double spacing,
                                   double min_length);

class SizeField {
 public:
  // `boundaries` are closed polygons (the last vertex joins the first) inside `domain`; a
  // polygon of fewer than 3 vertices is ignored. Throws std::invalid_argument for max_edge <= 0,
  // elements_across < 1, grading <= 0 or an empty domain.
  SizeField(const std::vector<Polyline2>& boundaries, const Vec2& domain_min,
            const Vec2& domain_max, const SizeFieldOptions& options);

  // The size at p (m), interpolated on a background grid; clamped into the domain.
  double operator()(const Vec2& p) const;
  double smallest() const { return smallest_; }
  const NarrowestFeature& narrowest() const { return narrowest_; }
  // Triangles a mesh of this size would have (about 4 / (sqrt(3) h^2) per unit area): the
  // memory check before meshing.
  double expected_triangles() const;

  struct Segment {
    Vec2 a, b;
  };

 private:
  struct Source {
    Vec2 at;
    double size;
  };
  std::vector<Source> measure(const std::vector<Polyline2>& boundaries);
  std::vector<Source> densify(const std::vector<Segment>& segs,
                              const std::vector<Source>& measured) const;
  void rasterize(const std::vector<Source>& sources);
  double cell_value(int i, int j) const { return h_[static_cast<size_t>(j) * nx_ + i]; }

  SizeFieldOptions options_;
  Vec2 origin_, extent_;
  double cell_ = 0.0;
  int nx_ = 0, ny_ = 0;
  std::vector<double> h_;
  double smallest_ = 0.0;
  NarrowestFeature narrowest_;
};

}  // namespace membra
