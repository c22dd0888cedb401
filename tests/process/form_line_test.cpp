// The run's one-line form summary, as `membra run` prints it.
#include <gtest/gtest.h>

#include "membra/process/summary.hpp"

namespace membra {
namespace {

TEST(FormLine, NamesTheHeightAndTheQuadricsRadii) {
  RunResult r;
  r.shape.height = 0.0772;
  EXPECT_EQ(form_line(r), "form: 77.2 mm high");  // no fit: the height alone
  const auto fit = [](double k1, double k2, double rms, const char* kind) {
    QuadricFit q;
    q.valid = true, q.k1 = k1, q.k2 = k2, q.rms = rms, q.classification = kind;
    return q;
  };
  r.shape.quadric = fit(1.0 / 0.112, 1.0 / 0.174, 0.0108, "synclastic");
  EXPECT_EQ(form_line(r),
            "form: 77.2 mm high, a synclastic quadric of radii 112 mm and 174 mm (the sheet "
            "10.8 mm rms off it)");
  r.shape.quadric = fit(1.0 / 0.062, 1.0 / 12.6, 0.0109, "cylindrical");
  EXPECT_EQ(form_line(r),
            "form: 77.2 mm high, a cylindrical quadric of radii 62 mm and straight (the sheet "
            "10.9 mm rms off it)");
  r.shape.quadric.classification = "folded";
  EXPECT_EQ(form_line(r), "form: 77.2 mm high, rolled or folded past what a quadric describes");
}

}  // namespace
}  // namespace membra
