// Headless renders: size, coverage, colours from the map, and the legend.
#include <gtest/gtest.h>

#include "membra/geometry/grid_sheet.hpp"
#include "membra/geometry/triangulation.hpp"
#include "membra/render/renderer.hpp"

namespace membra {
namespace {

TEST(Renderer, ShadedMeshAndLegendUseTheColourMap) {
  const GridSheet g({0.2, 0.1, 21, 11});
  const std::vector<Triangle> tris = triangulate(g);
  Points x(3, g.num_particles());
  std::vector<Rgb> colors;
  for (int p = 0; p < g.num_particles(); ++p) {
    const auto [i, j] = g.node(p);
    const Vec2 q = g.position(i, j);
    x.col(p) = Vec3(q.x(), q.y(), 0.02 * std::sin(10.0 * q.x()));
    colors.push_back(colormap(q.x(), 0.0, 0.2));  // blue on the left, red on the right
  }
  Renderer renderer(640, 480);
  const Legend legend{"test", "m", 0.0, 0.2};
  const Image img = renderer.render(x, tris, colors, Camera{}, &legend);
  ASSERT_EQ(img.width, 640);
  ASSERT_EQ(img.height, 480);
  ASSERT_EQ(img.rgb.size(), 640u * 480u * 3u);

  // The mesh (left 80 %): a plausible share of non-white pixels, and every coloured pixel is a
  // shaded map colour: the map never mixes red with blue.
  int covered = 0, total = 0, reddish = 0, bluish = 0;
  for (int y = 0; y < img.height; ++y)
    for (int xx = 0; xx < img.width * 8 / 10; ++xx, ++total) {
      const Rgb c = img.pixel(xx, y);
      if (c.minCoeff() > 0.95f) continue;                 // background
      if (c.maxCoeff() - c.minCoeff() < 0.05f) continue;  // the title's grey text
      ++covered;
      EXPECT_LT(std::min(c.x(), c.z()), 0.02f) << xx << "," << y;
      reddish += c.x() > 0.3f;
      bluish += c.z() > 0.3f;
    }
  EXPECT_GT(covered, total / 10);
  EXPECT_LT(covered, total * 9 / 10);
  EXPECT_GT(reddish, 100);
  EXPECT_GT(bluish, 100);

  // The legend bar: pure red at its top, green in the middle, blue at its bottom.
  const int bar_x = static_cast<int>(0.855 * img.width);
  const Rgb top = img.pixel(bar_x, static_cast<int>(0.16 * img.height));
  const Rgb mid = img.pixel(bar_x, img.height / 2);
  const Rgb bottom = img.pixel(bar_x, static_cast<int>(0.84 * img.height));
  EXPECT_GT(top.x(), 0.9f);
  EXPECT_GT(mid.y(), 0.9f);
  EXPECT_GT(bottom.z(), 0.9f);
  // Legend labels are drawn in dark grey right of the bar.
  int dark = 0;
  for (int y = 0; y < img.height; ++y)
    for (int xx = static_cast<int>(0.88 * img.width); xx < img.width; ++xx)
      dark += img.pixel(xx, y).maxCoeff() < 0.3f;
  EXPECT_GT(dark, 50);
  EXPECT_GT(encode_png(img).size(), 1000u);
}

}  // namespace
}  // namespace membra
