// TrueType text: decoding, metrics and coverage.
#include <gtest/gtest.h>

#include <algorithm>

#include "membra/render/font.hpp"
#include "membra/render/renderer.hpp"

namespace membra {
namespace {

TEST(Font, DecodesUtf8AndReplacesBrokenBytes) {
  EXPECT_EQ(decode_utf8("1/m\xc2\xb2"), (std::vector<char32_t>{'1', '/', 'm', 0xB2}));
  EXPECT_EQ(decode_utf8("\xe2\x88\x92"
                        "1"),
            (std::vector<char32_t>{0x2212, '1'}));
  EXPECT_EQ(decode_utf8("a\xff"), (std::vector<char32_t>{'a', 0xFFFD}));
  EXPECT_EQ(decode_utf8("\xc2"), (std::vector<char32_t>{0xFFFD}));  // cut short
}

TEST(Font, WidthScalesWithSizeAndCoverageIsAntialiased) {
  const Font& f = Font::standard();
  const float w12 = f.width("Gaussian curvature", 12.0f),
              w24 = f.width("Gaussian curvature", 24.0f);
  EXPECT_GT(w12, 12.0f * 5);
  EXPECT_NEAR(w24 / w12, 2.0f, 0.05f);
  const TextBitmap t = f.rasterize("Hg 1/m\xc2\xb2", 20.0f);
  EXPECT_GE(t.width, static_cast<int>(f.width("Hg 1/m\xc2\xb2", 20.0f)));
  EXPECT_GT(t.height, 20);
  EXPECT_GT(t.ascent, 10);
  int ink = 0, partial = 0;
  for (auto c : t.coverage) {
    ink += c > 200;
    partial += c > 20 && c < 200;
  }
  EXPECT_GT(ink, 50);
  EXPECT_GT(partial, 20);  // smooth edges, not a bitmap font
  // The padding row and column stay empty: nothing is clipped at the bitmap's edge.
  for (int x = 0; x < t.width; ++x) EXPECT_EQ(t.coverage[static_cast<size_t>(x)], 0);
}

TEST(Font, MissingFileNamesIt) {
  try {
    Font f("/nonexistent/font.ttf");
    FAIL() << "no error";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/font.ttf"), std::string::npos);
  }
}

}  // namespace
}  // namespace membra
