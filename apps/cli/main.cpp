// membra: the command-line tool. Thin: it parses arguments, calls the library and reports.
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include <csignal>
#include "bench_command.hpp"
#include "design_command.hpp"

#include "membra/core/input_error.hpp"
#include "membra/core/stop_request.hpp"
#include "membra/io/scene.hpp"
#include "membra/model/continuum_sheet.hpp"
#include "membra/output/output_set.hpp"
#include "membra/process/grid_resolution.hpp"
#include "membra/process/multilevel.hpp"
#include "membra/process/run.hpp"
#include "membra/process/summary.hpp"
#include "membra/render/run_outputs.hpp"
#include "membra/version.hpp"
#include "membra/view/view_script.hpp"
#include "progress_bar.hpp"
#include "sweep_command.hpp"
#include "view_command.hpp"

namespace {

// Exit codes, documented in docs/cli.md.
enum Exit : int {
  kOk = 0,
  kInternal = 1,
  kBadInput = 2,
  kDiverged = 3,
  kOutput = 4,
  kUnreachable = 5,   // membra design: the target cannot be reached (best attempt written)
  kNoDisplay = 6,     // membra view: no window can be opened
  kNotAtRest = 7,     // membra run: an equilibrium solver ended unconverged or at a saddle
  kInterrupted = 128  // + the signal: stopped by SIGINT (130) or SIGTERM (143), nothing written
};

// The first SIGINT or SIGTERM asks the run to stop (it stops at its next progress report, within
// a fraction of a second, writing nothing); a second one ends the process at once.
extern "C" void on_stop_signal(int signal) {
  if (membra::stop_requested()) {
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  membra::request_stop(signal);
}

void install_stop_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sa.sa_flags = SA_RESTART;  // a write to stderr under way is not cut short
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

int cmd_validate(const std::string& scene_file, const std::vector<std::string>& sets, bool quiet) {
  const membra::Scene scene = membra::load_scene(scene_file, sets);
  try {
    const membra::PreparedScene p = membra::prepare_scene(scene);
    const membra::Sheet& sheet = p.membrane.sheet;
    if (!quiet && sheet.continuum())
      std::cout << scene_file << ": valid (continuum: " << membra::mesh_line(sheet.mesh) << ", "
                << p.pinned << " pinned)\n";
    else if (!quiet)
      std::cout << scene_file << ": valid (" << sheet.model.num_particles() << " particles, "
                << sheet.model.springs.size() << " springs, " << p.pinned << " pinned)\n";
    if (const auto coarse = membra::coarse_grid(scene))
      std::cerr << "membra: warning: " << scene_file << ": " << coarse->message << "\n";
  } catch (const membra::InputError& e) {
    throw membra::InputError(scene_file + ": " + e.where(), e.detail());
  }
  return kOk;
}

// An equilibrium solver's end state that is no stable equilibrium (unconverged, or a saddle):
// says so on stderr with what to try, so that scripts can tell by the exit code too.
bool warn_if_not_at_rest(const std::string& scene_file, const membra::Scene& scene,
                         const membra::RunResult& r) {
  if (!scene.simulation.is_static()) return false;
  const bool saddle = r.stability.checked && !r.stability.stable;
  if (r.solve.converged && !saddle) return false;
  std::cerr << "membra: " << scene_file << ": "
            << (r.solve.converged ? "the end state is a saddle of the energy, not a stable form: "
                                  : "not converged: ")
            << (r.solve.converged ? r.stability.message : r.solve.message) << "\n";
  if (r.out_of_time)
    std::cerr << "membra: the run ran out of its wall-time budget: raise it, e.g. --set "
                 "simulation.max_seconds="
              << std::ceil(4.0 * scene.simulation.max_seconds)
              << "; the outputs show the end state as it is\n";
  else
    std::cerr << "membra: try more release increments (\"increments\"), another perturbation "
                 "seed, or the other equilibrium solver (--set simulation.solver=static|newton); "
                 "the outputs show the end state as it is\n";
  return true;
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
  const membra::StagedRun staged = membra::stage_run_outputs(scene, r, opts, out);
  if (staged.report_only) {
    // A diverged state is no form: only the report is written, and it says so.
    out.commit();
    std::cerr << "membra: " << scene_file << ": " << r.solve.message << "\n"
              << "membra: wrote only " << (out.dir() / "report.json").string() << "\n";
    return kDiverged;
  }
  if (r.curvature_map && !r.curvature_map->message.empty())
    std::cerr << "membra: warning: " << scene_file << ": " << r.curvature_map->step << ": "
              << r.curvature_map->message << "\n";
  for (const std::string& w : r.warnings)
    std::cerr << "membra: warning: " << scene_file << ": " << w << "\n";
  const std::string& render_note = staged.render_note;
  if (!render_note.empty()) std::cerr << "membra: warning: no PNG renders: " << render_note << "\n";
  out.commit();
  if (!quiet) {
    if (!r.levels.empty()) std::cout << membra::levels_summary(r.levels) << "\n";
    std::cout << membra::form_line(r) << "\n";
    std::cout << r.solve.message << " in " << r.solve.wall_seconds << " s\n"
              << "results in " << out.dir().string()
              << "/ (report.html, final.glb, final.obj, final.ply, report.json"
              << (r.solve.converged ? "" : "; not an equilibrium")
              << (render_note.empty() ? ", curvature.png, stress.png" : "") << ")\n";
    const std::string tip = membra::multilevel_hint(scene, r.solve.wall_seconds);
    if (!tip.empty()) std::cerr << tip << "\n";
  }
  return warn_if_not_at_rest(scene_file, scene, r) ? kNotAtRest : kOk;
}

// Every subcommand's arguments, filled in by CLI11.
struct Args {
  std::string scene_file, out_dir;
  std::vector<std::string> sets;
  bool quiet = false;
  membra::PictureOptions run_opts;
  membra::cli::BenchArgs bench;
  membra::cli::DesignArgs design;
  membra::cli::SweepArgs sweep;
  membra::viewer::ViewArgs view;
  bool script_help = false;
};

const char* const kSetHelp =
    "Override a scene value before validation, e.g. --set simulation.steps=500";

CLI::App* add_run(CLI::App& app, Args& a) {
  auto* run = app.add_subcommand("run", "Run a scene and write its results");
  run->add_option("scene", a.scene_file, "Scene file (JSON)")->required();
  run->add_option("--out,-o", a.out_dir, "Output directory (default: out/<scene name>)");
  run->add_option("--set", a.sets, kSetHelp)->type_name("PATH=VALUE");
  run->add_option(
         "--curvature-range", a.run_opts.curvature_range,
         "Colour range of curvature.png and final.ply, 1/m^2 (default: symmetric, automatic)")
      ->expected(2)
      ->allow_extra_args(false)
      ->type_name("LO HI");
  run->add_option("--stress-range", a.run_opts.stress_range,
                  "Colour range of stress.png, MPa (default: symmetric, automatic)")
      ->expected(2)
      ->allow_extra_args(false)
      ->type_name("LO HI");
  run->add_flag("--quiet,-q", a.quiet, "No progress bar or summary");
  return run;
}

CLI::App* add_validate(CLI::App& app, Args& a) {
  auto* validate = app.add_subcommand("validate", "Check a scene without running it");
  validate->add_option("scene", a.scene_file, "Scene file (JSON)")->required();
  validate->add_option("--set", a.sets, kSetHelp)->type_name("PATH=VALUE");
  validate->add_flag("--quiet,-q", a.quiet, "Print nothing when the scene is valid");
  return validate;
}

CLI::App* add_bench(CLI::App& app, Args& a) {
  auto* bench = app.add_subcommand(
      "bench", "Run membra's solvers side by side on the benchmark problem P(n)");
  bench->add_option("--sizes", a.bench.sizes, "Grid sizes n (n x n particles)")
      ->delimiter(',')
      ->check(CLI::Range(3, 4096));
  std::string names;
  for (std::string_view n : membra::kBenchSolvers)
    names += (names.empty() ? "" : ", ") + std::string(n);
  bench->add_option("--solvers", a.bench.solvers, names)->delimiter(',');
  bench->add_option("--budget", a.bench.budget, "Wall-time budget per run, s")
      ->check(CLI::PositiveNumber);
  bench->add_flag("--json", a.bench.json, "Machine-readable output on stdout");
  bench->add_option("--json-out", a.bench.json_out, "Also write the JSON to this file");
  bench->add_flag("--quiet,-q", a.bench.quiet, "No per-run log on stderr");
  bench->add_flag("--scenes", a.bench.scenes,
                  "Also run the forward examples (exp3_parallel, synclastic_ellipse, "
                  "anticlastic_hyperbola, exp5_shrink; from the repository root) on both models "
                  "with each equilibrium solver");
  bench->add_option("--scene-sizes", a.bench.scene_sizes, "Resolutions n of the scenes (n x n)")
      ->delimiter(',')
      ->check(CLI::Range(3, 4096))
      ->capture_default_str();
  bench->add_option("--scene-solvers", a.bench.scene_solvers, "Equilibrium solvers for the scenes")
      ->delimiter(',')
      ->capture_default_str();
  bench
      ->add_option("--scene-multilevel", a.bench.scene_multilevel,
                   "simulation.multilevel values for the scenes, each run side by side (0: off)")
      ->delimiter(',')
      ->check(CLI::Range(0, 4096))
      ->capture_default_str();
  bench->add_option("--scene-files", a.bench.scene_files, "Scene files for --scenes")
      ->delimiter(',')
      ->capture_default_str();
  bench
      ->add_option("--scene-models", a.bench.scene_models,
                   "Models for the scenes: lattice (at --scene-sizes), continuum (on meshes "
                   "scaled by --scene-mesh-scales)")
      ->delimiter(',')
      ->check(CLI::IsMember({"lattice", "continuum"}))
      ->capture_default_str();
  bench
      ->add_option("--scene-mesh-scales", a.bench.scene_mesh_scales,
                   "Continuum meshes: the default max_edge times each (elements_across over "
                   "it); 1,0.5 is the mesh-convergence check")
      ->delimiter(',')
      ->check(CLI::Range(0.05, 20.0))
      ->capture_default_str();
  return bench;
}

CLI::App* add_design(CLI::App& app, Args& a) {
  auto* design = app.add_subcommand("design", "Inverse design: a stencil for a wanted form");
  design->require_subcommand(1);
  auto* target =
      design->add_subcommand("target", "Design a stencil whose released form fits a target");
  target->add_option("file", a.design.file, "Design file (JSON)")->required();
  target->add_option("--out,-o", a.design.out_dir, "Output directory (default: out/<name>)");
  target->add_flag("--quiet,-q", a.design.quiet, "No progress or summary");
  target->add_flag("--no-cache", a.design.no_cache,
                   "Measure the adjoint method's stencil calibration even if one is stored "
                   "($MEMBRA_CACHE_DIR, else ~/.cache/membra; MEMBRA_CACHE_DIR=off: none)");
  return design;
}

CLI::App* add_sweep(CLI::App& app, Args& a) {
  auto* sweep = app.add_subcommand("sweep", "Run a sweep of scenes on a Dask cluster");
  sweep->add_option("file", a.sweep.file, "Sweep file (JSON, docs/sweeps.md)")->required();
  sweep->add_option("--out,-o", a.sweep.out_dir, "Output directory (default: out/<name>)");
  sweep
      ->add_option("--scheduler", a.sweep.scheduler,
                   "Address of a running Dask scheduler (default: a local cluster)")
      ->type_name("tcp://HOST:PORT");
  sweep->add_option("--workers", a.sweep.workers, "Worker processes of the local cluster")
      ->check(CLI::Range(1, 256));
  sweep->add_flag("--no-resume", a.sweep.no_resume, "Run every scene again");
  sweep->add_flag("--quiet,-q", a.sweep.quiet, "No progress lines");
  return sweep;
}

CLI::App* add_view(CLI::App& app, Args& a) {
  auto* view = app.add_subcommand("view", "The interactive viewer (or a script driving it)");
  view->add_option("scene", a.view.scene, "Scene file (JSON); default: a plain latex sheet");
  view->add_option("--script", a.view.script,
                   "Run the commands in FILE (one a line) instead of waiting for the mouse");
  view->add_option("--set", a.view.sets, kSetHelp)->type_name("PATH=VALUE");
  view->add_option("--size", a.view.size, "Window size in pixels")->expected(2)->type_name("W H");
  view->add_flag("--script-help", a.script_help, "List the script commands");
  return view;
}

// The chosen subcommand, carried out.
struct Commands {
  CLI::App *run, *validate, *bench, *design, *view, *sweep;
};

int dispatch(const Commands& c, const Args& a) {
  if (*c.run) {
    for (const auto& [flag, range] : {std::pair{"--curvature-range", &a.run_opts.curvature_range},
                                      std::pair{"--stress-range", &a.run_opts.stress_range}})
      if (range->size() == 2 && !((*range)[0] < (*range)[1]))
        throw membra::InputError(flag, "LO must be below HI");
    return cmd_run(a.scene_file, a.sets, a.out_dir, a.quiet, a.run_opts);
  }
  if (*c.validate) return cmd_validate(a.scene_file, a.sets, a.quiet);
  if (*c.design) return membra::cli::cmd_design(a.design);
  if (*c.sweep) return membra::cli::cmd_sweep(a.sweep);
  if (*c.view) {
    if (a.script_help) {
      std::cout << "membra view --script FILE: one command a line ('#' comments)\n"
                << membra::view_script_help();
      return kOk;
    }
    return membra::viewer::run_view(a.view);
  }
  if (*c.bench) {
    try {
      return membra::cli::cmd_bench(a.bench);
    } catch (const std::invalid_argument& e) {
      throw membra::InputError("--solvers", e.what());
    }
  }
  return kInternal;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"membra: form-finding for pre-stretched, resin-impregnated membranes"};
  app.set_version_flag("--version", std::string("membra ") + membra::kVersion);
  app.require_subcommand(1);
  Args a;
  const Commands c{add_run(app, a),    add_validate(app, a), add_bench(app, a),
                   add_design(app, a), add_view(app, a),     add_sweep(app, a)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kOk : kBadInput;
  }
  // Only the commands whose runs poll the stop request; the others keep the default (Ctrl-C
  // ends them at once).
  if (*c.run || *c.design) install_stop_handlers();
  try {
    return dispatch(c, a);
  } catch (const membra::Interrupted& e) {
    std::cerr << "\nmembra: " << (e.signal() == SIGTERM ? "terminated" : "stopped") << " ("
              << (e.signal() == SIGTERM ? "SIGTERM" : "SIGINT") << ") " << e.where()
              << "; nothing was written, and earlier results in the output folder are as "
                 "they were\n";
    return kInterrupted + e.signal();
  } catch (const membra::InputError& e) {
    std::cerr << "membra: error: " << e.what() << "\n";
    return kBadInput;
  } catch (const membra::OutputError& e) {
    std::cerr << "membra: error: " << e.what() << "\n";
    return kOutput;
  } catch (const std::invalid_argument& e) {
    std::cerr << "membra: error: " << a.scene_file << ": " << e.what() << "\n";
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << "membra: internal error: " << e.what() << "\n";
    return kInternal;
  }
}
