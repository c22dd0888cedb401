#include "membra/render/design_outputs.hpp"

#include "membra/core/units.hpp"
#include "membra/geometry/orbit_camera.hpp"
#include "membra/io/obj.hpp"
#include "membra/io/report.hpp"
#include "membra/io/scene.hpp"
#include "membra/render/renderer.hpp"
#include "membra/render/run_outputs.hpp"

namespace membra {

namespace {

nlohmann::json design_report(const DesignResult& d, const Scene& scene) {
  nlohmann::json report = make_report(scene, d.run);
  auto params = [](const DensityParameters& p) {
    return nlohmann::json{{"mean", p.mean}, {"radial", p.radial}, {"anisotropy", p.anisotropy}};
  };
  nlohmann::json iterations = nlohmann::json::array();
  for (const DesignIteration& it : d.history)
    iterations.push_back({{"index", it.index},
                          {"rms_error", it.rms_error},
                          {"max_error", it.max_error},
                          {"resin_share", it.resin_share},
                          {"pieces", it.pieces},
                          {"seconds", it.seconds},
                          {"best", it.best},
                          {"note", it.note},
                          {"parameters", params(it.parameters)}});
  report["design"] = {
      {"rms_error", d.rms_error},
      {"max_error", d.max_error},
      {"error_unit", "% of the target's diameter (square: side), after rigid alignment"},
      {"flat_error", d.flat_error},
      {"reachable", d.reachable},
      {"message", d.message},
      {"target",
       {{"kind", d.target.kind},
        {"diameter_mm", d.target.diameter / units::mm},
        {"area_mm2", d.target.area / (units::mm * units::mm)}}},
      {"stencil",
       {{"pieces", d.stencil.pieces},
        {"resin_share", d.stencil.resin_share},
        {"cell_mm", d.spec.layout.cell / units::mm},
        {"min_feature_mm", d.spec.layout.min_feature / units::mm}}},
      {"start", params(d.start)},
      {"best", params(d.best)},
      {"evaluations", d.history.size()},
      {"seconds", d.seconds},
      {"iterations", iterations}};
  return report;
}

}  // namespace

nlohmann::json make_design_report(const DesignResult& d) {
  return design_report(d, d.scene);
}

std::string stage_design_outputs(const DesignResult& d, OutputSet& out) {
  const nlohmann::json scene_file = design_scene(d.spec, d.stencil);
  out.add("scene.json", [&](std::ostream& os) { os << scene_file.dump(2) << '\n'; });
  out.add("target.obj", [&](std::ostream& os) { write_obj(os, d.target.x, d.target.triangles); });
  const Scene& scene = d.scene;
  const nlohmann::json report = design_report(d, scene);
  out.add("report.json", [report](std::ostream& os) { os << report.dump(2) << '\n'; });
  std::string note = stage_run_outputs(scene, d.run, {}, out);
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
    const Legend legend{"target | form: distance", "mm", 0.0, hi};
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
