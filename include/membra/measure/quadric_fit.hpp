#pragma once
// The whole form in two numbers: the principal curvatures of the quadric that best fits the
// released sheet, so that a designer reads "a bowl of radii 110 and 170 mm" however the sheet
// wrinkles or where its curvature concentrates (docs/measures.md, "The form's quadric").
#include <string>

#include "membra/core/vec.hpp"

namespace membra {

struct QuadricFit {
  bool valid = false;  // false for fewer than six particles or paper positions on one line
  // Principal curvatures at the centre, 1/m, k1 >= k2, the normal turned so that k1 + k2 >= 0
  // (a bowl has both positive whichever way it lies; a saddle k1 > 0 > k2).
  double k1 = 0.0, k2 = 0.0;
  double rms = 0.0;  // m: the particles' rms distance from the fitted surface, along its normal
  // "flat", "cylindrical", "synclastic" or "anticlastic"; "folded" when the sheet turns more than
  // a quadric can describe (k L > 2 over the fit's half-width L at the centre, or that half-width
  // under a third of the paper's): k1, k2 and rms are then the fit's, not the form's.
  std::string classification;
  // The fitted surface at the paper's centroid: its point (m), its unit normal (turned as k1
  // and k2 are: the side the form opens towards), the unit principal directions of k1 and k2,
  // and the unit tangent along the paper's x axis (measure/reading_pose.hpp poses by them).
  Vec3 centre = Vec3::Zero(), normal = Vec3::UnitZ();
  Vec3 d1 = Vec3::UnitX(), d2 = Vec3::UnitY(), paper_x = Vec3::UnitX();
};

// Fits each coordinate of x (3 x N, m) by a quadratic polynomial of the paper coordinates
// (3 x N, the flat sheet's positions; only x and y are used), least squares over all particles,
// and reads the principal curvatures of that parametric surface at the paper's centroid. The
// parametrisation does not matter (a stretched or sheared paper gives the same surface), nor does
// how the form lies in space.
QuadricFit fit_quadric(const Points& x, const Points& paper);

// `size`: half the sheet's larger side on the paper, m. "flat" when the larger curvature bends
// that half-width by less than 2.5 % of it (|k1| size < 0.05); "cylindrical" when the smaller
// curvature is under a quarter of the larger; otherwise by the sign of k1 k2.
std::string classify_quadric(double k1, double k2, double size);

}  // namespace membra
