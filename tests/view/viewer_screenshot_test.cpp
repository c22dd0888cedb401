// The viewer in a real window under Xvfb, driven by a script: its screenshots show the sheet,
// the colours of the chosen map and the legend. Runs `membra view` as a user would.
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <stb_image.h>
#include <sys/wait.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "test_util.hpp"
#include "view/rolling_strip.hpp"

namespace membra {
namespace {
namespace fs = std::filesystem;

constexpr int kPanel = 330;  // the control panel's width (viewer_window.cpp)

struct Png {
  int w = 0, h = 0;
  std::vector<unsigned char> rgb;
  std::array<int, 3> at(int x, int y) const {
    const size_t i = (static_cast<size_t>(y) * w + x) * 3;
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

Png load(const fs::path& file) {
  Png p;
  int n = 0;
  unsigned char* d = stbi_load(file.c_str(), &p.w, &p.h, &n, 3);
  if (!d) return p;
  p.rgb.assign(d, d + static_cast<size_t>(p.w) * p.h * 3);
  stbi_image_free(d);
  return p;
}

// Pixels of the sheet area (right of the panel, left of the legend) that satisfy `f`.
template <class F>
int count(const Png& p, F f) {
  int n = 0;
  const int legend_x = kPanel + (p.w - kPanel) * 4 / 5;
  for (int y = 0; y < p.h; ++y)
    for (int x = kPanel; x < legend_x; ++x)
      if (f(p.at(x, y))) ++n;
  return n;
}
// The default map's ends (ColorBrewer RdBu): a dark red (103, 0, 31) and a dark blue (5, 48, 97).
// Shaded, they darken: the tests look for the hue, not the exact colour.
bool red(const std::array<int, 3>& c) {
  return c[0] > 60 && c[0] > c[2] + 30 && c[1] < 60;
}
bool blue(const std::array<int, 3>& c) {
  return c[2] > 60 && c[2] > c[0] + 30 && c[0] < 60;
}
// Its white middle as the lighting shades it: a neutral grey, neither background nor ink.
bool near_zero(const std::array<int, 3>& c) {
  return std::abs(c[0] - c[1]) < 25 && std::abs(c[1] - c[2]) < 25 && c[1] > 90 && c[1] < 245;
}
bool white(const std::array<int, 3>& c) {
  return c[0] > 245 && c[1] > 245 && c[2] > 245;
}

// The colour bar: red at its top, blue at its bottom, in the legend column.
void expect_legend(const Png& p, const std::string& name) {
  const int scene_w = p.w - kPanel;
  const int x = kPanel + static_cast<int>(0.831 * scene_w);  // the bar: 0.82 to 0.842 of it
  EXPECT_TRUE(red(p.at(x, static_cast<int>(0.16 * p.h)))) << name << ": no red at the bar's top";
  EXPECT_TRUE(blue(p.at(x, static_cast<int>(0.9 * p.h)))) << name << ": no blue at its bottom";
}

// Runs `membra view SCENE --script SCRIPT` under Xvfb; returns the exit status and output.
std::pair<int, std::string> run_viewer(const fs::path& scene, const fs::path& script) {
  const std::string cmd = "xvfb-run -a -s '-screen 0 1280x800x24' " + std::string(MEMBRA_CLI) +
                          " view " + scene.string() + " --script " + script.string() +
                          " --size 1000 700 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf;
  while (size_t n = fread(buf.data(), 1, buf.size(), pipe)) out.append(buf.data(), n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

TEST(ViewerScreenshot, TheMouseToolsPaintCutAndPin) {
  const fs::path dir = unique_temp_dir();
  fs::create_directories(dir);
  {
    std::ofstream scene(dir / "scene.json");
    scene << R"({"name": "mouse", "sheet": {"size": [100, 100], "resolution": [17, 17]},
                 "simulation": {"G": 0}})";
    // In the 2-D view the stretched sheet spans about x 352..842, y 186..512 (1000 x 700).
    std::ofstream script(dir / "script.txt");
    script << "color pattern\nstretch\nview 2d\n"
           << "screenshot " << (dir / "before.png").string() << "\n"
           << "tool paint\nbrush 6\ndrag 450 350 750 350\n"
           << "screenshot " << (dir / "painted.png").string() << "\n"
           << "tool cut\ndrag 600 250 600 450\ntool pin\nclick 700 300\n"
           << "save " << (dir / "saved.json").string() << "\nquit\n";
  }
  const auto [code, out] = run_viewer(dir / "scene.json", dir / "script.txt");
  ASSERT_EQ(code, 0) << out;
  const Png before = load(dir / "before.png"), painted = load(dir / "painted.png");
  ASSERT_EQ(painted.w, 1000);
  // The drag left a red band along y = 350 from x 450 to 750 where all was blue before (the
  // frame's outline is red too, so only the band is looked at).
  int band_before = 0, band = 0;
  for (int x = 460; x <= 740; x += 10) {
    band_before += red(before.at(x, 350)) ? 1 : 0;
    band += red(painted.at(x, 350)) ? 1 : 0;
  }
  EXPECT_EQ(band_before, 0);
  EXPECT_EQ(band, 29);
  EXPECT_FALSE(red(painted.at(600, 250)));  // well off the stroke
  // The cut and the pin went into the session's protocol.
  nlohmann::json saved;
  std::ifstream(dir / "saved.json") >> saved;
  ASSERT_EQ(saved["protocol"].size(), 3u) << saved.dump();
  EXPECT_EQ(saved["protocol"][1]["step"], "cut");
  EXPECT_EQ(saved["protocol"][2]["step"], "load");
  fs::remove_all(dir);
}

// A strip coated on one face rolls past a full turn and, with no self-contact in the live
// relaxation, settles through itself: the crossing triangles are outlined in magenta, which no
// colour map uses, and nothing is outlined before.
TEST(ViewerScreenshot, AFormThatPassesThroughItselfIsOutlinedInMagenta) {
  const fs::path dir = unique_temp_dir();
  fs::create_directories(dir);
  {
    std::ofstream scene(dir / "scene.json");
    scene << kRollingStrip;
    std::ofstream script(dir / "script.txt");
    script << "view 3d\nscreenshot " << (dir / "flat.png").string() << "\n"
           << "play\nsettle\nfit\nscreenshot " << (dir / "rolled.png").string() << "\nquit\n";
  }
  const auto [code, out] = run_viewer(dir / "scene.json", dir / "script.txt");
  ASSERT_EQ(code, 0) << out;
  const auto magenta = [](const std::array<int, 3>& c) {
    return c[0] > 200 && c[2] > 200 && c[1] < 60;
  };
  const Png flat = load(dir / "flat.png"), rolled = load(dir / "rolled.png");
  ASSERT_EQ(rolled.w, 1000) << "no screenshot";
  EXPECT_EQ(count(flat, magenta), 0);
  EXPECT_GT(count(rolled, magenta), 200);
  fs::remove_all(dir);
}

TEST(ViewerScreenshot, ScriptedViewerDrawsTheSheetItsColoursAndTheLegend) {
  const fs::path dir = unique_temp_dir();
  fs::create_directories(dir);
  {
    std::ofstream scene(dir / "scene.json");
    scene << R"({"name": "shot", "sheet": {"size": [100, 100], "resolution": [17, 17]},
                 "simulation": {"G": 0}})";
    std::ofstream script(dir / "script.txt");
    script << "color pattern\nstretch\npaint 75 50 18\nview 2d\n"
           << "screenshot " << (dir / "pattern.png").string() << "\n"
           << "impregnate\nrelease\nstep 60\nview 3d\ncolor stress\n"
           << "screenshot " << (dir / "stress.png").string() << "\n"
           << "color curvature\n"
           << "screenshot " << (dir / "curvature.png").string() << "\n"
           << "save " << (dir / "saved.json").string() << "\nquit\n";
  }
  const auto [code, out] = run_viewer(dir / "scene.json", dir / "script.txt");
  ASSERT_EQ(code, 0) << out;

