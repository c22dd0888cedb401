// Headless renders: size, coverage, colours from the map, and the legend.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "membra/geometry/grid_sheet.hpp"
#include "membra/geometry/triangulation.hpp"
#include "membra/io/image.hpp"
#include "membra/render/renderer.hpp"

namespace membra {
namespace {

// A pixel next to the white background (the mesh's antialiased silhouette blends into it).
bool edge(const Image& img, int x, int y) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int u = std::clamp(x + dx, 0, img.width - 1), v = std::clamp(y + dy, 0, img.height - 1);
      if (img.pixel(u, v).minCoeff() > 0.95f) return true;
    }
  return false;
}

TEST(Renderer, ShadedMeshAndLegendUseTheColourMap) {
  const GridSheet g({0.2, 0.1, 21, 11});
  const std::vector<Triangle> tris = triangulate(g);
  Points x(3, g.num_particles());
  std::vector<Rgb> colors;
  for (int p = 0; p < g.num_particles(); ++p) {
    const auto [i, j] = g.node(p);
    const Vec2 q = g.position(i, j);
    x.col(p) = Vec3(q.x(), q.y(), 0.02 * std::sin(10.0 * q.x()));
    colors.push_back(
        colormap(q.x(), 0.0, 0.2, ColourMap::paper));  // blue on the left, red on the right
  }
  Renderer renderer(640, 480);
  const Legend legend{"test", "m", 0.0, 0.2, ColourMap::paper};
  Camera camera;
  camera.shadow = false;  // only map colours and the text's grey (the shadow: its own test)
  const Image img = renderer.render(x, tris, colors, camera, &legend);
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
      if (edge(img, xx, y)) continue;  // antialiased silhouette: mixed with the background
      ++covered;
      EXPECT_LT(std::min(c.x(), c.z()), 0.02f) << xx << "," << y;
      reddish += c.x() > 0.3f;
      bluish += c.z() > 0.3f;
    }
  EXPECT_GT(covered, total / 10);
  EXPECT_LT(covered, total * 9 / 10);
  EXPECT_GT(reddish, 100);
  EXPECT_GT(bluish, 100);

  // The legend bar (0.82 to 0.842 of the width; from 4.6 text heights below the top to 2 above
  // the bottom, a text height being 1/34 of the image's): red at its top, green in the middle,
  // blue at its bottom.
  const int bar_x = static_cast<int>(0.831 * img.width);
  const double px = img.height / 34.0, bar_top = 4.6 * px, bar_bottom = img.height - 2.0 * px;
  const Rgb top = img.pixel(bar_x, static_cast<int>(bar_top + 3));
  const Rgb mid = img.pixel(bar_x, static_cast<int>(0.5 * (bar_top + bar_bottom)));
  const Rgb bottom = img.pixel(bar_x, static_cast<int>(bar_bottom - 3));
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

namespace membra {
namespace {

// A bumpy sheet 0.2 x 0.1 m, coloured by x.
struct TestSheet {
  Points x;
  std::vector<Triangle> tris;
  std::vector<Rgb> colors;
};
TestSheet test_sheet(double bump) {
  const GridSheet g({0.2, 0.1, 21, 11});
  TestSheet s{Points(3, g.num_particles()), triangulate(g), {}};
  for (int p = 0; p < g.num_particles(); ++p) {
    const auto [i, j] = g.node(p);
    const Vec2 q = g.position(i, j);
    s.x.col(p) = Vec3(q.x(), q.y(), bump * std::sin(10.0 * q.x()));
    s.colors.push_back(colormap(q.x(), 0.0, 0.2, ColourMap::paper));
  }
  return s;
}

// Every label stays inside the picture at any size: its outermost ring of pixels is background.
TEST(Renderer, LabelsStayInsideTheImageAtAnySize) {
  const TestSheet s = test_sheet(0.02);
  const Legend legend{"Gaussian curvature of a rather long title that has to shrink to fit",
                      "1/mm^2", -1.88e-5, 1.88e-5};
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{
           {160, 120}, {320, 240}, {1200, 900}, {1600, 400}, {300, 900}, {64, 900}, {2048, 64}}) {
    Renderer renderer(w, h);
    const Image img = renderer.render(s.x, s.tris, s.colors, Camera{}, &legend, "Form");
    int touching = 0;
    for (int x = 0; x < w; ++x)
      touching += (img.pixel(x, 0).minCoeff() < 0.97f) + (img.pixel(x, h - 1).minCoeff() < 0.97f);
    for (int y = 0; y < h; ++y)
      touching += (img.pixel(0, y).minCoeff() < 0.97f) + (img.pixel(w - 1, y).minCoeff() < 0.97f);
    EXPECT_EQ(touching, 0) << w << " x " << h;
    // And the labels are there, not dropped (but where a picture is too narrow for them):
    // dark ink right of the colour bar and in the heading.
    int ink = 0, heading = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const bool dark = img.pixel(x, y).maxCoeff() < 0.6f;
        ink += dark && x > 0.85 * w;
        heading += dark && y < 0.08 * h + 10;
      }
    if (w >= 160) {
      EXPECT_GT(ink, 10) << w << " x " << h;
    }
    EXPECT_GT(heading, 5) << w << " x " << h;
  }
}

