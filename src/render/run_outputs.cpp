#include "membra/render/run_outputs.hpp"

#include "membra/output/report.hpp"
#include "membra/render/run_pictures.hpp"

namespace membra {

StagedRun stage_run_outputs(const Scene& scene, const RunResult& r, const PictureOptions& opts,
                            OutputSet& out) {
  const nlohmann::json report = make_report(scene, r);
  out.add("report.json", [&](std::ostream& os) { os << report.dump(2) << '\n'; });
  if (r.solve.diverged) {
    // A diverged state is no form: its page says so and shows the report's numbers only.
    stage_report_page(page_from_staged(out, scene.name, scene.description, {},
                                       "The run diverged: " + r.solve.message),
                      out);
    return {true, ""};
  }
  // What the outputs show first, then the writers.
  const RunStaging staging = prepare_run_staging(scene, r, opts);
  stage_run_files(scene, r, staging, out);
  const std::string note = stage_run_pictures(scene, r, staging, out);
  stage_report_page(page_from_staged(out, scene.name, scene.description, run_scales(staging.colors),
                                     note.empty() ? "" : "No pictures could be rendered: " + note),
                    out);
  return {false, note};
}

}  // namespace membra