  const Png pattern = load(dir / "pattern.png");
  ASSERT_EQ(pattern.w, 1000) << "no screenshot";
  ASSERT_EQ(pattern.h, 700);
  // 2-D view: the latex sheet (dark blue: no resin) with a painted disc (dark red), and the legend.
  const int area = (pattern.w - kPanel) * 4 / 5 * pattern.h;
  EXPECT_GT(count(pattern, blue), area / 5);
  EXPECT_GT(count(pattern, red), area / 100);
  expect_legend(pattern, "pattern.png");
  // The panel is drawn on the left (not the white background).
  EXPECT_FALSE(white(pattern.at(kPanel / 2, pattern.h / 2)));

  const Png stress = load(dir / "stress.png");
  ASSERT_EQ(stress.w, 1000);
  EXPECT_GT(count(stress, [](const auto& c) { return !white(c); }), area / 10);  // the sheet
  EXPECT_GT(count(stress, near_zero), area / 20);  // the map's white middle (near-zero stress)
  expect_legend(stress, "stress.png");
  const Png curvature = load(dir / "curvature.png");
  ASSERT_EQ(curvature.w, 1000);
  EXPECT_GT(count(curvature, near_zero), area / 20);
  expect_legend(curvature, "curvature.png");
  // The two maps colour the sheet differently.
  EXPECT_NE(stress.rgb, curvature.rgb);
  EXPECT_TRUE(fs::exists(dir / "saved.json"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace membra
