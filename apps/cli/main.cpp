// membra: the command-line tool. Thin: it parses arguments, calls the library and reports.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "membra/io/input_error.hpp"
#include "membra/io/obj.hpp"
#include "membra/io/output_set.hpp"
#include "membra/io/ply.hpp"
#include "membra/io/report.hpp"
#include "membra/io/run.hpp"
#include "membra/io/scene.hpp"
#include "membra/io/stencil.hpp"
#include "membra/measure/stress.hpp"
#include "membra/render/renderer.hpp"
#include "membra/version.hpp"
#include "progress_bar.hpp"

namespace {

// Exit codes, documented in docs/cli.md.
enum Exit : int { kOk = 0, kInternal = 1, kBadInput = 2, kDiverged = 3, kOutput = 4 };

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

struct RunOptions {
  std::vector<double> curvature_range;  // [lo, hi] in 1/mm^2, or empty for automatic
  std::vector<double> stress_range;     // [lo, hi] in MPa, or empty for automatic
};

int cmd_run(const std::string& scene_file, const std::vector<std::string>& sets,
            std::string out_dir, bool quiet, const RunOptions& opts) {
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
  const auto& mesh = r.prepared.membrane.sheet;
  const auto& x = r.prepared.membrane.state.x;
  out.add("final.obj", [&](std::ostream& os) { membra::write_obj(os, x, mesh.triangles); });
  // Colours on ranges symmetric about 0, so green is flat / unstressed: curvature red
  // synclastic, blue anticlastic (at least +-1e-6 1/mm^2, radius 1 m); stress red tension,
  // blue compression (at least +-1e-3 MPa).
  std::vector<double> k_mm, stress_mpa;
  for (double k : r.curvature.density) k_mm.push_back(k * 1e-6);  // 1/m^2 to 1/mm^2
  for (double sv : membra::vertex_stress(mesh.model, r.stress)) stress_mpa.push_back(sv * 1e-6);
  auto [k_lo, k_hi] = membra::symmetric_range(k_mm, 1e-6);
  if (opts.curvature_range.size() == 2)
    k_lo = opts.curvature_range[0], k_hi = opts.curvature_range[1];
  auto [s_lo, s_hi] = membra::symmetric_range(stress_mpa, 1e-3);
  if (opts.stress_range.size() == 2) s_lo = opts.stress_range[0], s_hi = opts.stress_range[1];
  const std::vector<membra::Rgb> k_colors = membra::colorize(k_mm, k_lo, k_hi);
  out.add("final.ply", [&](std::ostream& os) {
    membra::write_ply(os, x, mesh.triangles, k_colors,
                      {{"gaussian_curvature", k_mm}, {"stress", stress_mpa}});
  });
  // The stencil at true scale (outlines traced every 0.25 mm).
  if (const membra::PatternPtr pattern = membra::scene_pattern(scene)) {
    const membra::Box2 frame = membra::scene_frame(scene);
    const auto outlines = membra::trace_outlines(*pattern, frame, 0.25e-3);
    out.add("pattern.svg", [&](std::ostream& os) { membra::write_svg(os, outlines, frame); });
    out.add("pattern.dxf", [&](std::ostream& os) { membra::write_dxf(os, outlines, frame); });
    const auto png = membra::encode_png(membra::draw_pattern(*pattern, frame, 4.0));
    out.add("pattern.png", [png](std::ostream& os) {
      os.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
    });
  }
  std::string render_note;
  try {
    const membra::OutputSpec& o = scene.output;
    const membra::Camera camera{o.azimuth, o.elevation, 1.1};
    membra::Renderer renderer(o.image_width, o.image_height);
    auto add_png = [&](const std::string& file, const membra::Image& img) {
      const auto png = membra::encode_png(img);
      out.add(file, [png](std::ostream& os) {
        os.write(reinterpret_cast<const char*>(png.data()),
                 static_cast<std::streamsize>(png.size()));
      });
    };
    auto picture = [&](const std::string& file, const std::vector<membra::Rgb>& colors,
                       const membra::Legend& legend) {
      add_png(file, renderer.render(x, mesh.triangles, colors, camera, &legend));
    };
    picture("curvature.png", k_colors, {"Gaussian curvature", "1/mm^2", k_lo, k_hi});
    picture("stress.png", membra::colorize(stress_mpa, s_lo, s_hi),
            {"Stress (tension red)", "MPa", s_lo, s_hi});
    if (!r.frames.empty()) {
      // Frames share one stress range; the contact sheet tiles them six to a row (the paper's
      // figure 8 shows 24).
      std::vector<double> all;
      for (const auto& f : r.frames)
        for (double v : f.stress) all.push_back(v * 1e-6);
      const auto [f_lo, f_hi] = membra::symmetric_range(all, 1e-3);
      const membra::Legend legend{"Stress (tension red)", "MPa", f_lo, f_hi};
      const int cols = std::min<int>(6, static_cast<int>(r.frames.size()));
      const int rows = (static_cast<int>(r.frames.size()) + cols - 1) / cols;
      const int tw = 400, th = 300;
      membra::Renderer tiles(tw, th);
      membra::Image sheet{
          cols * tw, rows * th,
          std::vector<std::uint8_t>(static_cast<size_t>(cols * tw) * rows * th * 3, 255)};
      for (size_t i = 0; i < r.frames.size(); ++i) {
        std::vector<double> mpa;
        for (double v : r.frames[i].stress) mpa.push_back(v * 1e-6);
        const auto colors = membra::colorize(mpa, f_lo, f_hi);
        char name[64];
        std::snprintf(name, sizeof name, "frames/frame_%03zu.png", i + 1);
        add_png(name, renderer.render(r.frames[i].x, mesh.triangles, colors, camera, &legend));
        const membra::Image tile =
            tiles.render(r.frames[i].x, mesh.triangles, colors, camera, nullptr);
        const int ox = static_cast<int>(i) % cols * tw, oy = static_cast<int>(i) / cols * th;
        for (int yy = 0; yy < th; ++yy)
          std::copy_n(&tile.rgb[static_cast<size_t>(yy) * tw * 3], tw * 3,
                      &sheet.rgb[(static_cast<size_t>(oy + yy) * sheet.width + ox) * 3]);
      }
      add_png("contact_sheet.png", sheet);
    }
  } catch (const membra::RenderError& e) {
    render_note = e.what();
    std::cerr << "membra: warning: no PNG renders: " << e.what() << "\n";
  }
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
  RunOptions run_opts;
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
