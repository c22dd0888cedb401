// A run's pictures (render/run_pictures.hpp): a form that passes through itself has its crossing
// triangles outlined in magenta (docs/outputs.md), and the run warns (process/run.hpp).
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <stb_image.h>

#include "membra/io/scene.hpp"
#include "membra/output/output_set.hpp"
#include "membra/process/run.hpp"
#include "membra/render/run_outputs.hpp"
#include "process/crossing_warning.hpp"

namespace membra {
namespace run_pictures_test {
namespace {

namespace fs = std::filesystem;

// Pixels of the staged PNG `name` that are magenta (the crossing colour, in no colour map), in
// each of its `panels` side by side.
std::vector<int> magenta_pixels(const OutputSet& out, const std::string& name, int panels = 1) {
  int w = 0, h = 0, channels = 0;
  const std::unique_ptr<unsigned char, void (*)(void*)> px(
      stbi_load(out.staged(name).c_str(), &w, &h, &channels, 3), stbi_image_free);
  if (!px) return {};
  std::vector<int> n(static_cast<size_t>(panels), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const unsigned char* p = px.get() + 3 * (static_cast<long>(y) * w + x);
      n[static_cast<size_t>(x * panels / w)] += p[0] > 200 && p[2] > 200 && p[1] < 60;
    }
  return n;
}

using test_support::says_it_passes_through_itself;

// exp3 on the lattice at 21 x 21 rolls its strips past a full turn, and the turns cross (31
// pairs of triangles when measured): the run says so, and its curvature, stress and each of the
// three views outline the crossing triangles; the global form (smoothed, another surface) does
// not claim them.
TEST(RunPictures, AFormThatPassesThroughItselfIsOutlinedInMagenta) {
  const Scene scene = load_scene(std::string(MEMBRA_SOURCE_DIR) + "/examples/exp3_parallel.json",
                                 {"sheet.resolution=[21,21]", "output.image_size=[400,300]"});
  const RunResult r = run_scene(scene);
  ASSERT_TRUE(r.solve.converged);
  ASSERT_GT(r.self_intersection.pairs, 0);
  EXPECT_TRUE(says_it_passes_through_itself(r.warnings));
  const fs::path dir =
      fs::temp_directory_path() / ("membra_crossing_" + std::to_string(::getpid()));
  {
    OutputSet out(dir);
    stage_run_outputs(scene, r, PictureOptions{}, out);
    for (const char* name : {"curvature.png", "stress.png"})
      EXPECT_GT(magenta_pixels(out, name).at(0), 50) << name;
    const std::vector<int> views = magenta_pixels(out, "views.png", 3);
    ASSERT_EQ(views.size(), 3u);
    for (int v = 0; v < 3; ++v) EXPECT_GT(views[static_cast<size_t>(v)], 20) << "view " << v;
    EXPECT_EQ(magenta_pixels(out, "curvature_global.png"), std::vector<int>{0});
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace run_pictures_test
}  // namespace membra
