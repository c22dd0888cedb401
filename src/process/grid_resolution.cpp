#include "membra/process/grid_resolution.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

#include "membra/geometry/size_field.hpp"
#include "membra/process/prepare.hpp"

namespace membra {
namespace {

constexpr int kLargestResolution = 4096;  // the schema's bound on sheet.resolution

std::string coarse_message(const CoarseGrid& c) {
  char text[512];
  const bool reachable = std::max(c.resolution[0], c.resolution[1]) <= kLargestResolution;
  std::snprintf(text, sizeof text,
                "sheet.resolution: the narrowest resin piece or latex gap, %.3g mm across at "
                "(%.4g, %.4g) mm on the natural sheet, is %.2g grid spacings (%.3g mm) across; "
                "the lattice draws it as a staircase and the form may change with the grid",
                c.width * 1e3, c.at.x() * 1e3, c.at.y() * 1e3, c.width / c.spacing,
                c.spacing * 1e3);
  std::string out = text;
  if (reachable)
    out += "; sheet.resolution [" + std::to_string(c.resolution[0]) + ", " +
           std::to_string(c.resolution[1]) + "] gives it " + std::to_string(int(kAcross)) +
           " spacings";
  else
    out += "; no lattice resolution gives it " + std::to_string(int(kAcross)) + " spacings";
  return out + ", or \"model\": \"continuum\" meshes it";
}

}  // namespace

std::optional<CoarseGrid> coarse_grid(const Scene& scene) {
  if (scene.model != SheetModel::lattice || scene.benchmark_n > 0) return std::nullopt;
  const GridSpec& g = scene.grid;
  const double spacing = std::max(g.width / (g.nx - 1), g.height / (g.ny - 1));
  // The pattern outlines on the natural sheet, with the sheet's own outline: a gap to the rim
  // counts as a gap.
  ContinuumSpec spec;
  try {
    spec = continuum_spec(scene);
  } catch (const std::exception&) {
    return std::nullopt;  // advice only: a pattern the tracer refuses is the run's to report
  }
  if (spec.features.empty()) return std::nullopt;
  std::vector<Polyline2> boundaries(spec.features.begin(), spec.features.end());
  boundaries.push_back(sheet_outline(spec.width, spec.height, spec.disk, spec.mesh.tolerance));
  // Narrow along two grid spacings of its boundary at least: a pinch point is not a feature.
  const NarrowestFeature n =
      narrowest_feature(boundaries, std::min(1e-3, 0.25 * spacing), 2.0 * spacing);
  if (!(n.width > 0.0) || n.width >= kAcross * spacing) return std::nullopt;
  CoarseGrid c{n.width, n.at, spacing, {}, {}};
  const double needed = n.width / kAcross;
  c.resolution = {static_cast<int>(std::ceil(g.width / needed)) + 1,
                  static_cast<int>(std::ceil(g.height / needed)) + 1};
  c.message = coarse_message(c);
  return c;
}

}  // namespace membra
