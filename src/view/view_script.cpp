#include "membra/view/view_script.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <sstream>

#include "membra/core/input_error.hpp"
#include "membra/core/units.hpp"

namespace membra {
namespace {

// Each command: its arguments ("n" a number, "w" a word, "p" a path), and a help line.
struct Spec {
  std::string args;
  std::string help;
  std::vector<std::string> words = {};  // allowed values of the word argument, if restricted
};

const std::map<std::string, Spec>& specs() {
  static const std::map<std::string, Spec> s = {
      {"stretch", {"", "stretch the sheet by the current lambda"}},
      {"impregnate", {"", "apply the painted (and scene) resin pattern"}},
      {"release", {"", "let the frame go; the release follows its path as the sheet settles"}},
      {"play", {"", "carry out the scene's own protocol, a step each time the sheet settles"}},
      {"step", {"n", "step N: run N frames of the live simulation"}},
      {"settle", {"", "run the simulation until the sheet has settled"}},
      {"paint", {"nnn", "paint X Y RADIUS: a disc of resin (mm, frame coordinates)"}},
      {"erase", {"nnn", "erase X Y RADIUS: remove painted resin"}},
      {"cut", {"nnnn", "cut X0 Y0 X1 Y1: cut the springs a line crosses (mm)"}},
      {"hole", {"nnn", "hole X Y RADIUS: punch a round hole (mm)"}},
      {"pin", {"nn", "pin X Y: pin (or free) the particle nearest to (X, Y) mm"}},
      {"set",
       {"wn",
        "set K|G|T|D|lambda_x|lambda_y VALUE (K in N/mm, G m/s^2, T s, D 1/s)",
        {"K", "G", "T", "D", "lambda_x", "lambda_y"}}},
      {"mode", {"w", "mode relax|dynamics: the live simulation", {"relax", "dynamics"}}},
      {"color", {"w", "color stress|curvature|pattern", {"stress", "curvature", "pattern"}}},
      {"range", {"nn", "range LO HI: the colour range (display units); range auto"}},
      {"view", {"w", "view 2d|3d", {"2d", "3d"}}},
      {"orbit", {"nn", "orbit DAZIMUTH DELEVATION: turn the 3-D camera (degrees)"}},
      {"zoom", {"n", "zoom FACTOR: > 1 closer"}},
      {"fit", {"", "fit the camera to the sheet"}},
      {"springs", {"w", "springs on|off: draw the springs as lines", {"on", "off"}}},
      {"particles", {"w", "particles on|off", {"on", "off"}}},
      {"tool",
       {"w",
        "tool orbit|paint|erase|cut|hole|pin: what the left mouse button does",
        {"orbit", "paint", "erase", "cut", "hole", "pin"}}},
      {"drag", {"nnnn", "drag X0 Y0 X1 Y1: the left button dragged (window pixels) with the tool"}},
      {"click", {"nn", "click X Y: the left button clicked (window pixels) with the tool"}},
      {"brush", {"n", "brush R: the brush radius, mm"}},
      {"holesize", {"n", "holesize R: the hole tool's radius, mm"}},
      {"undo", {"", "undo the last edit"}},
      {"redo", {"", "redo it"}},
      {"reset", {"", "back to the flat sheet"}},
      {"screenshot", {"p", "screenshot PATH.png: save the window"}},
      {"save", {"p", "save PATH.json: the session as a scene"}},
      {"export", {"p", "export PATH.obj|.ply|.svg: the form (obj, ply) or the stencil (svg)"}},
      {"fps", {"n", "fps N: draw N frames as fast as possible and print frames per second"}},
      {"quit", {"", "close the viewer"}},
  };
  return s;
}

bool parse_double(const std::string& w, double& out) {
  const char* end = w.data() + w.size();
  const auto [p, ec] = std::from_chars(w.data(), end, out);
  return ec == std::errc() && p == end && std::isfinite(out);
}

Vec2 at_mm(const ScriptCommand& c, size_t i) {
  return Vec2(c.number(i), c.number(i + 1)) * units::mm;
}

}  // namespace

double ScriptCommand::number(size_t i) const {
  double v = 0.0;
  if (i >= words.size() || !parse_double(words[i], v))
    throw InputError(where,
                     "argument " + std::to_string(i + 1) + " of " + name + " must be a number");
  return v;
}

std::vector<ScriptCommand> parse_view_script(std::istream& in, const std::string& name) {
  std::vector<ScriptCommand> out;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    ScriptCommand c;
    c.where = name + ":" + std::to_string(n);
    if (!(words >> c.name)) continue;
    for (std::string w; words >> w;) c.words.push_back(w);
    const auto it = specs().find(c.name);
    if (it == specs().end())
      throw InputError(c.where, "unknown command '" + c.name + "' (membra view --script-help)");
    const Spec& s = it->second;
    const bool range_auto = c.name == "range" && c.words.size() == 1 && c.words[0] == "auto";
    if (c.words.size() != s.args.size() && !range_auto)
      throw InputError(
          c.where, c.name + " takes " + std::to_string(s.args.size()) + " argument(s): " + s.help);
    for (size_t i = 0; i < c.words.size() && !range_auto; ++i) {
      if (s.args[i] == 'n') c.number(i);
      if (s.args[i] == 'w' && !s.words.empty() &&
          std::find(s.words.begin(), s.words.end(), c.words[i]) == s.words.end())
        throw InputError(c.where, "'" + c.words[i] + "' is not allowed here: " + s.help);
    }
    if ((c.name == "step" || c.name == "fps") && (c.number(0) < 1 || c.number(0) > 1e6))
      throw InputError(c.where, c.name + " needs a count from 1 to 1000000");
    if (c.name == "range" && !range_auto && !(c.number(0) < c.number(1)))
      throw InputError(c.where, "range needs LO < HI");
    out.push_back(std::move(c));
  }
  return out;
}