// A picture's PNG decodes to its pixels (a grey one, which the scene reader decodes), at a width
// whose rows are not a multiple of four bytes; a file that cannot be written says which.
TEST(Renderer, APngHoldsThePicturesPixels) {
  Image img = blank_image(17, 5);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c)
        img.rgb[(static_cast<size_t>(y) * img.width + x) * 3 + c] =
            static_cast<std::uint8_t>((37 * x + 91 * y) % 256);
  const std::vector<std::uint8_t> png = encode_png(img);
  const GreyImage grey = decode_grey_image(png.data(), png.size(), "p.png", "test");
  ASSERT_EQ(grey.width, 17);
  ASSERT_EQ(grey.height, 5);
  int wrong = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      wrong += std::abs(grey.value[static_cast<size_t>(y) * 17 + x] * 255.0 -
                        (37 * x + 91 * y) % 256) > 0.01;
  EXPECT_EQ(wrong, 0);
  try {
    write_png("/nonexistent-directory/p.png", img);
    ADD_FAILURE() << "no error";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-directory/p.png"), std::string::npos);
  }
}

// Supersampling: the silhouette of a flat blue sheet seen from above has pixels between blue
// and white; without it every pixel would be one or the other.
TEST(Renderer, EdgesAreAntialiased) {
  TestSheet s = test_sheet(0.0);
  std::fill(s.colors.begin(), s.colors.end(), Rgb(0.0f, 0.0f, 1.0f));
  Renderer renderer(200, 150);
  const Image img =
      renderer.render(s.x, s.tris, s.colors, Camera{-90.0, 80.0, 1.1, false}, nullptr);
  int mixed = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const float r = img.pixel(x, y).x();  // 0 on the sheet, 1 on the background
      mixed += r > 0.15f && r < 0.85f;
    }
  EXPECT_GT(mixed, 20);
}

// The soft shadow: grey pixels under the form with it, none without it.
TEST(Renderer, SoftShadowOnTheGround) {
  const TestSheet s = test_sheet(0.02);
  Renderer renderer(320, 240);
  const auto picture = [&](bool shadow) {
    return renderer.render(s.x, s.tris, s.colors, Camera{-60.0, 35.0, 1.1, shadow}, nullptr);
  };
  const Image with = picture(true), without = picture(false);
  // The shadow's pixels: background that the shadow changed (the form is drawn over it alike).
  int shadow = 0, levels = 0, background = 0, coloured = 0;
  float darkest = 1.0f;
  std::vector<bool> seen(256, false);
  for (int y = 0; y < with.height; ++y)
    for (int x = 0; x < with.width; ++x) {
      const Rgb c = with.pixel(x, y), plain = without.pixel(x, y);
      if (plain.minCoeff() < 0.99f) continue;
      ++background;
      if ((c - plain).cwiseAbs().maxCoeff() < 0.01f) continue;
      ++shadow;
      coloured += c.maxCoeff() - c.minCoeff() > 0.06f;
      const int v = static_cast<int>(c.x() * 255);
      levels += !seen[static_cast<size_t>(v)];
      seen[static_cast<size_t>(v)] = true;
      darkest = std::min(darkest, c.x());
    }
  EXPECT_GT(shadow, 500);
  EXPECT_EQ(coloured, 0);         // grey
  EXPECT_LT(shadow, background);  // on the ground around the form, not over the picture
  EXPECT_GT(levels, 8);           // a soft penumbra, not one flat grey
  // Where the whole penumbra's disk is under the sheet: 40 copies of 1.2 % grey (0.25) on white.
  EXPECT_NEAR(darkest, 1.0 - (1.0 - std::pow(0.988, 40)) * 0.75, 0.02);
}

}  // namespace
}  // namespace membra

