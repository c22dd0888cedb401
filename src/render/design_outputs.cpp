#include "membra/render/design_outputs.hpp"

#include "membra/io/scene_writer.hpp"
#include "membra/output/design_files.hpp"
#include "membra/output/report_page.hpp"
#include "membra/output/run_files.hpp"
#include "membra/render/design_pictures.hpp"

namespace membra {

std::string stage_design_outputs(const DesignResult& d, OutputSet& out) {
  // What the outputs show first, then the writers.
  const RunStaging staging = prepare_run_staging(d.scene, d.run, {});
  stage_design_files(d, staging, out);
  const std::string note = stage_design_pictures(d, staging, out);
  ReportPage page = page_from_staged(out, "Design: " + d.scene.name, d.scene.description,
                                     run_scales(staging.colors, staging.options.colormap),
                                     note.empty() ? "" : "No pictures could be rendered: " + note);
  page.scene = write_scene(d.scene);
  stage_report_page(page, out);
  return note;
}

}  // namespace membra