std::string view_script_help() {
  std::string h;
  for (const auto& [name, s] : specs())
    h += "  " + name + std::string(12 - name.size(), ' ') + s.help + "\n";
  return h;
}

namespace {

// Throws the command's InputError when `why` says it could not be done.
void check(const ScriptCommand& c, const std::string& why) {
  if (!why.empty()) throw InputError(c.where, c.name + ": " + why);
}

// The session's commands (process, editing, simulation, parameters); false when `c` is none.
bool run_process_command(const ScriptCommand& c, ViewerSession& session, const ViewSettings& v) {
  const std::string& n = c.name;
  if (n == "stretch") {
    check(c, session.stretch());
  } else if (n == "impregnate") {
    check(c, session.impregnate());
  } else if (n == "release") {
    check(c, session.release());
  } else if (n == "play") {
    session.play_scene_protocol();
  } else if (n == "step") {
    for (long i = 0; i < static_cast<long>(c.number(0)); ++i) {
      const SliceReport r = session.advance(v.iterations_per_frame);
      if (r.diverged) check(c, r.message);
    }
  } else if (n == "settle") {
    const SliceReport r = session.settle();
    if (r.diverged) check(c, r.message);
    if (!r.settled) check(c, "the sheet did not settle within the iteration budget");
  } else if (n == "paint" || n == "erase") {
    check(c, session.paint(at_mm(c, 0), c.number(2) * units::mm, n == "erase"));
  } else if (n == "cut") {
    check(c, session.cut(at_mm(c, 0), at_mm(c, 2)));
  } else if (n == "hole") {
    check(c, session.hole(at_mm(c, 0), c.number(2) * units::mm));
  } else if (n == "pin") {
    check(c, session.toggle_pin(at_mm(c, 0)));
  } else if (n == "set") {
    LiveParameters p = session.parameters();
    const std::string& what = c.words[0];
    const double value = c.number(1);
    if (what == "K") p.K = value * units::N_per_mm;
    if (what == "G") p.G = value;
    if (what == "T") p.T = value;
    if (what == "D") p.D = value;
    if (what == "lambda_x") p.lambda.x() = value;
    if (what == "lambda_y") p.lambda.y() = value;
    check(c, session.set_parameters(p));
  } else if (n == "mode") {
    session.set_mode(c.words[0] == "relax" ? LiveMode::relax : LiveMode::dynamics);
  } else {
    return false;
  }
  return true;
}

// The view's commands (colours, camera, what is drawn) and undo/redo/reset; false when `c` is
// none.
bool run_view_command(const ScriptCommand& c, ViewerSession& session, ViewSettings& v) {
  const std::string& n = c.name;
  if (n == "color") {
    v.color = *parse_color_mode(c.words[0]);
    v.range.reset();
  } else if (n == "range") {
    if (c.words[0] == "auto")
      v.range.reset();
    else
      v.range = std::pair{c.number(0), c.number(1)};
  } else if (n == "view") {
    v.flat = c.words[0] == "2d";
  } else if (n == "orbit") {
    v.camera.orbit(c.number(0), c.number(1));
  } else if (n == "zoom") {
    if (!(c.number(0) > 0.0)) check(c, "the factor must be positive");
    v.camera.zoom(c.number(0));
  } else if (n == "fit") {
    v.camera_fitted = false;
  } else if (n == "springs") {
    v.show_springs.fill(c.words[0] == "on");
  } else if (n == "particles") {
    v.show_particles = c.words[0] == "on";
  } else if (n == "brush") {
    if (!(c.number(0) > 0.0)) check(c, "the radius must be positive");
    v.brush_radius = c.number(0) * units::mm;
  } else if (n == "undo") {
    if (!session.undo()) check(c, "nothing to undo");
  } else if (n == "redo") {
    if (!session.redo()) check(c, "nothing to redo");
  } else if (n == "reset") {
    session.reset();
    v.camera_fitted = false;
  } else {
    return false;
  }
  return true;
}

}  // namespace

bool run_session_command(const ScriptCommand& c, ViewerSession& session, ViewSettings& v) {
  // Not here: screenshot, save, export, fps, quit, tool, drag, click (the window's).
  return run_process_command(c, session, v) || run_view_command(c, session, v);
}

}  // namespace membra
