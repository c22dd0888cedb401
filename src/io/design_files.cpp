#include "membra/io/design_files.hpp"

#include "membra/core/units.hpp"
#include "membra/io/obj.hpp"
#include "membra/io/report.hpp"

namespace membra {

nlohmann::json make_design_report(const DesignResult& d) {
  nlohmann::json report = make_report(d.scene, d.run);
  auto params = [](const DensityParameters& p) {
    return nlohmann::json{{"mean", p.mean}, {"radial", p.radial}, {"anisotropy", p.anisotropy}};
  };
  nlohmann::json iterations = nlohmann::json::array();
  for (const DesignIteration& it : d.history) {
    if (it.stage == "density") {  // an adjoint iterate: no stencil, distances to own points
      iterations.push_back({{"index", it.index},
                            {"stage", it.stage},
                            {"correspondence_rms", it.rms_error},
                            {"objective", it.objective},
                            {"gradient_norm", it.gradient_norm},
                            {"seconds", it.seconds},
                            {"best", it.best},
                            {"note", it.note}});
      continue;
    }
    iterations.push_back({{"index", it.index},
                          {"stage", it.stage},
                          {"rms_error", it.rms_error},
                          {"max_error", it.max_error},
                          {"resin_share", it.resin_share},
                          {"pieces", it.pieces},
                          {"seconds", it.seconds},
                          {"best", it.best},
                          {"note", it.note},
                          {"parameters", params(it.parameters)}});
  }
  report["design"] = {
      {"method", d.method},
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
  if (d.method == "adjoint") {
    nlohmann::json& a = report["design"];
    a["density_rms_error"] = d.density_rms_error;
    a["stopped"] = d.stopped;
    a["reach"] = {{"unreachable_share", d.unreachable_share},
                  {"asks_min", d.asks_min},
                  {"asks_max", d.asks_max}};
    a["calibration"] = {{"share", d.calibration_share}, {"density", d.calibration_density}};
    a["density"] = {
        {"cells", {d.density.nx, d.density.ny}},
        {"cell_mm", d.density.cell_size().x() / units::mm},
        {"values", std::vector<double>(d.density.value.data(),
                                       d.density.value.data() + d.density.value.size())}};
  }
  return report;
}

void stage_design_files(const DesignResult& d, OutputSet& out) {
  const nlohmann::json scene_file = design_scene(d.spec, d.stencil);
  out.add("scene.json", [scene_file](std::ostream& os) { os << scene_file.dump(2) << '\n'; });
  out.add("target.obj", [&](std::ostream& os) { write_obj(os, d.target.x, d.target.triangles); });
  const nlohmann::json report = make_design_report(d);
  out.add("report.json", [report](std::ostream& os) { os << report.dump(2) << '\n'; });
  stage_run_files(d.scene, d.run, {}, out);
}

}  // namespace membra
