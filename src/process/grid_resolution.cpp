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
  // Rounded down: a feature just narrower than two spacings must not read "2 grid spacings".
  const double across = std::floor(c.width / c.spacing * 100.0) / 100.0;
  std::snprintf(text, sizeof text,
                "sheet.resolution: the narrowest resin piece or latex gap, %.3g mm across at "
                "(%.4g, %.4g) mm on the natural sheet, is %.3g grid spacings (%.3g mm) across; "
                "the lattice draws it as a staircase and the form may change with the grid",
                c.width * 1e3, c.at.x() * 1e3, c.at.y() * 1e3, across, c.spacing * 1e3);
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
  // Samples every quarter spacing, at most 1 mm and at least 0.05 mm apart (a finer grid than
  // that is beyond any resolution named).
  const auto narrowest_at = [&](double h) {
    return narrowest_feature(boundaries, std::clamp(0.25 * h, 5e-5, 1e-3), 2.0 * h);
  };
  const NarrowestFeature n = narrowest_at(spacing);
  if (!(n.width > 0.0) || n.width >= kAcross * spacing) return std::nullopt;
  CoarseGrid c{n.width, n.at, spacing, {}, {}};
  // The resolution that resolves it; on that finer grid a shorter feature may count, so the
  // grid named is checked in turn (a few rounds; each only refines).
  double needed = n.width / kAcross;
  for (int round = 0; round < 4; ++round) {
    c.resolution = {static_cast<int>(std::min(std::ceil(g.width / needed) + 1, 1e6)),
                    static_cast<int>(std::min(std::ceil(g.height / needed) + 1, 1e6))};
    if (std::max(c.resolution[0], c.resolution[1]) > kLargestResolution) break;  // none will do
    const double h = std::max(g.width / (c.resolution[0] - 1), g.height / (c.resolution[1] - 1));
    const NarrowestFeature finer = narrowest_at(h);
    if (!(finer.width > 0.0) || finer.width >= kAcross * h) break;
    needed = std::min(needed, finer.width / kAcross) * 0.999;
  }
  c.message = coarse_message(c);
  return c;
}

}  // namespace membra
