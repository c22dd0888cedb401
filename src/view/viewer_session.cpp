#include "membra/view/viewer_session.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "membra/core/input_error.hpp"
#include "membra/core/units.hpp"
#include "membra/io/scene_writer.hpp"
#include "membra/model/cut.hpp"
#include "membra/model/pins.hpp"
#include "membra/process/cut_after_motion.hpp"
#include "membra/process/grid_resolution.hpp"
#include "membra/process/steps.hpp"
#include "membra/solve/solver.hpp"

namespace membra {
namespace {

constexpr size_t kMaxUndo = 40;  // snapshots kept (a 64 x 64 membrane is about 2 MB each)

StaticOptions relax_options(const Scene& scene, double force_scale) {
  StaticOptions o;
  o.tolerance = scene.simulation.tolerance;
  o.force_scale = force_scale;
  return o;
}

}  // namespace

const char* stage_name(Stage stage) {
  switch (stage) {
    case Stage::flat:
      return "flat";
    case Stage::stretched:
      return "stretched";
    case Stage::impregnated:
      return "impregnated";
    case Stage::released:
      return "released";
  }
  return "?";
}

ViewerSession::ViewerSession(Scene scene)
    : scene_(std::move(scene)),
      prepared_(prepare_scene(scene_)),
      relaxation_(prepared_.membrane.sheet.model, prepared_.membrane.state.x,
                  relax_options(scene_, prepared_.force_scale)) {
  params_.K = prepared_.membrane.sheet.stiffness.stretch;
  params_.G = scene_.simulation.gravity;
  params_.T = scene_.simulation.dt;
  params_.D = scene_.simulation.damping;
  if (const auto* s = first_step<StretchStep>()) params_.lambda = s->lambda;
  if (!scene_.simulation.is_static()) mode_ = LiveMode::dynamics;
  if (const auto coarse = coarse_grid(scene_)) grid_warning_ = coarse->message;
  if (scene_.simulation.self_contact.on)
    grid_warning_ += std::string(grid_warning_.empty() ? "" : "; ") +
                     "self-contact is not applied to the live relaxation (FIRE): a form here may "
                     "pass through itself; membra run applies it";
}

std::optional<PatternSpec> ViewerSession::resin_pattern_spec() const {
  std::optional<PatternSpec> p;  // nothing yet
  if (!scene_pattern_used_) {
    std::vector<PatternSpec> parts;
    for (const ProtocolStep& s : scene_.protocol)
      if (const auto* i = s.as<ImpregnateStep>()) parts.push_back(i->pattern_spec);
    if (parts.size() == 1) p = parts[0];
    if (parts.size() > 1) p = union_spec(std::move(parts));
  }
  for (const Stroke& s : strokes_) {
    PatternSpec disc = circle_spec(s.centre, s.radius);
    if (s.erase) {
      if (p) p = difference_spec({*p, disc});
    } else if (!p) {
      p = disc;
    } else if (p->kind == PatternSpec::Kind::union_of) {
      p->parts.push_back(disc);  // consecutive strokes stay one flat union
    } else {
      p = union_spec({*p, disc});
    }
  }
  return p;
}

PatternPtr ViewerSession::resin_pattern() const {
  const auto spec = resin_pattern_spec();
  if (!spec) return nullptr;
  const Box2 frame = scene_frame(scene_);
  return make_pattern(*spec, frame.max - frame.min);
}

ViewerSession::Snapshot ViewerSession::snapshot() const {
  return {prepared_.membrane, stage_, strokes_, log_, walk_, viewer_pins_, scene_pattern_used_};
}

void ViewerSession::restore(const Snapshot& s) {
  prepared_.membrane = s.membrane;
  stage_ = s.stage;
  strokes_ = s.strokes;
  log_ = s.log;
  walk_ = s.walk;
  viewer_pins_ = s.viewer_pins;
  scene_pattern_used_ = s.scene_pattern_used;
  queue_.clear();
  model_changed();
}

void ViewerSession::push_undo() {
  if (editing_ && edit_snapshot_taken_) return;
  if (editing_) edit_snapshot_taken_ = true;
  undo_.push_back(snapshot());
  if (undo_.size() > kMaxUndo) undo_.pop_front();
  redo_.clear();
}

void ViewerSession::begin_edit() {
  editing_ = true;
  edit_snapshot_taken_ = false;
}

void ViewerSession::end_edit() {
  editing_ = false;
}

bool ViewerSession::undo() {
  if (undo_.empty()) return false;
  redo_.push_back(snapshot());
  restore(undo_.back());
  undo_.pop_back();
  return true;
}

bool ViewerSession::redo() {
  if (redo_.empty()) return false;
  undo_.push_back(snapshot());
  restore(redo_.back());
  redo_.pop_back();
  return true;
}

void ViewerSession::model_changed() {
  relaxation_ = StaticRelaxation(prepared_.membrane.sheet.model, prepared_.membrane.state.x,
                                 relax_options(scene_, prepared_.force_scale));
  prepared_.membrane.state.v.setZero(3, prepared_.membrane.sheet.model.num_particles());
  settled_ = false;
  crossings_ = {};
}

std::string ViewerSession::stretch() {
  if (stage_ != Stage::flat) return "the sheet is already stretched (reset or undo first)";
  const Vec2 l = params_.lambda;
  if (!(l.x() > 0.0 && l.y() > 0.0 && l.x() <= 10.0 && l.y() <= 10.0))
    return "the stretch ratios must be within (0, 10]";
  push_undo();
  StretchStep step;
  step.lambda = l;
  if (const auto* s = first_step<StretchStep>()) step.hold = s->hold;
  StepEffects effects;
  apply_stretch(prepared_.membrane, step, effects);
  log_.push_back({"", step});
  stage_ = Stage::stretched;
  model_changed();
  return "";
}

std::string ViewerSession::impregnate_with(const PatternSpec& pattern, const ImpregnateStep* s) {
  ImpregnateStep step;
  step.resin = s ? s->resin : epoxy();
  step.resin_side = s ? s->resin_side : +1;
  step.bilayer = s && s->bilayer;
  step.pattern_spec = pattern;
  const Box2 frame = scene_frame(scene_);
  step.pattern = make_pattern(pattern, frame.max - frame.min);
  push_undo();
  try {
    StepEffects effects;
    apply_impregnate(prepared_.membrane, step, "", effects);
  } catch (const InputError&) {
    restore(undo_.back());
    undo_.pop_back();
    return "the resin pattern covers no spring of the sheet";
  }
  log_.push_back({"", step});
  stage_ = Stage::impregnated;
  model_changed();
  return "";
}

std::string ViewerSession::impregnate() {
  if (stage_ == Stage::flat) return "stretch the sheet before impregnating it";
  if (stage_ == Stage::released) return "the sheet is released: resin goes on the stretched sheet";
  const auto pattern = resin_pattern_spec();
  if (!pattern) return "there is no resin to apply: paint some first";
  const std::string why = impregnate_with(*pattern, first_step<ImpregnateStep>());
  if (!why.empty()) return why;
  // What was applied is used up; the next strokes start a new pattern.
  strokes_.clear();
  scene_pattern_used_ = true;
  return "";
}

std::string ViewerSession::release() {
  if (stage_ == Stage::flat) return "stretch the sheet before releasing it";
  if (stage_ == Stage::released) return "the sheet is already released";
  push_undo();
  const ReleaseStep* s = first_step<ReleaseStep>();
  const ReleaseStep r = s ? *s : ReleaseStep{};
  StepEffects effects;
  start_path(apply_release(prepared_.membrane, r, effects));
  log_.push_back({"", r});
  stage_ = Stage::released;
  model_changed();
  return "";
}

void ViewerSession::set_mode(LiveMode mode) {
  if (mode == mode_) return;
  mode_ = mode;
  model_changed();
}

SliceReport ViewerSession::advance(long max_iterations, double max_seconds) {
  last_slice_ = advance_slice(max_iterations, max_seconds);
  return last_slice_;
}

SliceReport ViewerSession::advance_slice(long max_iterations, double max_seconds) {
  SliceReport rep;
  Membrane& m = prepared_.membrane;
  const Model& model = m.sheet.model;
  if (settled_ && !queue_.empty()) {
    const ProtocolStep* step = queue_.front();
    queue_.pop_front();
    rep.message = apply_scene_step(*step);
  }
  if (settled_) {
    rep.settled = true;
    return rep;
  }
  const Points before = m.state.x;
  SolveReport r;
  if (mode_ == LiveMode::relax) {
    StaticOptions& o = relaxation_.options();
    o.max_seconds = max_seconds;
    // The path's increment to its tolerance (the path tolerance but for the last), as
    // `membra run` solves it.
    o.tolerance = walk_.done() ? scene_.simulation.tolerance : walk_.tolerance();
    r = relaxation_.advance(model, m.state, max_iterations);
  } else {
    // Motion in time: the scene's integrator, or the paper's RK4 for an equilibrium scene.
    SolverSettings o;
    o.dt = params_.T;
    o.steps = max_iterations;
    o.tolerance = scene_.simulation.tolerance;
    o.force_scale = prepared_.force_scale;
    o.max_seconds = max_seconds;
    const Solver integrator =
        scene_.simulation.is_static() ? Solver::rk4 : scene_.simulation.solver;
    r = solve_with(integrator, model, m.state, o);
  }
  rep.iterations = r.iterations;
  rep.residual_relative = r.residual_relative;
  if (r.diverged) {
    // Put the sheet back as it was before the slice, and stop until something changes.
    m.state.x = before;
    m.state.v.setZero();
    relaxation_.reset(model, m.state.x);
    rep.diverged = true;
    rep.message = r.message + (mode_ == LiveMode::dynamics ? " (try a smaller T or more D)" : "");
    settled_ = true;
    return rep;
  }
  if (!r.converged) return rep;
  if (!walk_.done()) {
    // The next increment of the path, as follow_path takes it.
    walk_.accept(m.state.x, r.iterations);
    if (!walk_.done()) {
      walk_.begin(m.state.x, &m.sheet.model);
      model_changed();
      return rep;
    }
  }
  settled_ = true;
  crossings_ = self_intersections(m.state.x, m.sheet.triangles);
  rep.settled = queue_.empty();
  return rep;
}

SliceReport ViewerSession::settle(long max_iterations) {
  SliceReport total;
  long spent = 0;
  while (spent < max_iterations) {
    const SliceReport s = advance(std::min<long>(5000, max_iterations - spent));
    spent += std::max<long>(1, s.iterations);
    total.iterations += s.iterations;
    total.residual_relative = s.residual_relative;
    if (!s.message.empty()) total.message = s.message;
    if (s.diverged) {
      total.diverged = true;
      return total;
    }
    if (s.settled && queue_.empty()) {
      total.settled = true;
      return total;
    }
  }
  return total;
}

void ViewerSession::play_scene_protocol() {
  for (const ProtocolStep& s : scene_.protocol) queue_.push_back(&s);
  if (!settled_) return;
  const ProtocolStep* first = queue_.front();
  queue_.pop_front();
  apply_scene_step(*first);
}

std::string ViewerSession::apply_scene_step(const ProtocolStep& step) {
  // The log keeps the scene's own step.
  auto logged = [&](const std::string& why) {
    if (why.empty() && !log_.empty()) log_.back() = step;
    return why;
  };
  switch (step.kind()) {
    case ProtocolStep::Kind::stretch: {
      const Vec2 keep = params_.lambda;
      params_.lambda = step.as<StretchStep>()->lambda;
      const std::string why = stretch();
      params_.lambda = keep;
      return logged(why);
    }
    case ProtocolStep::Kind::impregnate:
      if (stage_ == Stage::flat || stage_ == Stage::released)
        return "impregnate needs the stretched sheet";
      scene_pattern_used_ = true;
      return logged(
          impregnate_with(step.as<ImpregnateStep>()->pattern_spec, step.as<ImpregnateStep>()));
    case ProtocolStep::Kind::release:
      return logged(release());
    default:
      // A cut on the moved continuum sheet needs its mesh made again
      // (process/cut_after_motion.hpp), which the live session's sheet and undo history do not
      // follow.
      if (step.kind() == ProtocolStep::Kind::cut && prepared_.membrane.sheet.continuum() &&
          (stage_ == Stage::released ||
           std::any_of(log_.begin(), log_.end(), [](const auto& s) { return moves_sheet(s); })))
        return "on the continuum model the viewer cuts the sheet on its frame only; `membra run` "
               "cuts it after it has moved (it meshes the sheet again)";
      // cut, load, grow, add_springs, curvature_map: as the runner applies them.
      push_undo();
      try {
        StepEffects effects;
        start_path(apply_step(prepared_, step, effects));
      } catch (const InputError& e) {
        restore(undo_.back());
        undo_.pop_back();
        return e.what();
      }
      if (const auto* l = step.as<LoadStep>(); l && l->gravity) params_.G = *l->gravity;
      log_.push_back(step);
      model_changed();
      return "";
  }
}

void ViewerSession::start_path(Path path) {
  walk_ = IncrementWalk();
  if (path.kind != Path::Kind::gradual) return;
  // Live time stepping lets go at once, as `membra run` does with an integrator and no
  // ramp_seconds; the viewer does not ramp (a saved scene keeps the ramp for `membra run`).
  if (mode_ == LiveMode::dynamics) return path.set(1.0);
  // The live relaxation is first order: no predictor or halving (IncrementWalk). The first
  // increment at once, as follow_path takes it: the step's perturbation must still be there when
  // the change begins, or the sheet relaxes it away and buckles on round-off.
  walk_ = IncrementWalk(std::move(path), scene_.simulation, false);
  walk_.begin(prepared_.membrane.state.x, &prepared_.membrane.sheet.model);
}

Scene ViewerSession::to_scene() const {
  Scene s = scene_;
  s.protocol = log_;
  for (size_t i = 0; i < s.protocol.size(); ++i)
    s.protocol[i].pointer = "/protocol/" + std::to_string(i);
  if (scene_.benchmark_n == 0) {
    s.sheet.stretch_stiffness = params_.K;
    s.simulation.gravity = params_.G;
    s.simulation.dt = params_.T;
    s.simulation.damping = params_.D;
    // The live relaxation is FIRE whatever the scene names: a saved session names it, so that
    // `membra run` takes the same path to the same form (docs/viewer.md).
    if (mode_ == LiveMode::relax && s.simulation.is_static()) {
      s.simulation.solver = Solver::static_fire;
      s.simulation.self_contact.on = false;  // FIRE does not hold it, and the viewer did not
    }
    // A smaller T shortens the run's simulated time: keep it long enough for the scene's ramp.
    SimulationSpec& sim = s.simulation;
    if (sim.ramp_seconds > 0.0 && sim.ramp_seconds > static_cast<double>(sim.steps) * sim.dt)
      sim.steps = static_cast<long>(std::ceil(sim.ramp_seconds / sim.dt));
  }
  return s;
}

nlohmann::json ViewerSession::to_scene_json() const {
  return write_scene(to_scene());
}

}  // namespace membra
