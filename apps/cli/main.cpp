// membra: the command-line tool. Thin: it parses arguments, calls the library and reports.
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench_command.hpp"
#include "design_command.hpp"
#include "membra/core/input_error.hpp"
#include "membra/io/output_set.hpp"
#include "membra/io/report.hpp"
#include "membra/io/run_files.hpp"
#include "membra/io/scene.hpp"
#include "membra/process/run.hpp"
#include "membra/render/run_pictures.hpp"
#include "membra/version.hpp"
#include "membra/view/view_script.hpp"
#include "progress_bar.hpp"
#include "view_command.hpp"

namespace {

// Exit codes, documented in docs/cli.md.
enum Exit : int {
  kOk = 0,
  kInternal = 1,
  kBadInput = 2,
  kDiverged = 3,
  kOutput = 4,
  kUnreachable = 5,  // membra design: the target cannot be reached (best attempt written)
  kNoDisplay = 6     // membra view: no window can be opened
};

int cmd_validate(const std::string& scene_file, const std::vector<std::string>& sets, bool quiet) {
  const membra::Scene scene = membra::load_scene(scene_file, sets);
  try {
    const membra::PreparedScene p = membra::prepare_scene(scene);
    if (!quiet)
      std::cout << scene_file << ": valid (" << p.membrane.sheet.model.num_particles()
                << " particles, " << p.membrane.sheet.model.springs.size() << " springs, "
                << p.pinned << " pinned)\n";
  } catch (const membra::InputError& e) {
    throw membra::InputError(scene_file + ": " + e.where(), e.detail());
  }
  return kOk;
}

int cmd_run(const std::string& scene_file, const std::vector<std::string>& sets,
            std::string out_dir, bool quiet, const membra::PictureOptions& opts) {
  const membra::Scene scene = membra::load_scene(scene_file, sets);
  try {
    (void)membra::prepare_scene(scene);  // fail on bad input before touching the disk
  } catch (const membra::InputError& e) {
    throw membra::InputError(scene_file + ": " + e.where(), e.detail());
  }
  if (out_dir.empty()) out_dir = "out/" + scene.name;
  membra::OutputSet out(out_dir);

  membra::cli::ProgressBar bar(!quiet);
  const membra::RunResult r =
      membra::run_scene(scene, [&](const membra::Progress& p) { bar.update(p); });
  bar.finish();
  const nlohmann::json report = membra::make_report(scene, r);
  out.add("report.json", [&](std::ostream& os) { os << report.dump(2) << '\n'; });
  if (r.solve.diverged) {
    // A diverged state is no form: only the report is written, and it says so.
    out.commit();
    std::cerr << "membra: " << scene_file << ": " << r.solve.message << "\n"
              << "membra: wrote only " << (out.dir() / "report.json").string() << "\n";
    return kDiverged;
  }
  if (r.curvature_map && !r.curvature_map->message.empty())
    std::cerr << "membra: warning: " << scene_file << ": " << r.curvature_map->step << ": "
              << r.curvature_map->message << "\n";
  membra::stage_run_files(scene, r, opts, out);
  const std::string render_note = membra::stage_run_pictures(scene, r, opts, out);
  if (!render_note.empty()) std::cerr << "membra: warning: no PNG renders: " << render_note << "\n";
  out.commit();
  if (!quiet) {
    std::cout << r.solve.message << " in " << r.solve.wall_seconds << " s\n"
              << "results in " << out.dir().string() << "/ (final.obj, final.ply, report.json"
              << (render_note.empty() ? ", curvature.png, stress.png" : "") << ")\n";
  }
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"membra: form-finding for pre-stretched, resin-impregnated membranes"};
  app.set_version_flag("--version", std::string("membra ") + membra::kVersion);
  app.require_subcommand(1);

  std::string scene_file, out_dir;
  std::vector<std::string> sets;
  bool quiet = false;
  const char* set_help =
      "Override a scene value before validation, e.g. --set simulation.steps=500";
  auto* run = app.add_subcommand("run", "Run a scene and write its results");
  run->add_option("scene", scene_file, "Scene file (JSON)")->required();
  run->add_option("--out,-o", out_dir, "Output directory (default: out/<scene name>)");
  run->add_option("--set", sets, set_help)->type_name("PATH=VALUE");
  membra::PictureOptions run_opts;
  run->add_option(
         "--curvature-range", run_opts.curvature_range,
         "Colour range of curvature.png and final.ply, 1/mm^2 (default: symmetric, automatic)")
      ->expected(2)
      ->allow_extra_args(false)
      ->type_name("LO HI");
  run->add_option("--stress-range", run_opts.stress_range,
                  "Colour range of stress.png, MPa (default: symmetric, automatic)")
      ->expected(2)
      ->allow_extra_args(false)
      ->type_name("LO HI");
  run->add_flag("--quiet,-q", quiet, "No progress bar or summary");

