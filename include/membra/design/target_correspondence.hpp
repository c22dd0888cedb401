#pragma once
// Inverse design's first stage: where on the target each particle should end up, and the resin
// density that asks for the right metric there. The target is parametrised over the frame in
// one of two ways (`Flattening`):
//  - conformal: the target's conformal flattening (design/conformal_flattening.hpp), scaled so
//    that the sheet's extent covers the flattening's; a particle at frame position P, measured
//    from the sheet's centre, belongs at the surface point whose flat image is s P. The metric
//    asked is then isotropic, as a resin density makes it.
//  - projection: P belongs at s P on the footprint, lifted onto the surface (s = target
//    diameter / the sheet's extent); steep parts then ask for more shrink across the slope than
//    along it, which an isotropic density cannot give.
// The extent is the particles' (a coarse disk sheet covers less than its disk, and the error is
// measured both ways, so the particles must cover the whole target). Along each stretched
// direction the sheet must shrink by the map's stretch there: between 1 / lambda (bare latex,
// back at its natural length) and 1 (resin, kept at its stretched length), linear in the resin
// share for a uniform sheet. Where the target asks for less or more, it cannot be reached there
// (docs/inverse_design.md).
#include "membra/design/aligned_distance.hpp"
#include "membra/design/density_field.hpp"
#include "membra/design/target_surface.hpp"

namespace membra {

enum class Flattening { conformal, projection };

// The height of the target over footprint point p (its centre at the origin), m: linear over the
// triangle that covers p, the nearest vertex's beyond the footprint.
double target_height(const TargetSurface& target, const Vec2& p);

// Each particle's point on the target (frame positions `frame_x`, weights as given).
Correspondence target_correspondence(const TargetSurface& target, const Points& frame_x,
                                     const Eigen::VectorXd& weights,
                                     Flattening flattening = Flattening::conformal);

struct MetricStart {
  Eigen::VectorXd density;                // per cell of the field, clamped to [0, 1]
  double unreachable_share = 0.0;         // of the cells, where the target asks for more or less
  double asks_min = 0.0, asks_max = 0.0;  // the needed densities before clamping
};

// The starting density: at each cell centre the density whose uniform release gives the
// target's stretch there (the mean of the two directions).
MetricStart metric_start(const TargetSurface& target, const Points& frame_x,
                         const DensityField& field, const Vec2& lambda,
                         Flattening flattening = Flattening::conformal);

}  // namespace membra