namespace membra {
namespace {

// A run draws its panels with a second renderer while the first lives on: ending the second
// must not end the first's display (every picture after views.png came out black).
TEST(Renderer, ASecondRendererEndingLeavesTheFirstDrawing) {
  const TestSheet s = test_sheet(0.02);
  Renderer first(160, 120);
  {
    Renderer second(80, 60);
    (void)second.render(s.x, s.tris, s.colors, Camera{}, nullptr);
  }
  const Image img = first.render(s.x, s.tris, s.colors, Camera{}, nullptr);
  int white = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) white += img.pixel(x, y).minCoeff() > 0.97f;
  EXPECT_GT(white, img.width * img.height / 4);  // the white background, not a black frame
}

// The penumbra about a straight edge, seen from straight above: half the 40 copies cover the
// edge, the share beyond it falls as a disk of radius `blur` (3 % of the form's diagonal) leaves
// it — (acos r - r sqrt(1 - r^2)) / pi at r radii out — and nothing reaches past one radius.
// The same on the left, right and far edges: in place and to scale on both axes.
TEST(Renderer, ThePenumbraIsADiskOfTheBlurRadiusAboutTheEdges) {
  TestSheet s = test_sheet(0.0);  // 200 x 100 mm, flat
  std::fill(s.colors.begin(), s.colors.end(), Rgb(0.0f, 0.0f, 1.0f));
  Renderer renderer(400, 300);
  const Image img = renderer.render(s.x, s.tris, s.colors, Camera{-90.0, 90.0, 1.1, true}, nullptr);
  const auto blue = [&](int x, int y) { return img.pixel(x, y).x() < 0.5f; };
  const int mid_y = img.height / 2, mid_x = img.width / 2;
  int left = 0, right = img.width - 1, top = 0;
  while (left < img.width && !blue(left, mid_y)) ++left;
  while (right > 0 && !blue(right, mid_y)) --right;
  while (top < img.height && !blue(mid_x, top)) ++top;
  ASSERT_LT(left, right);
  const double per_m = (right - left + 1) / 0.2;  // pixels per metre, both axes
  EXPECT_NEAR((mid_y - top) / per_m, 0.05, 0.003);
  const double blur = 0.03 * std::hypot(0.2, 0.1) * per_m;  // pixels
  const auto expected = [](double r) {
    const double share =
        r >= 1.0 ? 0.0 : (std::acos(r) - r * std::sqrt(1.0 - r * r)) / std::numbers::pi;
    return 1.0 - (1.0 - std::pow(0.988, 40.0 * share)) * 0.75;
  };
  for (const double r : {0.15, 0.4, 0.7, 1.3}) {
    const int d = static_cast<int>(std::lround(r * blur));
    // The pixel's centre d + 1/2 pixels beyond the last pixel of the sheet's edge.
    const double at = (d + 0.5) / blur;
    EXPECT_NEAR(img.pixel(right + 1 + d, mid_y).x(), expected(at), 0.035) << "right, r " << r;
    EXPECT_NEAR(img.pixel(left - 1 - d, mid_y).x(), expected(at), 0.035) << "left, r " << r;
    EXPECT_NEAR(img.pixel(mid_x, top - 1 - d).x(), expected(at), 0.035) << "far, r " << r;
  }
}

// Triangles asked to be outlined (where a form passes through itself) are drawn in magenta over
// the form, two image pixels wide; nothing else in a picture is magenta.
TEST(Renderer, OutlinedTrianglesAreMagentaOverTheForm) {
  const TestSheet s = test_sheet(0.02);
  Renderer renderer(320, 240);
  const auto magenta = [&](const std::vector<int>& outlined) {
    const Image img = renderer.render(s.x, s.tris, s.colors, Camera{}, nullptr, "", outlined);
    int n = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const Rgb c = img.pixel(x, y);
        n += c.x() > 0.8f && c.z() > 0.8f && c.y() < 0.25f;
      }
    return n;
  };
  EXPECT_EQ(magenta({}), 0);
  EXPECT_EQ(magenta({-1, 100000}), 0);  // not triangles of the mesh: skipped
  const int one = magenta({50}), three = magenta({50, 120, 300});
  EXPECT_GT(one, 40);  // three edges of a 10 mm triangle, about 2 pixels wide
  EXPECT_GT(three, 2 * one);
}

}  // namespace
}  // namespace membra
