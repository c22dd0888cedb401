// A run's pictures (render/run_pictures.hpp): a form that passes through itself has its crossing
// triangles outlined in magenta and says so in the heading (docs/outputs.md).
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <memory>
#include <string>

#include <stb_image.h>

#include "membra/io/scene.hpp"
#include "membra/output/output_set.hpp"
#include "membra/process/run.hpp"
#include "membra/render/run_outputs.hpp"

namespace membra {
namespace run_pictures_test {
namespace {

namespace fs = std::filesystem;

// Pixels of the staged PNG `name` that are magenta (the crossing colour, in no colour map).
int magenta_pixels(const OutputSet& out, const std::string& name) {
  int w = 0, h = 0, channels = 0;
  const std::unique_ptr<unsigned char, void (*)(void*)> px(
      stbi_load(out.staged(name).c_str(), &w, &h, &channels, 3), stbi_image_free);
  if (!px) return -1;
  int n = 0;
  for (long i = 0; i < static_cast<long>(w) * h; ++i) {
    const unsigned char* p = px.get() + 3 * i;
    n += p[0] > 200 && p[2] > 200 && p[1] < 60;
  }
  return n;
}

// exp3 on the lattice at 21 x 21 rolls through itself (the run warns, docs/measures.md): its
// curvature, stress and three views outline the crossing triangles; the global form (smoothed,
// another surface) does not claim them.
TEST(RunPictures, AFormThatPassesThroughItselfIsOutlinedInMagenta) {
  const Scene scene = load_scene(std::string(MEMBRA_SOURCE_DIR) + "/examples/exp3_parallel.json",
                                 {"sheet.resolution=[21,21]", "output.image_size=[400,300]"});
  const RunResult r = run_scene(scene);
  ASSERT_GT(r.self_intersection.pairs, 0);
  const fs::path dir =
      fs::temp_directory_path() / ("membra_crossing_" + std::to_string(::getpid()));
  {
    OutputSet out(dir);
    stage_run_outputs(scene, r, PictureOptions{}, out);
    for (const char* name : {"curvature.png", "stress.png", "views.png"})
      EXPECT_GT(magenta_pixels(out, name), 50) << name;
    EXPECT_EQ(magenta_pixels(out, "curvature_global.png"), 0);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace run_pictures_test
}  // namespace membra
