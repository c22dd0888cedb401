#include "membra/solve/newton_solver.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <random>
#include <vector>

#include <dlfcn.h>

#include "membra/model/forces.hpp"
#include "membra/solve/negative_curvature.hpp"
#include "membra/solve/newton_workspace.hpp"
#include "membra/solve/rigid_gauge.hpp"
#include "membra/solve/tangent_correction.hpp"

namespace membra {
namespace {

// The supernodal factorization calls BLAS; OpenBLAS's threads spin against the force passes'
// and make the sums, so the results, depend on the thread count. One BLAS thread keeps Newton
// deterministic and no slower on these sizes (docs/performance.md). Sets OpenBLAS's
// process-wide thread count when OpenBLAS is the BLAS in use (any other BLAS works unchanged).
void single_threaded_blas() {
  static const bool once = [] {
    using SetThreads = void (*)(int);
    if (auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
      set(1);
    return true;
  }();
  (void)once;
}

// Numbers the free coordinates into `dof` (-1: pinned, held by the gauge, or a z coordinate of a
// plane-stress solve) and returns how many there are.
int number_dofs(const Model& model, const std::vector<int>* gauge, bool in_plane,
                std::vector<int>& dof) {
  const int n = model.num_particles();
  dof.assign(static_cast<size_t>(3 * n), 0);
  for (int p = 0; p < n; ++p) {
    if (model.pinned(p)) dof[3 * p] = dof[3 * p + 1] = dof[3 * p + 2] = -1;
    if (in_plane) dof[3 * p + 2] = -1;
  }
  if (gauge)
    for (int k : *gauge) dof[static_cast<size_t>(k)] = -1;
  int ndof = 0;
  for (int& d : dof)
    if (d >= 0) d = ndof++;
  return ndof;
}

// The metric of the regularising shifts: |diagonal| of the assembled matrix (stiffness-scaled,
// so a 1000:1 resin/latex contrast is shifted in proportion), and in `floor` 1e-12 of its
// largest entry for coordinates that nothing stiffens.
Eigen::VectorXd shift_metric(const HessianAssembler& h, double& floor) {
  Eigen::VectorXd diag = h.diagonal().cwiseAbs();
  floor = 1e-12 * (diag.size() ? diag.maxCoeff() : 1.0);
  return diag;
}

// One solve: the state of Newton's iteration and its kinds of step.
class Newton {
 public:
  Newton(const Model& model, Points& x, const std::vector<int>& dof, int ndof,
         const NewtonOptions& o, SolveReport& r, std::unique_ptr<NewtonWorkspace>& ws)
      : model_(model),
        x_(x),
        dof_(dof),
        ndof_(ndof),
        o_(o),
        r_(r),
        ws_(ws),
        tangent_(model, dof, ndof) {
    length_ = saddle_escape_length(model);
    shifted_search_ = model.membrane_triangles.size() > 0;
  }

  void run(const Stopwatch& clock);

 private:
  bool exact_step();
  bool factor_projected();
  bool negative_curvature(Eigen::VectorXd& v, double& curvature);
  void exact_here();
  const Eigen::VectorXd& last_negative_curvature();
  bool shifted_negative_curvature(Eigen::VectorXd& v, double& curvature);
  bool escape_direction(Eigen::VectorXd& v, double& curvature) const;
  bool indefinite_step();
  bool continuation_step();
  bool exact_is_positive_definite();
  void assemble_exact();
  bool factorize(const Eigen::SparseMatrix<double>& a);
  bool line_search(const Eigen::VectorXd& d, double slope, double curvature,
                   const Eigen::VectorXd& e = {});
  Eigen::VectorXd corrected(const Eigen::VectorXd& d, const HessianAssembler& h);
  Eigen::VectorXd gradient(const Points& f) const;
  Eigen::VectorXd gradient() const { return gradient(f_); }
  Points moved(const Eigen::VectorXd& d, double alpha, const Eigen::VectorXd& e = {}) const;
  void evaluate();
  void refresh_contact();
  Points displacement(const Eigen::VectorXd& v) const;
  double contact_step_limit(const Eigen::VectorXd& d, const Eigen::VectorXd& e) const;

  const Model& model_;
  Points& x_;
  const std::vector<int>& dof_;
  int ndof_;
  const NewtonOptions& o_;
  SolveReport& r_;
  std::unique_ptr<NewtonWorkspace>& ws_;  // set up again when self-contact's pairs change
  TangentCorrection tangent_;
  Points f_;
  double energy_ = 0.0;
  double mu_ = 1e-8;            // shift of the projected matrix, in units of its diagonal
  double length_ = 1.0;         // m, the scale of a saddle escape (saddle_escape_length)
  bool try_exact_ = true;       // the last steps suggest the Hessian is positive definite
  double last_alpha_ = 0.0;     // the accepted step's share of the longest the line search allowed
  double ptc_shift_ = 1.0;      // continuation: 1/h^2, the implicit-Euler shift, units of diag|H|
  Eigen::VectorXd nc_;          // the last direction of negative curvature (the searches' start)
  double escape_shift_ = 1e-8;  // the shifted search's last working shift, units of diag|H|
  Points exact_x_;              // where exact_ was last assembled
  int stalled_ = 0;             // iterations since the residual last fell to half its reference
  double reference_residual_ = 0.0;
  static constexpr int kStalled = 20;  // stalled_ from which the shifted search is asked
  bool shifted_search_ = false;        // on the continuum only (docs/solver.md)
};

void Newton::evaluate() {
  compute_static_forces(model_, x_, f_);
  ++r_.force_passes;
  energy_ = potential_energy(model_, x_);
  r_.residual = max_free_force(model_, f_);
  r_.residual_relative = r_.residual / o_.force_scale;
}

// Self-contact's pairs gathered again where the sheet has come near itself
// (model/elements/self_contact.hpp): a changed list changes the Hessian's pattern, so the
// workspace is set up again, and the energy and forces are those of the new list.
void Newton::refresh_contact() {
  if (!model_.self_contact.refresh(x_)) return;
  ws_.reset();
  ws_ = std::make_unique<NewtonWorkspace>(model_, dof_, ndof_);
  ++r_.setups;
  exact_x_.resize(3, 0);
  tangent_.forget_pattern();
  evaluate();
}

// The motion of every particle for the free coordinates v (zero on held ones).
Points Newton::displacement(const Eigen::VectorXd& v) const {
  Points dx = Points::Zero(3, x_.cols());
  for (size_t k = 0; k < dof_.size(); ++k)
    if (const int i = dof_[k]; i >= 0) dx.data()[k] = v[i];
  return dx;
}

// The share of the step x + alpha d + alpha^2 e that self-contact allows (1 without it).
double Newton::contact_step_limit(const Eigen::VectorXd& d, const Eigen::VectorXd& e) const {
  if (!model_.self_contact.enabled()) return 1.0;
  const Points ed = e.size() == d.size() ? displacement(e) : Points();
  return model_.self_contact.step_limit(x_, displacement(d), ed);
}

Eigen::VectorXd Newton::gradient(const Points& f) const {
  Eigen::VectorXd g(ndof_);
  for (size_t k = 0; k < dof_.size(); ++k)
    if (dof_[k] >= 0) g[dof_[k]] = -f.data()[k];
  return g;
}

// x + alpha d + alpha^2 e: a straight step, or a curved one with a second-order correction e.
Points Newton::moved(const Eigen::VectorXd& d, double alpha, const Eigen::VectorXd& e) const {
  Points xt = x_;
  const bool curved = e.size() == d.size();
  for (size_t k = 0; k < dof_.size(); ++k)
    if (const int i = dof_[k]; i >= 0)
      xt.data()[k] += alpha * d[i] + (curved ? alpha * alpha * e[i] : 0.0);
  return xt;
}

// The tangent correction of the step d (tangent_correction.hpp) with h the Hessian d was solved
// with; kept only where it lowers the energy at the step's end, else empty.
Eigen::VectorXd Newton::corrected(const Eigen::VectorXd& d, const HessianAssembler& h) {
  if (!tangent_.applies() || !o_.tangent_correction) return {};
  const Points xt = moved(d, 1.0);
  Points ft;
  compute_static_forces(model_, xt, ft);
  ++r_.force_passes;
  Eigen::VectorXd e;
  const long factorizations = tangent_.factorizations(), analyses = tangent_.analyses();
  const bool solved = ft.allFinite() && tangent_.correction(x_, h.lower(), gradient(ft), e);
  r_.factorizations += tangent_.factorizations() - factorizations;
  r_.setups += tangent_.analyses() - analyses;
  if (!solved) return {};
  const double straight = potential_energy(model_, xt);
  const double curved = potential_energy(model_, moved(d, 1.0, e));
  if (!(curved < straight)) return {};
  ++r_.tangent_corrections;
  return e;
}

bool Newton::factorize(const Eigen::SparseMatrix<double>& a) {
  ++r_.factorizations;
  return ws_->factorize(a);
}

// Backtracking on the energy along d: alpha is accepted when the energy falls by at least 1e-4
// of what the local model promises (slope alpha + curvature alpha^2 / 2; the curvature term only
// for negative-curvature steps). Near convergence the change drowns in round-off, so a step that
// lowers the residual is accepted too.
bool Newton::line_search(const Eigen::VectorXd& d, double slope, double curvature,
                         const Eigen::VectorXd& e) {
  const double longest = contact_step_limit(d, e);  // 1 without self-contact
  double alpha = longest;
  for (int k = 0; k < 40; ++k, alpha *= 0.5) {
    Points xt = moved(d, alpha, e);
    const double et = potential_energy(model_, xt);
    if (!std::isfinite(et)) continue;
    const double promised = alpha * slope + 0.5 * alpha * alpha * std::min(curvature, 0.0);
    const bool armijo = et <= energy_ + 1e-4 * promised;
    if (!armijo && !(std::abs(et - energy_) <= 1e-12 * std::abs(energy_))) continue;
    Points ft;
    compute_static_forces(model_, xt, ft);
    ++r_.force_passes;
    const double residual = max_free_force(model_, ft);
    if (!armijo && !(residual < r_.residual)) continue;
    // Accepted: the forces and energy just computed are the new state's.
    x_ = std::move(xt);
    f_ = std::move(ft);
    energy_ = et;
    r_.residual = residual;
    r_.residual_relative = residual / o_.force_scale;
    last_alpha_ = alpha / longest;
    return true;
  }
  return false;
}

// Factorizes the exact Hessian plus a shift of 1e-10 of its diagonal (the gauge has removed the
// rigid motions; the shift only keeps floppy but stable modes factorizable): success means the
// energy is convex here, a minimum if the forces vanish.
bool Newton::exact_is_positive_definite() {
  assemble_exact();
  double floor = 0.0;
  const Eigen::VectorXd diag = shift_metric(ws_->exact, floor);
  ws_->exact.add_to_diagonal((1e-10 * diag).array() + floor);
  return factorize(ws_->exact.lower());
}

void Newton::assemble_exact() {
  ws_->exact.assemble(x_, false);
  exact_x_ = x_;
}

bool Newton::exact_step() {
  if (!exact_is_positive_definite()) return false;
  const Eigen::VectorXd g = gradient();
  const Eigen::VectorXd d = ws_->llt.solve(-g);
  const double slope = g.dot(d);
  return slope < 0.0 && line_search(d, slope, 0.0, corrected(d, ws_->exact));
}

// Factorizes the projected Hessian at x plus mu times its diagonal, growing mu (remembered
// across iterations) until the factorization succeeds.
bool Newton::factor_projected() {
  ws_->projected.assemble(x_, true);
  double floor = 0.0;
  const Eigen::VectorXd diag = shift_metric(ws_->projected, floor);
  double applied = 0.0;
  for (int attempt = 0; attempt < 20; ++attempt, mu_ *= 10.0) {
    ws_->projected.add_to_diagonal(((mu_ - applied) * diag).array() +
                                   (applied == 0.0 ? floor : 0.0));
    applied = mu_;
    if (factorize(ws_->projected.lower())) return true;
  }
  return false;
}

// The exact Hessian at x without shifts: the matrix the last factorization attempt shifted
// (the same numbers as a new assembly), or assembled anew where it was not tried here.
void Newton::exact_here() {
  if (exact_x_.cols() == x_.cols() && exact_x_ == x_)
    ws_->exact.remove_shifts();
  else
    assemble_exact();
}

// The last direction of negative curvature found, or a fixed random one: the searches' start.
const Eigen::VectorXd& Newton::last_negative_curvature() {
  if (nc_.size() != ndof_) {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    nc_.resize(ndof_);
    for (Eigen::Index k = 0; k < ndof_; ++k) nc_[k] = u(rng);
  }
  return nc_;
}

// With the projected matrix A factored at x: power iteration on I - A^-1 H, whose eigenvalues
// above 1 belong to directions of negative curvature of the energy, finds the most negative one
// in A's metric (warm-started from the last one found, so a few iterations suffice). Returns
// false when the energy has no negative curvature there; the direction is scaled and turned by
// escape_direction.
bool Newton::negative_curvature(Eigen::VectorXd& v, double& curvature) {
  exact_here();
  v = last_negative_curvature();
  for (int it = 0; it < 8; ++it) {
    v = ws_->llt.solve(ws_->projected.multiply(v) - ws_->exact.multiply(v));
    v /= v.norm();
  }
  nc_ = v;
  return escape_direction(v, curvature);
}

// Scales a direction v of negative curvature of ws_->exact to move no particle by more than the
// escape length and turns it downhill, or (at an exact saddle) so that it continues the sheet's
// present out-of-plane displacement, so the side is the seeded perturbation's (resin_side); false
// if v.Hv is not negative.
bool Newton::escape_direction(Eigen::VectorXd& v, double& curvature) const {
  const Points dv = moved(v, 1.0) - x_;
  const double largest = dv.colwise().norm().maxCoeff();
  if (!(v.dot(ws_->exact.multiply(v)) < 0.0) || !(largest > 0.0)) return false;
  v *= length_ / largest;
  const Eigen::VectorXd g = gradient();
  const double slope = g.dot(v);
  if (std::abs(slope) <= 1e-12 * g.norm() * v.norm()) {
    const Eigen::VectorXd height = x_.row(2).transpose().array() - x_.row(2).mean();
    if (dv.row(2).transpose().dot(height) < 0.0) v = -v;
  } else if (slope > 0.0) {
    v = -v;
  }
  curvature = v.dot(ws_->exact.multiply(v));
  return true;
}

// Where the power iteration finds no negative curvature (a small negative eigenvalue among the
// wrinkling latex's soft modes): the exact Hessian's most negative curvature by the shifted
// Lanczos search (negative_curvature.hpp), scaled and turned by escape_direction. Leaves ws_->llt
// holding the shifted exact matrix; the shift's ladder starts a decade below its last success.
bool Newton::shifted_negative_curvature(Eigen::VectorXd& v, double& curvature) {
  // One search per stall: the clock restarts whatever it finds, so a search that finds nothing
  // (or a step that escapes) is not repeated at every iteration while the residual recovers.
  reference_residual_ = r_.residual;
  stalled_ = 0;
  // ws_->exact is at x without shifts: negative_curvature has just made it so.
  double floor = 0.0;
  const Eigen::VectorXd metric = shift_metric(ws_->exact, floor).array() + floor;
  const CurvatureSearch s = most_negative_curvature(
      ws_->exact, metric, last_negative_curvature(), escape_shift_ / 10.0,
      {[this](const auto& a) { return factorize(a); },
       [this](const auto& b) { return Eigen::VectorXd(ws_->llt.solve(b)); }});
  if (!s.found) return false;
  escape_shift_ = std::max(s.shift, 1e-9);
  nc_ = s.direction;
  v = s.direction;
  return escape_direction(v, curvature);
}

// The better of the projected Newton step and a step along negative curvature, judged by the
// energy decrease each promises (-g.d/2 for the Newton step of the convex model; -(g.v + v.Hv/2)
// along negative curvature, where the quadratic model has no minimum).
bool Newton::indefinite_step() {
  const Eigen::VectorXd g = gradient();
  const Eigen::VectorXd d = ws_->llt.solve(-g);
  const double slope = g.dot(d);
  Eigen::VectorXd v;
  double curvature = 0.0;
  bool has_nc = negative_curvature(v, curvature);
  // The shifted search costs a few factorizations: asked for only at a saddle (small forces) or
  // where Newton has stalled, which the hyperbola's creep does and a steady release does not;
  // and only on the continuum, whose wrinkling latex hides its negative curvature from the power
  // iteration (on the lattice it moved validated forms to other minima: docs/solver.md, "The
  // saddle's escape").
  const bool stuck =
      shifted_search_ && (r_.residual_relative <= o_.tolerance || stalled_ >= kStalled);
  const bool lanczos = !has_nc && stuck && shifted_negative_curvature(v, curvature);
  has_nc = has_nc || lanczos;
  const double promised_nc = has_nc ? -(g.dot(v) + 0.5 * curvature) : 0.0;
  if (has_nc && (promised_nc > -0.5 * slope || !(slope < 0.0))) {
    if (line_search(v, g.dot(v), curvature)) {
      ++r_.negative_curvature_steps;
      if (lanczos) ++r_.lanczos_steps;
      return true;
    }
  }
  if (slope < 0.0 && line_search(d, slope, 0.0)) {
    if (last_alpha_ == 1.0) mu_ = std::max(0.25 * mu_, 1e-8);
    if (last_alpha_ < 0.25) mu_ *= 4.0;
    return true;
  }
  return false;
}

// Pseudo-transient continuation: one implicit-Euler step of the gradient flow in the
// stiffness-diagonal metric, (H + diag|H| / h^2) dx = -g, taken in full. The shift grows (x4)
// until the matrix factorizes and after a step that raises both the energy and the residual
// (which is undone); otherwise h grows with the residual ratio (switched evolution relaxation,
// shift x (r_new / r_old)^2) and at least by sqrt 2 (shift x 1/2), so the steps become Newton's
// near a minimum. Without that floor the shift stalls wherever the sheet creeps with a residual
// that hardly falls (a buckled release: over 5000 steps, against 400 ms with it; the hyperbola
// at 21^2 ended at a saddle). Measured against Newton in docs/solver.md: it still loses, and
// stays as a benchmark candidate.
bool Newton::continuation_step() {
  assemble_exact();
  double floor = 0.0;
  const Eigen::VectorXd diag = shift_metric(ws_->exact, floor);
  double applied = 0.0;
  bool factored = false;
  for (int attempt = 0; attempt < 30 && !factored; ++attempt) {
    if (attempt > 0) ptc_shift_ *= 4.0;
    ws_->exact.add_to_diagonal(((ptc_shift_ - applied) * diag).array() +
                               (applied == 0.0 ? floor : 0.0));
    applied = ptc_shift_;
    factored = factorize(ws_->exact.lower());
  }
  if (!factored) return false;
  // Self-contact: no further than the contact allows (the step is not line-searched).
  Eigen::VectorXd d = ws_->llt.solve(-gradient());
  d *= contact_step_limit(d, {});
  Points xt = moved(d, 1.0);
  const double et = potential_energy(model_, xt);
  Points ft;
  compute_static_forces(model_, xt, ft);
  ++r_.force_passes;
  const double residual = max_free_force(model_, ft);
  if (!std::isfinite(et) || !std::isfinite(residual) || (et > energy_ && residual >= r_.residual)) {
    ptc_shift_ *= 4.0;  // too long a step: undone, a shorter one next
    return true;
  }
  const double ratio = residual / r_.residual;
  ptc_shift_ = std::clamp(ptc_shift_ * std::min(ratio * ratio, 0.5), 1e-10, 1e12);
  x_ = std::move(xt);
  f_ = std::move(ft);
  energy_ = et;
  r_.residual = residual;
  r_.residual_relative = residual / o_.force_scale;
  last_alpha_ = 1.0;
  return true;
}

void Newton::run(const Stopwatch& clock) {
  evaluate();
  bool exact_recent = false;  // the last step was a Newton step on a positive definite Hessian
  for (long it = 0;; ++it) {
    refresh_contact();
    if (!std::isfinite(r_.residual) || !std::isfinite(energy_)) {
      r_.diverged = true;
      r_.message = "newton diverged at iteration " + std::to_string(it) +
                   ": forces became NaN/Inf. Try more increments" +
                   (model_.self_contact.enabled() ? std::string(".") : " or the static solver.");
      return;
    }
    if (o_.progress)
      o_.progress({"", it, o_.max_iterations, r_.residual_relative, clock.seconds(), -1.0, -1.0});
    if (it == 0 || r_.residual < 0.5 * reference_residual_) {
      reference_residual_ = r_.residual;
      stalled_ = 0;
    } else {
      ++stalled_;
    }
    if (r_.residual_relative <= o_.tolerance) {
      if (exact_recent || exact_is_positive_definite()) {
        r_.converged = true;
        return;
      }
      // Forces vanish but the energy is not convex: a saddle. Leave it downhill.
      if (it >= o_.max_iterations || !(factor_projected() && indefinite_step())) {
        r_.saddle = true;
        r_.message =
            "newton: stopped at a saddle of the energy (no descent along negative "
            "curvature found); try another perturbation seed or more increments";
        return;
      }
      exact_recent = false;
      ++r_.iterations;
      continue;
    }
    if (it >= o_.max_iterations || ndof_ == 0) return;
    if (o_.max_seconds > 0.0 && clock.seconds() > o_.max_seconds) return;
    ++r_.iterations;
    if (o_.continuation) {
      if (!continuation_step()) {
        r_.message =
            "ptc: the shifted Hessian did not factorize at iteration " + std::to_string(it);
        return;
      }
      continue;
    }
    exact_recent = try_exact_ && exact_step();
    if (exact_recent) continue;
    try_exact_ = false;
    const bool stepped = factor_projected() && indefinite_step();
    if (!stepped) {
      r_.message = "newton: no downhill step found at iteration " + std::to_string(it);
      return;
    }
    if (last_alpha_ == 1.0) try_exact_ = true;
  }
}

}  // namespace

std::shared_ptr<NewtonCache> make_newton_cache() {
  return std::make_shared<NewtonCache>();
}

SolveReport solve_newton(const Model& model, State& state, const NewtonOptions& o) {
  const Stopwatch clock;
  single_threaded_blas();
  SolveReport r;
  const int n = model.num_particles();
  bool any_pinned = false;
  for (int p = 0; p < n; ++p) any_pinned = any_pinned || model.pinned(p);
  // A free sheet is solved in the gauge's frame (rigid_gauge.hpp) and turned back after.
  const bool gauged = !any_pinned && n >= 3;
  const RigidGauge gauge = gauged ? free_sheet_gauge(model, state.x) : RigidGauge{};
  Model turned;  // a turn about z (the planar gauge's) leaves gravity and the table as they are
  const bool turn_gravity = gauged && !held_by_table(model) && model.gravity != Vec3::Zero();
  if (turn_gravity) turned = model, turned.gravity = gauge.rotation * model.gravity;
  const Model& m = turn_gravity ? turned : model;
  Points x = gauged ? Points(gauge.rotation * state.x) : state.x;
  std::vector<int> dof;
  const int ndof = number_dofs(m, gauged ? &gauge.held : nullptr, o.in_plane, dof);
  if (ndof == 0) {
    // Every particle pinned (or held by the gauge): nothing can move, so there is nothing to
    // solve (the residual counts free particles only, and there are none).
    state.v.setZero(3, n);
    r.converged = true;
    r.message = "newton: nothing to solve: every particle is pinned";
    r.wall_seconds = clock.seconds();
    return r;
  }
  // The cache's workspace when no other solve holds it and it fits this sheet; else a new one,
  // kept in the cache (when free) for the next solve.
  // Self-contact's pairs gathered here first, so that a cached workspace is judged against them.
  m.self_contact.refresh(x);
  std::unique_lock<std::mutex> lock;
  if (o.cache) lock = std::unique_lock<std::mutex>(o.cache->in_use, std::try_to_lock);
  std::unique_ptr<NewtonWorkspace> own;
  std::unique_ptr<NewtonWorkspace>& ws = lock.owns_lock() ? o.cache->workspace : own;
  if (ws && ws->fits(m, dof)) {
    ws->bind(m);
  } else {
    ws.reset();  // the old factor and Hessians go before the new ones are built
    ws = std::make_unique<NewtonWorkspace>(m, dof, ndof);
    ++r.setups;
  }
  Newton newton(m, x, dof, ndof, o, r, ws);
  newton.run(clock);
  if (&m != &model) model.self_contact.take_pairs(m.self_contact);
  state.x = gauged ? Points(gauge.rotation.transpose() * x) : x;
  state.v.setZero(3, n);
  r.wall_seconds = clock.seconds();
  if (r.message.empty() || r.converged)
    r.message = summary_message(o.continuation ? "ptc" : "newton", r, o.tolerance);
  return r;
}

}  // namespace membra
