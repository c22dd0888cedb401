#include "membra/render/run_pictures.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>

#include "membra/measure/colormap.hpp"
#include "membra/measure/shape.hpp"
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
  const std::vector<Rgb> measured = colorize(c.curvature, t_lo, t_hi);
  Image side = blank_image(3 * pw, ph);
  const Camera flat{-90.0, 89.9, 1.1, false};
  blit(side,
       panel.render(mesh.model.reference, mesh.triangles, colorize(target_mm, t_lo, t_hi), flat,
                    nullptr, "Target"),
       0, 0);
  blit(side,
       panel.render(mesh.model.reference, mesh.triangles, measured, flat, nullptr,
                    "Measured, on the flat sheet"),
       pw, 0);
  const Legend legend{"Gaussian curvature", "1/mm^2", t_lo, t_hi};
  blit(side, panel.render(x, mesh.triangles, measured, camera, &legend, "Form"), 2 * pw, 0);
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
    char caption[32];
    std::snprintf(caption, sizeof caption, "%zu", i + 1);
    blit(sheet, tiles.render(r.frames[i].x, mesh.triangles, colors, camera, nullptr, caption),
         static_cast<int>(i) % cols * tw, static_cast<int>(i) / cols * th);
  }
  add_png(out, "contact_sheet.png", sheet);
}

// The global form (wrinkles finer than the window averaged out, measure/shape.hpp) coloured by
// its own Gaussian curvature: where the bowl reads as a bowl.
void stage_global_form(const RunResult& r, const PictureOptions& opts, const Camera& camera,
                       Renderer& renderer, OutputSet& out) {
  const auto& mesh = r.prepared.membrane.sheet;
  const Points global = global_form(r.prepared.membrane.state.x, mesh.model.reference);
  if (global.cols() != r.prepared.membrane.state.x.cols()) return;
  std::vector<double> k, interior;
  for (double v : r.curvature_global.density) k.push_back(v * 1e-6);  // 1/m^2 to 1/mm^2
  // The range from the particles a window (1/8 of the sheet) or more inside the edge: the
  // averaging window is cut off at the edge, which bends the global form's rim more sharply
  // than the form itself.
  const GridSheet& g = mesh.grid;
  for (int p = 0; p < g.num_particles(); ++p) {
    const auto [i, j] = g.node(p);
    if (8 * i >= g.nx() && 8 * i <= 7 * g.nx() && 8 * j >= g.ny() && 8 * j <= 7 * g.ny())
      interior.push_back(k[static_cast<size_t>(p)]);
  }
  if (mesh.continuum())
    for (int p = 0; p < mesh.model.num_particles(); ++p) {
      const Vec2 u =
          mesh.model.reference.col(p).head<2>().cwiseQuotient(Vec2(g.width(), g.height()));
      if ((u.array() >= 0.125).all() && (u.array() <= 0.875).all())
        interior.push_back(k[static_cast<size_t>(p)]);
    }
  auto [lo, hi] =
      symmetric_percentile_range(interior.empty() ? k : interior, kCurvaturePercentile, 1e-6);
  if (opts.curvature_range.size() == 2) lo = opts.curvature_range[0], hi = opts.curvature_range[1];
  const Legend legend{"Global form: Gaussian curvature, averaged over 1/4 of the sheet across",
                      "1/mm^2", lo, hi};
  add_png(out, "curvature_global.png",
          renderer.render(global, mesh.triangles, colorize(k, lo, hi), camera, &legend));
}

// Each stable form of an exploration, on the main picture's curvature range.
void stage_branches(const RunResult& r, const RunColors& c, const Camera& camera,
                    Renderer& renderer, OutputSet& out) {
  for (size_t b = 0; b < r.branches.size(); ++b) {
    const RunResult& f = r.branches[b].run;
    std::vector<double> k;
    for (double v : f.curvature.density) k.push_back(v * 1e-6);
    const Legend legend{"Branch " + std::to_string(b + 1) + ": Gaussian curvature", "1/mm^2",
                        c.k_lo, c.k_hi};
    add_png(out, "branches/" + std::to_string(b + 1) + "/curvature.png",
            renderer.render(f.prepared.membrane.state.x, f.prepared.membrane.sheet.triangles,
                            colorize(k, c.k_lo, c.k_hi), camera, &legend));
  }
}

}  // namespace

std::string stage_run_pictures(const Scene& scene, const RunResult& r, const PictureOptions& opts,
                               OutputSet& out) {
  const auto& mesh = r.prepared.membrane.sheet;
  const auto& x = r.prepared.membrane.state.x;
  const RunColors c = run_colors(r, opts);
  const std::vector<Rgb> k_colors = colorize(c.curvature, c.k_lo, c.k_hi);
  const PatternPtr top = scene_pattern(scene, false), bottom = scene_pattern(scene, true);
  if (top || bottom)
    add_png(out, "pattern.png", draw_pattern(top.get(), scene_frame(scene), 4.0, bottom.get()));
  std::string render_note;
  try {
    const OutputSpec& o = scene.output;
    const Camera camera{o.azimuth, o.elevation, 1.1};
    Renderer renderer(o.image_width, o.image_height);
    auto picture = [&](const std::string& file, const std::vector<Rgb>& colors,
                       const Legend& legend) {
      add_png(out, file, renderer.render(x, mesh.triangles, colors, camera, &legend));
    };
    const bool fixed = opts.curvature_range.size() == 2;
    picture("curvature.png", k_colors,
            {fixed ? "Gaussian curvature" : "Gaussian curvature (95% in range)", "1/mm^2", c.k_lo,
             c.k_hi});
    stage_global_form(r, opts, camera, renderer, out);
    stage_branches(r, c, camera, renderer, out);
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
