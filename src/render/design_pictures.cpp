#include "membra/render/design_pictures.hpp"

#include <algorithm>

#include "membra/core/units.hpp"
#include "membra/geometry/orbit_camera.hpp"
#include "membra/render/renderer.hpp"
#include "membra/render/run_pictures.hpp"

namespace membra {

namespace {

// density.png (adjoint designs): the optimised densities on the frame seen from above, one flat
// square per cell in its own colour.
void stage_density_picture(const DensityField& f, Renderer& renderer, OutputSet& out) {
  const int n = static_cast<int>(f.value.size());
  Points x(3, 4 * n);
  std::vector<Triangle> tris;
  std::vector<Rgb> colors;
  const Vec2 h = 0.5 * f.cell_size();
  // The colours span the design's own range, so that its pattern shows (the legend says which).
  double lo = f.value.minCoeff(), hi = f.value.maxCoeff();
  if (hi - lo < 1e-3) lo = std::max(0.0, lo - 0.05), hi = std::min(1.0, hi + 0.05);
  for (int c = 0; c < n; ++c) {
    const Vec2 m = f.centre(c);
    const Vec2 corner[4] = {m - h, m + Vec2(h.x(), -h.y()), m + h, m + Vec2(-h.x(), h.y())};
    for (int k = 0; k < 4; ++k) {
      x.col(4 * c + k) = Vec3(corner[k].x(), corner[k].y(), 0.0);
      colors.push_back(colormap(f.value[c], lo, hi, ColourMap::sequential));
    }
    tris.emplace_back(4 * c, 4 * c + 1, 4 * c + 2);
    tris.emplace_back(4 * c, 4 * c + 2, 4 * c + 3);
  }
  const Camera top{-90.0, 89.0, 1.1, false};
  const Legend legend{"Resin density per cell (0: bare latex, 1: resin), the frame from above", "",
                      lo, hi, ColourMap::sequential};
  const auto png = encode_png(renderer.render(x, tris, colors, top, &legend));
  out.add("density.png", [png](std::ostream& os) {
    os.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  });
}

// One picture, one scale: the target in grey on the left, the form (positions x, moved onto the
// target by error.motion) on the right, shifted sideways by 1.3 diameters as the camera sees it,
// coloured by its distance to the target.
void stage_comparison(const TargetSurface& target, const Points& x,
                      const std::vector<Triangle>& triangles, const ShapeError& error,
                      const std::string& title, const std::string& file, Renderer& renderer,
                      OutputSet& out) {
  Camera cam;
  cam.elevation = 25.0;
  OrbitCamera view;
  view.azimuth = cam.azimuth;
  view.elevation = cam.elevation;
  const Vec3 right = view.rotation().row(0).transpose();
  const Eigen::Index nt = target.x.cols(), nf = x.cols();
  Points both(3, nt + nf);
  both.leftCols(nt) = target.x.colwise() - 1.3 * target.diameter * right;
  for (Eigen::Index p = 0; p < nf; ++p) both.col(nt + p) = error.motion.apply(x.col(p));
  std::vector<Triangle> tris = target.triangles;
  for (Triangle t : triangles) {
    for (int& c : t) c += static_cast<int>(nt);
    tris.push_back(t);
  }
  const double hi = std::max(1e-3, error.max / units::mm);
  std::vector<Rgb> colors(static_cast<size_t>(nt), Rgb(0.8f, 0.8f, 0.8f));
  for (double v : error.form_distance)
    colors.push_back(colormap(v / units::mm, 0.0, hi, ColourMap::sequential));
  const Legend legend{title, "mm", 0.0, hi, ColourMap::sequential};
  const auto png = encode_png(renderer.render(both, tris, colors, cam, &legend));
  out.add(file, [png](std::ostream& os) {
    os.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  });
}

}  // namespace

std::string stage_design_pictures(const DesignResult& d, const RunStaging& s, OutputSet& out) {
  std::string note = stage_run_pictures(d.scene, d.run, s, out);
  if (!note.empty()) return note;
  try {
    Renderer renderer(1400, 700);
    const Membrane& m = d.run.prepared.membrane;
    stage_comparison(d.target, m.state.x, m.sheet.triangles, d.error,
                     "Target (grey) | form: distance to the target", "comparison.png", renderer,
                     out);
    if (d.method == "adjoint" && d.density.value.size() > 0) {
      stage_density_picture(d.density, renderer, out);
      if (d.density_form.cols() > 0)
        stage_comparison(d.target, d.density_form, m.sheet.triangles, d.density_error,
                         "Target (grey) | the density design's form: distance to the target",
                         "comparison_density.png", renderer, out);
    }
  } catch (const RenderError& e) {
    return e.what();
  }
  return "";
}

}  // namespace membra
