// Scripts are checked before the window opens; session commands act without one.
#include <gtest/gtest.h>

#include <sstream>

#include "membra/core/input_error.hpp"
#include "membra/io/scene.hpp"
#include "membra/view/view_script.hpp"

namespace membra {
namespace {

std::string error_of(const std::string& text) {
  std::istringstream in(text);
  try {
    parse_view_script(in, "s.txt");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ViewScript, ParsesCommandsSkippingCommentsAndBlankLines) {
  std::istringstream in("# a comment\n\nstretch\npaint 10 20 5  # dab\nrange auto\nquit\n");
  const auto cmds = parse_view_script(in, "s.txt");
  ASSERT_EQ(cmds.size(), 4u);
  EXPECT_EQ(cmds[1].name, "paint");
  EXPECT_EQ(cmds[1].where, "s.txt:4");
  EXPECT_EQ(cmds[1].number(2), 5.0);
}

TEST(ViewScript, BadLinesAreNamedByFileAndLine) {
  EXPECT_NE(error_of("stretch\nflyaway\n").find("s.txt:2"), std::string::npos);
  EXPECT_NE(error_of("flyaway\n").find("unknown command"), std::string::npos);
  EXPECT_NE(error_of("paint 1 2\n").find("takes 3 argument"), std::string::npos);
  EXPECT_NE(error_of("hole 1 x 3\n").find("must be a number"), std::string::npos);
  EXPECT_NE(error_of("color rainbow\n").find("not allowed"), std::string::npos);
  EXPECT_NE(error_of("range 2 1\n").find("LO < HI"), std::string::npos);
  EXPECT_NE(error_of("step 0\n").find("count"), std::string::npos);
  EXPECT_NE(error_of("paint 1 2 nan\n").find("must be a number"), std::string::npos);
}

TEST(ViewScript, SessionCommandsActAndWindowCommandsAreLeftToTheApp) {
  ViewerSession s(parse_scene(
      {{"sheet", {{"size", {100, 100}}, {"resolution", {9, 9}}}}, {"simulation", {{"G", 0.0}}}}));
  ViewSettings v;
  std::istringstream in(
      "stretch\npaint 75 50 20\ncolor pattern\nrange -1 2\nview 2d\nset K 1.5\nscreenshot a.png\n"
      "impregnate\nimpregnate\n");
  const auto cmds = parse_view_script(in, "s.txt");
  for (size_t i = 0; i < 6; ++i) EXPECT_TRUE(run_session_command(cmds[i], s, v)) << i;
  EXPECT_EQ(s.stage(), Stage::stretched);
  EXPECT_EQ(s.strokes().size(), 1u);
  EXPECT_EQ(v.color, ColorMode::pattern);
  ASSERT_TRUE(v.range);
  EXPECT_EQ(v.range->second, 2.0);
  EXPECT_TRUE(v.flat);
  EXPECT_NEAR(s.parameters().K, 1500.0, 1e-9);  // N/mm in the script, N/m inside
  EXPECT_FALSE(run_session_command(cmds[6], s, v));
  EXPECT_TRUE(run_session_command(cmds[7], s, v));
  // A refused command names its line.
  try {
    run_session_command(cmds[8], s, v);
    FAIL() << "a second impregnate without new resin must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("s.txt:9"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace membra
