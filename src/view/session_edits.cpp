// The viewer session's edits: brush strokes, cuts, holes, pins, reset and the live parameters
// (the protocol buttons and the simulation are in viewer_session.cpp).
#include <algorithm>
#include <cmath>
#include <limits>

#include "membra/core/input_error.hpp"
#include "membra/model/cut.hpp"
#include "membra/process/steps.hpp"
#include "membra/view/viewer_session.hpp"

namespace membra {

std::string ViewerSession::paint(const Vec2& centre, double radius, bool erase) {
  if (!(radius > 0.0) || !centre.allFinite()) return "the brush needs a positive radius";
  if (stage_ == Stage::flat)
    return "stretch the sheet first: resin is painted on the stretched sheet (frame coordinates)";
  if (stage_ == Stage::released || stage_ == Stage::impregnated)
    return "paint resin on the sheet before impregnating it (undo or reset to go back)";
  push_undo();
  strokes_.push_back({centre, radius, erase});
  return "";
}

// The continuum sheet's mesh is made with the scene's cuts as edges (docs/deformation.md, "Holes
// and slits on the continuum model"): one drawn now would not follow it.
constexpr const char* kContinuumCuts =
    "on the continuum model holes and slits are cut in the scene's protocol, before the release, "
    "so that the mesh follows them";

std::string ViewerSession::cut(const Vec2& a, const Vec2& b) {
  if (!a.allFinite() || !b.allFinite() || (a - b).norm() == 0.0) return "the cut needs two points";
  if (prepared_.membrane.sheet.continuum()) return kContinuumCuts;
  push_undo();
  const int n = cut_along(prepared_.membrane, {a, b});
  if (n == 0) {
    undo_.pop_back();
    return "the cut crosses no spring of the sheet";
  }
  CutStep step;
  step.line = {a, b};
  log_.push_back({"", step});
  model_changed();
  return "";
}

std::string ViewerSession::hole(const Vec2& centre, double radius) {
  if (!(radius > 0.0) || !centre.allFinite()) return "the hole needs a positive radius";
  if (prepared_.membrane.sheet.continuum()) return kContinuumCuts;
  push_undo();
  CutStep step;
  step.hole_spec = circle_spec(centre, radius);
  step.hole = make_pattern(*step.hole_spec, Vec2::Zero());
  try {
    const int n = punch_hole(prepared_.membrane, *step.hole);
    if (n == 0) {
      undo_.pop_back();
      return "the hole covers no particle of the sheet";
    }
  } catch (const std::invalid_argument& e) {
    restore(undo_.back());
    undo_.pop_back();
    return e.what();
  }
  log_.push_back({"", step});
  model_changed();
  return "";
}

int ViewerSession::nearest_particle(const Vec2& at) const {
  const Points& x = prepared_.membrane.state.x;
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (Eigen::Index p = 0; p < x.cols(); ++p) {
    const double d = (x.col(p).head<2>() - at).squaredNorm();
    if (d < best_d) best_d = d, best = static_cast<int>(p);
  }
  return best;
}

std::string ViewerSession::toggle_pin(const Vec2& at) {
  const int p = nearest_particle(at);
  if (p < 0) return "the sheet has no particle";
  Membrane& m = prepared_.membrane;
  const Vec2 paper = m.sheet.model.reference.col(p).head<2>();
  auto is_mine = [&](const ProtocolStep& s) {
    const LoadStep* l = s.as<LoadStep>();
    return l && l->pins.size() == 1 && l->pins[0].kind == PinSpec::Kind::point &&
           (l->pins[0].point - paper).norm() < 1e-12;
  };
  const auto mine = std::find_if(viewer_pins_.begin(), viewer_pins_.end(),
                                 [&](const Vec2& q) { return (q - paper).norm() < 1e-12; });
  if (m.sheet.model.pinned(p) && mine == viewer_pins_.end())
    return "this particle is held by the scene's pins or the frame";
  push_undo();
  if (mine != viewer_pins_.end()) {
    m.sheet.model.unpin(p);
    viewer_pins_.erase(mine);
    // Its pin leaves the log again, so the saved scene does not pin it.
    const auto it = std::find_if(log_.begin(), log_.end(), is_mine);
    if (it != log_.end()) log_.erase(it);
  } else {
    m.sheet.model.pin(p);
    m.state.v.col(p).setZero();
    viewer_pins_.push_back(paper);
    LoadStep step;
    PinSpec pin;
    pin.kind = PinSpec::Kind::point;
    pin.point = paper;
    step.pins = {pin};
    log_.push_back({"", step});
  }
  model_changed();
  return "";
}

void ViewerSession::reset() {
  push_undo();
  prepared_ = prepare_scene(scene_);
  stage_ = Stage::flat;
  strokes_.clear();
  log_.clear();
  viewer_pins_.clear();
  walk_ = IncrementWalk();
  scene_pattern_used_ = false;
  queue_.clear();
  // The live parameters stay as the user set them.
  const LiveParameters p = params_;
  params_.K = prepared_.membrane.sheet.stiffness.stretch;
  set_parameters(p);
  model_changed();
}

std::string ViewerSession::set_parameters(const LiveParameters& p) {
  if (!(p.K > 0.0) || !std::isfinite(p.K)) return "K must be positive";
  if (!std::isfinite(p.G)) return "G must be a number";
  if (!(p.G > 0.0) && prepared_.membrane.sheet.model.table.size() > 0)
    return "G must be above 0: the piece rests on a table";
  if (!(p.T > 0.0) || !std::isfinite(p.T)) return "T must be positive";
  if (!(p.D >= 0.0) || !std::isfinite(p.D)) return "D must be zero or positive";
  if (!(p.lambda.x() > 0.0 && p.lambda.y() > 0.0 && p.lambda.maxCoeff() <= 10.0))
    return "the stretch ratios must be within (0, 10]";
  Membrane& m = prepared_.membrane;
  Model& model = m.sheet.model;
  bool changed = false;
  if (p.K != params_.K) {
    // Every latex spring keeps its ratio to K (shear K/2, flex, added); the resin does not change.
    const double ratio = p.K / params_.K;
    for (double& k : model.springs.latex_stiffness) k *= ratio;
    for (double& k : model.added_springs.stiffness) k *= ratio;
    m.sheet.stiffness.stretch *= ratio;
    m.sheet.stiffness.shear *= ratio;
    m.sheet.stiffness.flex *= ratio;
    model.springs.update(m.release());
    prepared_.force_scale *= ratio;
    changed = true;
  }
  if (p.G != params_.G || p.D != params_.D) changed = true;
  model.gravity = Vec3(0.0, 0.0, -p.G);
  // The table's weights follow G (its contact's depth under a particle's weight stays the same).
  if (p.G != params_.G && model.table.size() > 0)
    model.table.rest_on(model.mass, p.G, model.table.height, model.table.softness);
  model.velocity_damping = p.D;
  params_ = p;
  if (changed) model_changed();
  return "";
}

}  // namespace membra
