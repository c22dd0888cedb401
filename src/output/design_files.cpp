#include "membra/output/design_files.hpp"

#include <cmath>

#include "membra/core/units.hpp"
#include "membra/design/design_verdict.hpp"
#include "membra/io/obj.hpp"
#include "membra/output/report.hpp"

namespace membra {

namespace {

// A number, or null where there is none (a failed equilibrium): never NaN or inf in the file.
nlohmann::json number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

// `darts`: the stencil is laid out as darts, whose scale is then the parameter that counts.
nlohmann::json params(const DensityParameters& p, bool darts) {
  nlohmann::json j = {
      {"mean", p.mean}, {"radial", p.radial}, {"anisotropy", p.anisotropy}, {"stretch", p.stretch}};
  if (darts) j["darts"] = p.darts;
  return j;
}

nlohmann::json iteration(const DesignIteration& it, bool darts) {
  if (it.adjoint_iterate())  // no stencil simulated from flat: distances to its own points
    return {{"index", it.index},
            {"stage", it.stage},
            {"correspondence_rms", number(it.rms_error)},
            {"objective", number(it.objective)},
            {"gradient_norm", number(it.gradient_norm)},
            {"seconds", it.seconds},
            {"best", it.best},
            {"note", it.note}};
  return {{"index", it.index},
          {"stage", it.stage},
          {"rms_error", number(it.rms_error)},
          {"max_error", number(it.max_error)},
          {"resin_share", it.resin_share},
          {"pieces", it.pieces},
          {"density_scale", it.scale},
          {"seconds", it.seconds},
          {"best", it.best},
          {"note", it.note},
          {"parameters", params(it.parameters, darts)}};
}

// The adjoint method's own keys (docs/inverse_design.md).
void add_adjoint(const DesignResult& d, nlohmann::json& a) {
  a["density_rms_error"] = number(d.density_rms_error);
  a["stopped"] = d.stopped;
  a["reach"] = {{"unreachable_share", d.unreachable_share},
                {"asks_min", d.asks_min},
                {"asks_max", d.asks_max}};
  a["calibration"] = {{"share", d.calibration_share},
                      {"density", d.calibration_density},
                      {"cached", d.calibration_cached}};
  a["density"] = {{"cells", {d.density.nx, d.density.ny}},
                  {"cell_mm", d.density.cell_size().x() / units::mm},
                  {"values", std::vector<double>(d.density.value.data(),
                                                 d.density.value.data() + d.density.value.size())}};
}

}  // namespace

nlohmann::json make_design_report(const DesignResult& d) {
  nlohmann::json report = make_report(d.scene, d.run);
  nlohmann::json iterations = nlohmann::json::array();
  const bool darts = d.spec.layout.has_darts();
  for (const DesignIteration& it : d.history) iterations.push_back(iteration(it, darts));
  const DesignVerdict verdict = design_verdict(d);
  report["design"] = {
      {"method", d.method},
      {"rms_error", number(d.rms_error)},
      {"max_error", number(d.max_error)},
      {"error_unit", "% of the target's diameter (square: side), after rigid alignment"},
      {"flat_error", d.flat_error},
      {"lambda", {d.spec.lambda.x(), d.spec.lambda.y()}},
      {"verdict", verdict.grade},
      {"verdict_note", verdict.sentence},
      {"reachable", d.reachable},
      {"message", d.message},
      {"target",
       {{"kind", d.target.kind},
        {"diameter_mm", d.target.diameter / units::mm},
        {"area_mm2", d.target.area / (units::mm * units::mm)}}},
      {"stencil",
       {{"pieces", d.stencil.pieces},
        {"pieces_bottom", d.stencil.pieces_bottom()},
        {"resin_side", d.spec.resin_side},
        {"bilayer", d.spec.bilayer},
        {"resin_share", d.stencil.resin_share},
        {"layout", d.spec.layout.kind},
        {"darts", darts ? d.spec.layout.darts : 0},
        {"cell_mm", d.spec.layout.cell / units::mm},
        {"min_feature_mm", d.spec.layout.min_feature / units::mm}}},
      {"start", params(d.start, darts)},
      {"best", params(d.best, darts)},
      {"evaluations", d.history.size()},
      {"seconds", d.seconds},
      {"iterations", iterations}};
  if (d.method == "adjoint") add_adjoint(d, report["design"]);
  if (!d.spec.layout.centres.empty()) {
    nlohmann::json centres = nlohmann::json::array();
    for (const Vec2& c : d.spec.layout.centres)
      centres.push_back({c.x() / units::mm, c.y() / units::mm});
    report["design"]["stencil"]["dart_centres_mm"] = centres;
    report["design"]["stencil"]["dart_centres_found"] = d.spec.layout.auto_centres;
  }
  return report;
}

void stage_design_files(const DesignResult& d, const RunStaging& s, OutputSet& out) {
  const nlohmann::json scene_file = design_scene(d.spec, d.stencil);
  out.add("scene.json", [scene_file](std::ostream& os) { os << scene_file.dump(2) << '\n'; });
  out.add("target.obj", [&](std::ostream& os) { write_obj(os, d.target.x, d.target.triangles); });
  const nlohmann::json report = make_design_report(d);
  out.add("report.json", [report](std::ostream& os) { os << report.dump(2) << '\n'; });
  stage_run_files(d.scene, d.run, s, out);
}

}  // namespace membra