  auto* validate = app.add_subcommand("validate", "Check a scene without running it");
  validate->add_option("scene", scene_file, "Scene file (JSON)")->required();
  validate->add_option("--set", sets, set_help)->type_name("PATH=VALUE");
  validate->add_flag("--quiet,-q", quiet, "Print nothing when the scene is valid");

  membra::cli::BenchArgs bench_args;
  auto* bench = app.add_subcommand(
      "bench", "Run membra's solvers side by side on the benchmark problem P(n)");
  bench->add_option("--sizes", bench_args.sizes, "Grid sizes n (n x n particles)")
      ->delimiter(',')
      ->check(CLI::Range(3, 4096));
  bench->add_option("--solvers", bench_args.solvers, "static, dr_unit, newton, rk4")
      ->delimiter(',');
  bench->add_option("--budget", bench_args.budget, "Wall-time budget per run, s")
      ->check(CLI::PositiveNumber);
  bench->add_flag("--json", bench_args.json, "Machine-readable output on stdout");
  bench->add_option("--json-out", bench_args.json_out, "Also write the JSON to this file");
  bench->add_flag("--quiet,-q", bench_args.quiet, "No per-run log on stderr");

  membra::cli::DesignArgs design_args;
  auto* design = app.add_subcommand("design", "Inverse design: a stencil for a wanted form");
  design->require_subcommand(1);
  auto* design_target =
      design->add_subcommand("target", "Design a stencil whose released form fits a target");
  design_target->add_option("file", design_args.file, "Design file (JSON)")->required();
  design_target->add_option("--out,-o", design_args.out_dir,
                            "Output directory (default: out/<name>)");
  design_target->add_flag("--quiet,-q", design_args.quiet, "No progress or summary");

  membra::viewer::ViewArgs view_args;
  auto* view = app.add_subcommand("view", "The interactive viewer (or a script driving it)");
  view->add_option("scene", view_args.scene, "Scene file (JSON); default: a plain latex sheet");
  view->add_option("--script", view_args.script,
                   "Run the commands in FILE (one a line) instead of waiting for the mouse");
  view->add_option("--set", view_args.sets, set_help)->type_name("PATH=VALUE");
  view->add_option("--size", view_args.size, "Window size in pixels")
      ->expected(2)
      ->type_name("W H");
  bool script_help = false;
  view->add_flag("--script-help", script_help, "List the script commands");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kOk : kBadInput;
  }
  try {
    if (*run) {
      for (const auto& [flag, range] : {std::pair{"--curvature-range", &run_opts.curvature_range},
                                        std::pair{"--stress-range", &run_opts.stress_range}})
        if (range->size() == 2 && !((*range)[0] < (*range)[1]))
          throw membra::InputError(flag, "LO must be below HI");
      return cmd_run(scene_file, sets, out_dir, quiet, run_opts);
    }
    if (*validate) return cmd_validate(scene_file, sets, quiet);
    if (*design) return membra::cli::cmd_design(design_args);
    if (*view) {
      if (script_help) {
        std::cout << "membra view --script FILE: one command a line ('#' comments)\n"
                  << membra::view_script_help();
        return kOk;
      }
      return membra::viewer::run_view(view_args);
    }
    if (*bench) {
      try {
        return membra::cli::cmd_bench(bench_args);
      } catch (const std::invalid_argument& e) {
        throw membra::InputError("--solvers", e.what());
      }
    }
  } catch (const membra::InputError& e) {
    std::cerr << "membra: error: " << e.what() << "\n";
    return kBadInput;
  } catch (const membra::OutputError& e) {
    std::cerr << "membra: error: " << e.what() << "\n";
    return kOutput;
  } catch (const std::invalid_argument& e) {
    std::cerr << "membra: error: " << scene_file << ": " << e.what() << "\n";
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << "membra: internal error: " << e.what() << "\n";
    return kInternal;
  }
  return kInternal;
}
