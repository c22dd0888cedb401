#include "view_command.hpp"

#include <chrono>
#include <fstream>
#include <iostream>

#include "membra/core/input_error.hpp"
#include "membra/io/scene.hpp"
#include "membra/output/output_set.hpp"
#include "membra/view/session_files.hpp"
#include "membra/view/view_script.hpp"
#include "viewer_window.hpp"

namespace membra::viewer {
namespace {

constexpr int kBadInput = 2, kNoDisplay = 6;  // as main.cpp's exit codes

// The scene the viewer opens without one: a plain latex sheet on a 1.5 x 1 frame.
Scene default_scene(const std::vector<std::string>& sets) {
  nlohmann::json j = {
      {"name", "sheet"},
      {"sheet", {{"size", {200, 200}}, {"resolution", {41, 41}}, {"material", "latex"}}},
      {"simulation", {{"G", 0.0}}},
      {"protocol", {{{"step", "stretch"}, {"lambda", {1.5, 1.0}}}}}};
  for (const std::string& s : sets) apply_override(j, s);
  return parse_scene(j);
}

// The `drag` and `click` commands: a scripted left-button stroke, one frame per mouse step.
void run_drag(const ScriptCommand& c, ViewerSession& session, ViewSettings& settings,
              ViewerWindow& window) {
  // The left button pressed at the start, moved in steps, released at the end: one frame
  // each, through the same mouse code as a hand on the mouse.
  const double x0 = c.number(0), y0 = c.number(1);
  const double x1 = c.name == "drag" ? c.number(2) : x0, y1 = c.name == "drag" ? c.number(3) : y0;
  constexpr int steps = 12;
  Pointer p;
  p.x = x0;
  p.y = y0;
  window.inject(p);  // hover first: no jump in the drag's first move
  window.frame(session, settings, false, nullptr);
  for (int k = 0; k <= steps; ++k) {
    p.x = x0 + (x1 - x0) * k / steps;
    p.y = y0 + (y1 - y0) * k / steps;
    p.down[0] = true;
    window.inject(p);
    window.frame(session, settings, false, nullptr);
  }
  p.down[0] = false;
  window.inject(p);
  window.frame(session, settings, false, nullptr);
  if (window.status().find("cannot") != std::string::npos)
    std::cerr << c.where << ": " << window.status() << "\n";
}

// `screenshot`, `save` and `export`: a file written, its errors reported at the command.
void run_file_command(const ScriptCommand& c, ViewerSession& session, ViewSettings& settings,
                      ViewerWindow& window) {
  try {
    if (c.name == "screenshot") {
      Image img;
      window.frame(session, settings, false, &img);
      write_png(c.words[0], img);
    } else if (c.name == "save") {
      save_session_scene(session, c.words[0]);
    } else if (c.name == "export") {
      export_session(session, c.words[0]);
    }
  } catch (const OutputError& e) {
    throw InputError(c.where, e.what());
  } catch (const RenderError& e) {
    throw InputError(c.where, e.what());
  }
}

// Runs a script: session commands act at once, `step N` draws N frames, window commands here.
int run_script(const std::vector<ScriptCommand>& script, ViewerSession& session,
               ViewSettings& settings, ViewerWindow& window) {
  for (const ScriptCommand& c : script) {
    if (c.name == "quit") return 0;
    if (c.name == "step") {
      // Frames with the live simulation, each a fixed number of iterations (reproducible).
      const long frames = static_cast<long>(c.number(0));
      for (long f = 0; f < frames; ++f) {
        const SliceReport r = session.advance(settings.iterations_per_frame);
        if (r.diverged) throw InputError(c.where, r.message);
        window.frame(session, settings, false, nullptr);
      }
      continue;
    }
    if (c.name == "fps") {
      // As the interactive loop runs: a time slice of simulation and a full redraw per frame.
      const long frames = static_cast<long>(c.number(0));
      const auto t0 = std::chrono::steady_clock::now();
      for (long f = 0; f < frames; ++f) window.frame(session, settings, true, nullptr);
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::cout << "fps: " << static_cast<double>(frames) / s << " frames/s (" << frames
                << " frames, " << session.membrane().sheet.model.num_particles() << " particles)\n";
      continue;
    }
    if (run_session_command(c, session, settings)) {
      window.frame(session, settings, false, nullptr);
      continue;
    }
    if (c.name == "tool") {
      window.set_tool(c.words[0]);
      continue;
    }
    if (c.name == "holesize") {
      if (!(c.number(0) > 0.0)) throw InputError(c.where, "holesize: the radius must be positive");
      window.set_hole_radius(c.number(0) * 1e-3);
      continue;
    }
    if (c.name == "drag" || c.name == "click") {
      run_drag(c, session, settings, window);
      continue;
    }
    run_file_command(c, session, settings, window);
  }
  return 0;
}

}  // namespace

int run_view(const ViewArgs& args) {
  try {
    Scene scene = args.scene.empty() ? default_scene(args.sets) : load_scene(args.scene, args.sets);
    std::vector<ScriptCommand> script;
    if (!args.script.empty()) {
      std::ifstream in(args.script);
      if (!in) throw InputError(args.script, "cannot open the script file");
      script = parse_view_script(in, args.script);  // all checked before a window opens
    }
    ViewerSession session(std::move(scene));
    if (!session.grid_warning().empty())
      std::cerr << "membra view: warning: " << session.grid_warning() << "\n";
    ViewSettings settings;
    if (args.size.size() != 2 || args.size[0] < 400 || args.size[1] < 300 || args.size[0] > 8192 ||
        args.size[1] > 8192)
      throw InputError("--size", "the window needs 400..8192 x 300..8192 pixels");
    std::unique_ptr<ViewerWindow> window;
    try {
      window = std::make_unique<ViewerWindow>(args.size[0], args.size[1], args.script.empty());
    } catch (const RenderError& e) {
      std::cerr << "membra view: " << e.what() << "\n";
      return kNoDisplay;
    }
    if (!args.scene.empty()) window->set_scene_path(args.scene);
    if (!script.empty()) return run_script(script, session, settings, *window);
    while (!window->should_close()) window->frame(session, settings, true, nullptr);
    return 0;
  } catch (const InputError& e) {
    std::cerr << "membra view: " << e.what() << "\n";
    return kBadInput;
  }
}

}  // namespace membra::viewer
