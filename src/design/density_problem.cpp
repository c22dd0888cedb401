#include "membra/design/density_problem.hpp"

#include <stdexcept>

#include "membra/design/adjoint_solve.hpp"
#include "membra/model/pattern.hpp"
#include "membra/process/path.hpp"
#include "membra/process/steps.hpp"
#include "membra/solve/solver.hpp"

namespace membra {
namespace {

// Follows one protocol step (and its path) on `p`.
StepReport follow_step(const Scene& scene, PreparedScene& p, const ProtocolStep& step) {
  StepEffects effects;
  const Path path = apply_step(p, step, effects);
  FrameRecorder none;
  return follow_path(scene, p, p.membrane.state, effects.report.name, path, {}, none);
}

}  // namespace

DensityProblem::DensityProblem(Scene scene, DensityField field)
    : DensityProblem(std::move(scene), [&field](const Membrane& m, const Points& frame_x) {
        DensitySites sites = density_sites(m, frame_x, field);
        return std::make_unique<DensityMap>(field, std::move(sites));
      }) {}

DensityProblem::DensityProblem(Scene scene, const MapMaker& make_map) : scene_(std::move(scene)) {
  const auto& protocol = scene_.protocol;
  if (protocol.size() != 3 || !protocol[0].as<StretchStep>() || !protocol[1].as<ImpregnateStep>() ||
      !protocol[2].as<ReleaseStep>())
    throw std::invalid_argument("a design by the adjoint runs stretch, impregnate, release");
  auto* resin = scene_.protocol[1].as<ImpregnateStep>();
  if (resin->bilayer)
    throw std::invalid_argument("a density design does not yet place a bilayer coat");
  if (!solver_info(scene_.simulation.solver).equilibrium)
    throw std::invalid_argument("a design by the adjoint needs an equilibrium solver");
  // Resin everywhere (a polygon beyond the frame): each element learns its resin's stiffness and
  // length at impregnation; the variables then set only the fractions.
  const Box2 frame = scene_frame(scene_);
  const Vec2 pad = 0.01 * (frame.max - frame.min);
  const Vec2 lo = frame.min - pad, hi = frame.max + pad;
  resin->pattern = make_polygon({lo, Vec2(hi.x(), lo.y()), hi, Vec2(lo.x(), hi.y())});
  stretched_ = prepare_scene(scene_);
  for (int k = 0; k < 2; ++k) follow_step(scene_, stretched_, protocol[k]);
  frame_x_ = stretched_.membrane.state.x;
  map_ = make_map(stretched_.membrane, frame_x_);
}

Eigen::VectorXd DensityProblem::area_weights() const {
  const std::vector<double>& m = stretched_.membrane.sheet.model.mass;
  Eigen::VectorXd w =
      Eigen::Map<const Eigen::VectorXd>(m.data(), static_cast<Eigen::Index>(m.size()));
  return w / w.sum();
}

void DensityProblem::set_target(Correspondence target, double scale, double smoothing) {
  if (target.target.cols() != frame_x_.cols() || target.weight.size() != frame_x_.cols())
    throw std::invalid_argument("the target needs one point and one weight per particle");
  if (!(scale > 0.0)) throw std::invalid_argument("the target's scale must be > 0");
  target_ = std::move(target);
  scale_ = scale;
  smoothing_ = smoothing;
}

bool DensityProblem::release_from_frame(const Eigen::VectorXd& rho) {
  p_ = stretched_;
  map_->apply(p_.membrane, rho);
  const StepReport r = follow_step(scene_, p_, scene_.protocol[2]);
  iterations_ += r.solve.iterations;
  ++restarts_;
  released_ = r.solve.converged;
  return released_;
}

const DensityField& DensityProblem::field() const {
  static const DensityField none;
  const auto* densities = dynamic_cast<const DensityMap*>(map_.get());
  return densities ? densities->field() : none;
}

void DensityProblem::check_variables(const Eigen::VectorXd& rho) const {
  if (rho.size() != map_->size()) throw std::invalid_argument("one value per design variable");
}

bool DensityProblem::solve(const Eigen::VectorXd& rho) {
  check_variables(rho);
  if (released_) {
    if (anchor_.cols() == p_.membrane.state.x.cols()) {
      p_.membrane.state.x = anchor_;
      p_.membrane.state.v.setZero();
    }
    map_->apply(p_.membrane, rho);
    const SolveReport r = solve_scene_step(scene_, p_, p_.membrane.state, "design", {});
    iterations_ += r.iterations;
    if (r.converged || on_branch_only_) return r.converged;
  }
  return release_from_frame(rho);
}

void DensityProblem::anchor() {
  if (released_) anchor_ = p_.membrane.state.x;
}

bool DensityProblem::solve_from(const Eigen::VectorXd& rho, const Points& x) {
  check_variables(rho);
  if (x.cols() != frame_x_.cols())
    throw std::invalid_argument("a start needs one position per particle");
  p_ = stretched_;
  // The release step's end state without its path: the frame let go, the latex at its natural
  // length (apply_release, process/steps.cpp, ends there).
  begin_release(p_.membrane);
  set_release_level(p_.membrane, 0.0);
  map_->apply(p_.membrane, rho);
  p_.membrane.state.x = x;
  p_.membrane.state.v.setZero();
  const SolveReport r = solve_scene_step(scene_, p_, p_.membrane.state, "design", {});
  iterations_ += r.iterations;
  released_ = r.converged;
  anchor_.resize(3, 0);
  anchor();
  return released_;
}

DensityEvaluation DensityProblem::evaluate(const Eigen::VectorXd& rho) {
  if (target_.target.cols() == 0) throw std::logic_error("set_target before evaluate");
  DensityEvaluation ev;
  const long iterations = iterations_;
  const int restarts = restarts_;
  ev.converged = solve(rho);
  ev.newton_iterations = iterations_ - iterations;
  ev.restarted = restarts_ > restarts;
  ev.gradient = Eigen::VectorXd::Zero(rho.size());
  if (!ev.converged) return ev;
  const Points& x = positions();
  const AlignedDistance a = aligned_distance(x, target_);
  const double s2 = scale_ * scale_;
  Eigen::VectorXd smooth;
  ev.distance = a.value;
  ev.objective = a.value / s2 + map_->regularization(rho, smoothing_, &smooth);
  const std::optional<Points> w = solve_adjoint(p_.membrane.sheet.model, x, a.gradient / s2);
  if (!w) {  // not a stable minimum after all: no gradient to trust
    ev.converged = false;
    return ev;
  }
  ev.gradient = smooth - map_->pull_back(p_.membrane, rho, x, *w);
  return ev;
}

}  // namespace membra
