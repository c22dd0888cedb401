#include "membra/render/design_pictures.hpp"

#include "membra/core/units.hpp"
#include "membra/geometry/orbit_camera.hpp"
#include "membra/render/renderer.hpp"
#include "membra/render/run_pictures.hpp"

namespace membra {

std::string stage_design_pictures(const DesignResult& d, OutputSet& out) {
  std::string note = stage_run_pictures(d.scene, d.run, {}, out);
  if (!note.empty()) return note;
  try {
    // One picture, one scale: the target in grey on the left, the form moved onto it on the
    // right (shifted sideways by 1.3 diameters as the camera sees it), coloured by its distance
    // to the target.
    Camera cam;
    cam.elevation = 25.0;
    OrbitCamera view;
    view.azimuth = cam.azimuth;
    view.elevation = cam.elevation;
    const Vec3 right = view.rotation().row(0).transpose();
    const Membrane& m = d.run.prepared.membrane;
    const Eigen::Index nt = d.target.x.cols(), nf = m.state.x.cols();
    Points both(3, nt + nf);
    both.leftCols(nt) = d.target.x.colwise() - 1.3 * d.target.diameter * right;
    for (Eigen::Index p = 0; p < nf; ++p) both.col(nt + p) = d.error.motion.apply(m.state.x.col(p));
    std::vector<Triangle> tris = d.target.triangles;
    for (Triangle t : m.sheet.triangles) {
      for (int& c : t) c += static_cast<int>(nt);
      tris.push_back(t);
    }
    const double hi = std::max(1e-3, d.error.max / units::mm);
    std::vector<Rgb> colors(static_cast<size_t>(nt), Rgb(0.8f, 0.8f, 0.8f));
    for (double v : d.error.form_distance) colors.push_back(colormap(v / units::mm, 0.0, hi));
    const Legend legend{"Target (grey) | form: distance to the target", "mm", 0.0, hi};
    Renderer renderer(1400, 700);
    const auto png = encode_png(renderer.render(both, tris, colors, cam, &legend));
    out.add("comparison.png", [png](std::ostream& os) {
      os.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
    });
  } catch (const RenderError& e) {
    return e.what();
  }
  return "";
}

}  // namespace membra
