#include "design_command.hpp"

#include <cstdio>
#include <iostream>

#include "membra/design/design_stretch.hpp"
#include "membra/design/design_verdict.hpp"
#include "membra/io/design_reader.hpp"
#include "membra/output/calibration_store.hpp"
#include "membra/output/design_files.hpp"
#include "membra/output/output_set.hpp"
#include "membra/render/design_outputs.hpp"

namespace membra::cli {
namespace {

// "stencil: N pieces on top, M underneath" when the stencil has pieces on both faces.
std::string faces_line(const DesignResult& r) {
  const int under = r.stencil.pieces_bottom();
  if (under == 0) return "";
  return "stencil: " + std::to_string(r.stencil.pieces - under) + " pieces on top, " +
         std::to_string(under) + " underneath (blue in pattern.svg)\n";
}

}  // namespace

int cmd_design(const DesignArgs& args) {
  DesignSpec spec = load_design(args.file);
  if (const auto dir = default_cache_dir(); !args.no_cache && !dir.empty())
    spec.calibration_cache = calibration_store(dir);
  const std::string dir = args.out_dir.empty() ? "out/" + spec.name : args.out_dir;
  OutputSet out(dir);
  if (!args.quiet)
    std::cerr << "membra design: " << spec.target.kind << " target, " << spec.method << ", at most "
              << spec.evaluations
              << (spec.method == "adjoint" ? " evaluations" : " forward simulations") << " or "
              << spec.budget << " s\n";
  const DesignResult r = run_design(spec, [&](const DesignIteration& it) {
    if (args.quiet) return;
    char line[200];
    if (it.adjoint_iterate()) {  // distance to its own target points
      std::snprintf(
          line, sizeof line,
          "  %3d  %starget points rms %6.2f %%  objective %.4g  |gradient| %.3g  %6.1f s%s%s%s\n",
          it.index, it.stage == "pieces" ? "pieces: " : "", it.rms_error, it.objective,
          it.gradient_norm, it.seconds, it.best ? "  best" : "", it.note.empty() ? "" : "  ",
          it.note.c_str());
      std::cerr << line;
      return;
    }
    char scale[48] = "", darts[24] = "";
    if (it.scale != 1.0) std::snprintf(scale, sizeof scale, "  densities x%.2f", it.scale);
    if (spec.layout.has_darts())  // their width over what the target's metric asks
      std::snprintf(darts, sizeof darts, "  darts x%.2f", it.parameters.darts);
    if (spec.search_stretch) {  // the stretch this stencil was simulated at
      const Vec2 l = stretched_lambda(spec.lambda, it.parameters.stretch);
      std::snprintf(scale, sizeof scale, "  lambda %.2f x %.2f", l.x(), l.y());
    }
    std::snprintf(
        line, sizeof line,
        "  %3d  rms %6.2f %%  max %6.2f %%  resin %4.0f %%  %3d pieces  %6.1f s%s%s%s%s%s\n",
        it.index, it.rms_error, it.max_error, 100.0 * it.resin_share, it.pieces, it.seconds, darts,
        scale, it.best ? "  best" : "", it.note.empty() ? "" : "  ", it.note.c_str());
    std::cerr << line;
  });
  const std::string note = stage_design_outputs(r, out);
  out.commit();
  if (!note.empty()) std::cerr << "membra: warning: no PNG renders: " << note << "\n";
  if (!args.quiet)
    std::cout << "design: rms error " << r.rms_error << " %, max " << r.max_error
              << " % of the target's diameter after " << r.history.size() << " simulations ("
              << r.seconds << " s); a flat sheet scores " << r.flat_error << " %\n"
              << faces_line(r) << "verdict: " << design_verdict(r).sentence << "\n"
              << (r.reachable && !r.message.empty() ? "note: " + r.message + "\n" : "")
              << "results in " << out.dir().string()
              << "/ (scene.json, pattern.svg, pattern.dxf, final.obj, final.ply, "
                 "comparison.png, report.json, report.html)\n";
  if (!r.reachable) {
    std::cerr << "membra: " << args.file << ": the target cannot be reached: " << r.message
              << "\nmembra: the best attempt is in " << out.dir().string() << "/\n";
    return 5;  // main.cpp's kUnreachable
  }
  return 0;
}

}  // namespace membra::cli
