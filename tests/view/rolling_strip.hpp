#pragma once
// A scene the viewer's tests share: a 110 x 10 mm latex strip on a coarse lattice, stretched 1.5x
// along x and coated on top with 0.2 mm epoxy, rolls past a full turn when released. The live
// relaxation has no self-contact, so it settles through itself.
namespace membra {

inline constexpr const char* kRollingStrip = R"({
  "name": "coil", "materials": {"thin_epoxy": {"preset": "epoxy", "thickness": 0.2}},
  "sheet": {"size": [110, 10], "resolution": [23, 3], "material": "latex"},
  "simulation": {"solver": "static", "G": 0},
  "protocol": [
    {"step": "stretch", "lambda": [1.5, 1.0]},
    {"step": "impregnate", "material": "thin_epoxy", "resin_side": "top", "bilayer": true,
     "pattern": {"polygon": {"points": [[-10, -10], [310, -10], [310, 210], [-10, 210]]}}},
    {"step": "release", "increments": 10, "perturbation": 0.2, "seed": 1}]})";

}  // namespace membra
