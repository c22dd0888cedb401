#include "membra/render/run_pictures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "membra/core/readable_units.hpp"
#include "membra/render/renderer.hpp"

namespace membra {
namespace {

void add_png(OutputSet& out, const std::string& file, const Image& img) {
  const auto png = encode_png(img);
  out.add(file, [png](std::ostream& os) {
    os.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  });
}

// Said in the heading of a picture whose form passes through itself, where its crossing
// triangles are outlined (docs/outputs.md).
std::string crossing_note(const RunResult& r) {
  return r.self_intersection.pairs > 0 ? "crosses itself (magenta)" : "";
}

// Side by side on one colour range: the target map and the measured curvature on the flat sheet
// (seen from above), and the form.
void paint_curvature_map(const RunResult& r, const RunStaging& s, const Camera& camera,
                         OutputSet& out) {
  const auto& mesh = r.prepared.membrane.sheet;
  const int pw = 800, ph = 700;
  Renderer panel(pw, ph);
  Image side = blank_image(3 * pw, ph);
  const Camera flat{-90.0, 89.9, 1.1, false};
  blit(side,
       panel.render(mesh.model.reference, mesh.triangles, s.target.rgb, flat, nullptr, "Target"), 0,
       0);
  blit(side,
       panel.render(mesh.model.reference, mesh.triangles, s.measured.rgb, flat, nullptr,
                    "Measured, on the flat sheet"),
       pw, 0);
  const Legend legend{"Gaussian curvature", "1/m^2", s.target.lo, s.target.hi, s.options.colormap};
  blit(side,
       panel.render(r.prepared.membrane.state.x, mesh.triangles, s.measured.rgb, camera, &legend,
                    "Form", r.self_intersection.triangles),
       2 * pw, 0);
  add_png(out, "curvature_map.png", side);
}

// Each frame, and a contact sheet that tiles them six to a row (the paper's figure 8 shows 24).
void paint_frames(const RunResult& r, const RunStaging& s, const Camera& camera, Renderer& renderer,
                  OutputSet& out) {
  const auto& mesh = r.prepared.membrane.sheet;
  const Legend legend{"Stress (tension red)", "MPa", s.frames[0].lo, s.frames[0].hi,
                      s.options.colormap};
  const int cols = std::min<int>(6, static_cast<int>(r.frames.size()));
  const int rows = (static_cast<int>(r.frames.size()) + cols - 1) / cols;
  const int tw = 400, th = 300;
  Renderer tiles(tw, th);
  Image sheet = blank_image(cols * tw, rows * th);
  for (size_t i = 0; i < r.frames.size(); ++i) {
    // A frame from before a continuum slit added particles has too few for the final mesh; its
    // tile stays blank. (Frames from before a hole are drawn on the final mesh, as they were.)
    if (r.frames[i].x.cols() < r.prepared.membrane.state.x.cols()) continue;
    const std::vector<Rgb>& colors = s.frames[i].rgb;
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

// The global form coloured by its own Gaussian curvature: where the bowl reads as a bowl.
void paint_global_form(const RunResult& r, const RunStaging& s, const Camera& camera,
                       Renderer& renderer, OutputSet& out) {
  if (s.global_form.cols() == 0) return;
  const Legend legend{"Global form: Gaussian curvature, averaged over 1/4 of the sheet across",
                      "1/m^2", s.global.lo, s.global.hi, s.options.colormap};
  add_png(out, "curvature_global.png",
          renderer.render(s.global_form, r.prepared.membrane.sheet.triangles, s.global.rgb, camera,
                          &legend));
}

// Each stable form of an exploration, on the main picture's curvature range.
void paint_branches(const RunResult& r, const RunStaging& s, const Camera& camera,
                    Renderer& renderer, OutputSet& out) {
  for (size_t b = 0; b < r.branches.size(); ++b) {
    const RunResult& f = r.branches[b].run;
    const Legend legend{"Branch " + std::to_string(b + 1) + ": Gaussian curvature", "1/m^2",
                        s.branches[b].lo, s.branches[b].hi, s.options.colormap};
    add_png(out, "branches/" + std::to_string(b + 1) + "/curvature.png",
            renderer.render(f.prepared.membrane.state.x, f.prepared.membrane.sheet.triangles,
                            s.branches[b].rgb, camera, &legend, crossing_note(f),
                            f.self_intersection.triangles));
  }
}

// The posed form's overall size, "218 x 163 x 81 mm" (its box along x, y and z), and the best-fit
// quadric's principal radii where it describes the form ("radii 92 / 174 mm").
std::string dimensions(const RunResult& r) {
  const Vec3 size = r.shape.bbox_max - r.shape.bbox_min;
  std::string text = box_dimensions(size.x(), size.y(), size.z());
  const QuadricFit& q = r.shape.quadric;
  if (q.valid && q.classification != "flat" && q.classification != "folded") {
    const auto radius = [](double k) { return std::abs(k) < 1e-3 ? 0.0 : 1e3 / k; };
    char radii[64];
    if (q.classification == "cylindrical")
      std::snprintf(radii, sizeof radii, ", radius %.0f mm", radius(q.k1));
    else
      std::snprintf(radii, sizeof radii, ", radii %.0f / %.0f mm", radius(q.k1), radius(q.k2));
    text.append(radii);
  }
  return text;
}

// The heading of the form's pictures: its size, and whether it passes through itself.
std::string caption(const RunResult& r) {
  const std::string note = crossing_note(r);
  return note.empty() ? dimensions(r) : dimensions(r) + " \u00b7 " + note;
}

// The form three ways, as a drawing shows a piece (docs/outputs.md, "The pose"): the 3/4 view
// of the other pictures, and orthographic views from the top and from the front (-y), each with
// its dimensions and a scale bar.
// Drawn with the run's renderer, at its size (three panels side by side).
void paint_views(const RunResult& r, const RunStaging& s, const Camera& camera, Renderer& panel,
                 int pw, int ph, OutputSet& out) {
  const auto& x = r.prepared.membrane.state.x;
  const auto& tris = r.prepared.membrane.sheet.triangles;
  const Vec3 size = (r.shape.bbox_max - r.shape.bbox_min) * 1e3;
  Image views = blank_image(3 * pw, ph);
  char top[64], side[64];
  std::snprintf(top, sizeof top, "Top: %.0f \u00d7 %.0f mm", size.x(), size.y());
  std::snprintf(side, sizeof side, "Front: %.0f \u00d7 %.0f mm", size.x(), size.z());
  const bool fixed = s.options.curvature_range.size() == 2;
  const Legend legend{fixed ? "Gaussian curvature" : "Gaussian curvature (95% in range)", "1/m^2",
                      s.colors.k_lo, s.colors.k_hi, s.options.colormap};
  const std::vector<int>& crossing = r.self_intersection.triangles;
  blit(views,
       panel.render(x, tris, s.curvature_rgb, camera, nullptr, "3/4 view: " + caption(r), crossing),
       0, 0);
  Camera from_top{-90.0, 90.0, 1.15, false, true};
  blit(views, panel.render(x, tris, s.curvature_rgb, from_top, nullptr, top, crossing), pw, 0);
  Camera from_front{-90.0, 0.0, 1.15, false, true};
  blit(views, panel.render(x, tris, s.curvature_rgb, from_front, &legend, side, crossing), 2 * pw,
       0);
  add_png(out, "views.png", views);
}

}  // namespace

std::string stage_run_pictures(const Scene& scene, const RunResult& r, const RunStaging& s,
                               OutputSet& out) {
  const auto& mesh = r.prepared.membrane.sheet;
  const auto& x = r.prepared.membrane.state.x;
  const RunColors& c = s.colors;
  if (s.top || s.bottom)
    add_png(out, "pattern.png", draw_pattern(s.top.get(), s.frame, 4.0, s.bottom.get()));
  std::string render_note;
  try {
    const OutputSpec& o = scene.output;
    const Camera camera{o.azimuth, o.elevation, 1.1};
    Renderer renderer(o.image_width, o.image_height);
    auto picture = [&](const std::string& file, const std::vector<Rgb>& colors,
                       const Legend& legend) {
      add_png(out, file,
              renderer.render(x, mesh.triangles, colors, camera, &legend, caption(r),
                              r.self_intersection.triangles));
    };
    const bool fixed = s.options.curvature_range.size() == 2;
    picture("curvature.png", s.curvature_rgb,
            {fixed ? "Gaussian curvature" : "Gaussian curvature (95% in range)", "1/m^2", c.k_lo,
             c.k_hi, s.options.colormap});
    paint_views(r, s, camera, renderer, o.image_width, o.image_height, out);
    paint_global_form(r, s, camera, renderer, out);
    paint_branches(r, s, camera, renderer, out);
    picture("stress.png", s.stress_rgb,
            {"Stress (tension red)", "MPa", c.s_lo, c.s_hi, s.options.colormap});
    if (r.curvature_map) paint_curvature_map(r, s, camera, out);
    if (!r.frames.empty()) paint_frames(r, s, camera, renderer, out);
  } catch (const RenderError& e) {
    render_note = e.what();
  }
  return render_note;
}

}  // namespace membra
