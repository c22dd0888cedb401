#include "membra/render/run_outputs.hpp"

#include "membra/io/scene_writer.hpp"
#include "membra/output/report.hpp"
#include "membra/render/run_pictures.hpp"

namespace membra {

StagedRun stage_run_outputs(const Scene& scene, const RunResult& r, const PictureOptions& opts,
                            OutputSet& out) {
  const nlohmann::json report = make_report(scene, r);
  out.add("report.json", [&](std::ostream& os) { os << report.dump(2) << '\n'; });
  if (r.solve.diverged) {
    // A diverged state is no form: its page says so and shows the report's numbers only.
    ReportPage page = page_from_staged(out, scene.name, scene.description, {},
                                       "The run diverged: " + r.solve.message);
    page.scene = write_scene(scene);  // the inputs matter most when the form is missing
    stage_report_page(page, out);
    return {true, ""};
  }
  // What the outputs show first, then the writers.
  const RunStaging staging = prepare_run_staging(scene, r, opts);
  stage_run_files(scene, r, staging, out);
  const std::string note = stage_run_pictures(scene, r, staging, out);
  ReportPage page = page_from_staged(out, scene.name, scene.description,
                                     run_scales(staging.colors, staging.options.colormap),
                                     note.empty() ? "" : "No pictures could be rendered: " + note);
  page.scene = write_scene(scene);
  stage_report_page(page, out);
  return {false, note};
}

}  // namespace membra
