#include "membra/render/design_outputs.hpp"

#include "membra/output/design_files.hpp"
#include "membra/output/report_page.hpp"
#include "membra/output/run_files.hpp"
#include "membra/render/design_pictures.hpp"

namespace membra {

std::string stage_design_outputs(const DesignResult& d, OutputSet& out) {
  stage_design_files(d, out);
  const std::string note = stage_design_pictures(d, out);
  stage_report_page(page_from_staged(out, "Design: " + d.scene.name, d.scene.description,
                                     run_scales(run_colors(d.run, {})),
                                     note.empty() ? "" : "No pictures could be rendered: " + note),
                    out);
  return note;
}

}  // namespace membra
