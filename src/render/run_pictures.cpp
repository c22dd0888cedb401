#include "membra/render/run_pictures.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>

#include "membra/measure/colormap.hpp"
#include "membra/render/renderer.hpp"

namespace membra {
namespace {

void add_png(OutputSet& out, const std::string& file, const Image& img) {
  const auto png = encode_png(img);
  out.add(file, [png](std::ostream& os) {
    os.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  });
}

// Side by side on one colour range: the target map and the measured curvature on the flat sheet
// (seen from above), and the form.
void stage_curvature_map(const RunResult& r, const RunColors& c, const PictureOptions& opts,
                         const Camera& camera, OutputSet& out) {
  const auto& mesh = r.prepared.membrane.sheet;
  const auto& x = r.prepared.membrane.state.x;
  std::vector<double> target_mm;
  for (double k : r.curvature_map->target) target_mm.push_back(k * 1e-6);
  auto [t_lo, t_hi] = symmetric_range(target_mm, 1e-6);
  if (opts.curvature_range.size() == 2)
    t_lo = opts.curvature_range[0], t_hi = opts.curvature_range[1];
  const int pw = 800, ph = 700;
  Renderer panel(pw, ph);
  const Camera above{-90.0, 89.9, 1.1};
  const std::vector<Rgb> measured = colorize(c.curvature, t_lo, t_hi);
  Image side = blank_image(3 * pw, ph);
  blit(side,
       panel.render(mesh.model.reference, mesh.triangles, colorize(target_mm, t_lo, t_hi), above,
                    nullptr),
       0, 0);
  blit(side, panel.render(mesh.model.reference, mesh.triangles, measured, above, nullptr), pw, 0);
  const Legend legend{"Target | measured | form", "1/mm^2", t_lo, t_hi};
  blit(side, panel.render(x, mesh.triangles, measured, camera, &legend), 2 * pw, 0);
  add_png(out, "curvature_map.png", side);
}

// Frames share one stress range; the contact sheet tiles them six to a row (the paper's figure 8
// shows 24).
void stage_frames(const RunResult& r, const Camera& camera, Renderer& renderer, OutputSet& out) {
  const auto& mesh = r.prepared.membrane.sheet;
  std::vector<double> all;
  for (const auto& f : r.frames)
    for (double v : f.stress) all.push_back(v * 1e-6);
  const auto [f_lo, f_hi] = symmetric_range(all, 1e-3);
  const Legend legend{"Stress (tension red)", "MPa", f_lo, f_hi};
  const int cols = std::min<int>(6, static_cast<int>(r.frames.size()));
  const int rows = (static_cast<int>(r.frames.size()) + cols - 1) / cols;
  const int tw = 400, th = 300;
  Renderer tiles(tw, th);
  Image sheet = blank_image(cols * tw, rows * th);
  for (size_t i = 0; i < r.frames.size(); ++i) {
    std::vector<double> mpa;
    for (double v : r.frames[i].stress) mpa.push_back(v * 1e-6);
    const auto colors = colorize(mpa, f_lo, f_hi);
    char name[64];
    std::snprintf(name, sizeof name, "frames/frame_%03zu.png", i + 1);
    add_png(out, name, renderer.render(r.frames[i].x, mesh.triangles, colors, camera, &legend));
    blit(sheet, tiles.render(r.frames[i].x, mesh.triangles, colors, camera, nullptr),
         static_cast<int>(i) % cols * tw, static_cast<int>(i) / cols * th);
  }
  add_png(out, "contact_sheet.png", sheet);
}

}  // namespace

std::string stage_run_pictures(const Scene& scene, const RunResult& r, const PictureOptions& opts,
                               OutputSet& out) {
  const auto& mesh = r.prepared.membrane.sheet;
  const auto& x = r.prepared.membrane.state.x;
  const RunColors c = run_colors(r, opts);
  const std::vector<Rgb> k_colors = colorize(c.curvature, c.k_lo, c.k_hi);
  if (const PatternPtr pattern = scene_pattern(scene))
    add_png(out, "pattern.png", draw_pattern(*pattern, scene_frame(scene), 4.0));
  std::string render_note;
  try {
    const OutputSpec& o = scene.output;
    const Camera camera{o.azimuth, o.elevation, 1.1};
    Renderer renderer(o.image_width, o.image_height);
    auto picture = [&](const std::string& file, const std::vector<Rgb>& colors,
                       const Legend& legend) {
      add_png(out, file, renderer.render(x, mesh.triangles, colors, camera, &legend));
    };
    picture("curvature.png", k_colors, {"Gaussian curvature", "1/mm^2", c.k_lo, c.k_hi});
    picture("stress.png", colorize(c.stress, c.s_lo, c.s_hi),
            {"Stress (tension red)", "MPa", c.s_lo, c.s_hi});
    if (r.curvature_map) stage_curvature_map(r, c, opts, camera, out);
    if (!r.frames.empty()) stage_frames(r, camera, renderer, out);
  } catch (const RenderError& e) {
    render_note = e.what();
  }
  return render_note;
}

}  // namespace membra
