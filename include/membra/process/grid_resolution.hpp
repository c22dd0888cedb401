#pragma once
// Whether a lattice scene's grid resolves its pattern (docs/forms.md, "When the grid is too
// coarse"): a resin piece or latex gap less than two grid spacings across is a staircase of one
// or two cells, and the form can change with the grid (exp3 is a bowl at 21 x 21, a tube at
// 25 x 25). The check measures the narrowest piece or gap on the natural sheet, as the
// continuum's mesher does, and names a resolution that resolves it.
#include <array>
#include <optional>
#include <string>

#include "membra/core/vec.hpp"
#include "membra/process/scene.hpp"

namespace membra {

struct CoarseGrid {
  double width = 0.0;               // m, the narrowest piece or gap on the natural sheet
  Vec2 at;                          // m, where it was measured (natural sheet)
  double spacing = 0.0;             // m, the grid's larger spacing
  std::array<int, 2> resolution{};  // the sheet.resolution that gives it kAcross spacings
  std::string message;              // "sheet.resolution: ..." for a warning
};

// Spacings a piece or gap needs across.
constexpr double kAcross = 2.0;

// The narrowest feature of a lattice scene's patterns when it is less than kAcross grid spacings
// across; nothing for a continuum scene, a scene without patterns or a resolved one.
std::optional<CoarseGrid> coarse_grid(const Scene& scene);

}  // namespace membra
