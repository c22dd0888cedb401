#pragma once
// What a design's error means for the designer (docs/inverse_design.md, "The verdict"): whether
// the stencil meets the goal, comes clearly closer than a flat sheet, or does not — so that a
// bare sheet that scores a little below a flat one is not read as a design.
#include <string>

namespace membra {

struct DesignResult;

struct DesignVerdict {
  // "meets_goal": rms <= 2 % of the diameter and at most half a flat sheet's error;
  // "closer_than_flat": rms at most 0.9 of a flat sheet's; "no_closer_than_flat": otherwise,
  // and whenever the stencil's simulation did not settle (unconverged, a saddle, out of time).
  std::string grade;
  std::string sentence;  // the same in words, with the numbers and what to try
};

DesignVerdict design_verdict(const DesignResult& r);

}  // namespace membra
