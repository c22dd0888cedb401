// Material presets and the homogenization of docs/model.md ("Homogenization").
#include <gtest/gtest.h>

#include "membra/model/material.hpp"

namespace membra {
namespace {

TEST(Material, LatexPresetInSI) {
  const Material m = latex();
  EXPECT_DOUBLE_EQ(m.youngs_modulus, 1.5e6);
  EXPECT_DOUBLE_EQ(m.thickness, 0.5e-3);
  EXPECT_DOUBLE_EQ(m.density, 930.0);
  EXPECT_DOUBLE_EQ(epoxy().youngs_modulus, 2.5e9);
  EXPECT_FALSE(material_preset("rubber").has_value());
}

TEST(Material, HomogenizationWithoutFlexSprings) {
  const LatticeStiffness k = homogenize(latex());
  const double et = 1.5e6 * 0.5e-3;  // 750 N/m
  EXPECT_NEAR(k.stretch, 0.75 * et, 1e-9);
  EXPECT_NEAR(k.shear, 0.375 * et, 1e-9);
  EXPECT_EQ(k.flex, 0.0);
  EXPECT_NEAR(membrane_stiffness_from_stretch(k.stretch), et, 1e-9);
}

TEST(Material, HomogenizationWithFlexSpringsKeepsIsotropy) {
  const double ratio = 0.1;
  const LatticeStiffness k = homogenize(latex(), ratio);
  const double c11 = k.stretch + k.shear + 4.0 * k.flex, c12 = k.shear, c66 = k.shear;
  EXPECT_NEAR(c66, 0.5 * (c11 - c12), 1e-9);                // isotropy
  EXPECT_NEAR(c12 / c11, 1.0 / 3.0, 1e-12);                 // Poisson ratio
  EXPECT_NEAR((c11 * c11 - c12 * c12) / c11, 750.0, 1e-9);  // E t
  EXPECT_NEAR(k.flex / k.stretch, ratio, 1e-12);
  EXPECT_NEAR(membrane_stiffness_from_stretch(k.stretch, ratio), 750.0, 1e-9);
}

TEST(Material, BendingStiffness) {
  // D = E t^3 / (12 (1 - 1/9)) = 1.5e6 * 1.25e-10 / (32/3)
  EXPECT_NEAR(bending_stiffness(latex()), 1.5e6 * 1.25e-10 * 3.0 / 32.0, 1e-18);
}

}  // namespace
}  // namespace membra
