#include "membra/process/run.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <variant>

#include "membra/geometry/mesh_prolongation.hpp"
#include "membra/process/explore.hpp"
#include "membra/process/grid_resolution.hpp"
#include "membra/process/multilevel.hpp"
#include "membra/process/path.hpp"
#include "membra/process/steps.hpp"
#include "membra/process/summary.hpp"

namespace membra {
namespace {

// A run whose budget ran out (a solve stopped for it, and the run ended unconverged) says so,
// first, in its message.
void note_budget(const Scene& scene, RunResult& r) {
  r.out_of_time = r.solve.out_of_time && !r.solve.converged;
  if (r.out_of_time)
    r.solve.message = "stopped at the wall-time budget (simulation.max_seconds = " +
                      std::to_string(scene.simulation.max_seconds) + " s): " + r.solve.message;
}

}  // namespace

namespace {

// A step's share of a run's work: its increments where it follows a path, else one.
double step_weight(const ProtocolStep& step) {
  return std::visit(
      [](const auto& s) {
        if constexpr (requires { s.path.increments; })
          return static_cast<double>(std::max(1, s.path.increments));
        else
          return 1.0;
      },
      step.step);
}

}  // namespace

ProgressFn SceneRun::whole_run(ProgressFn progress) const {
  if (!progress) return progress;
  return [this, progress = std::move(progress)](const Progress& pr) {
    Progress q = pr;
    const auto& steps = scene_->protocol;
    double total = 0.0, done = 0.0;
    for (size_t k = 0; k < steps.size(); ++k) {
      const double w = step_weight(steps[k]);
      total += w;
      if (k < r_.steps.size())
        done += w;
      else if (k == r_.steps.size())
        done += w * std::max(0.0, pr.step_done);
    }
    q.run_done = total > 0.0 ? std::min(1.0, done / total) : -1.0;
    progress(q);
  };
}

SceneRun::SceneRun(const Scene& scene, ProgressFn progress)
    : scene_(&scene), progress_(whole_run(std::move(progress))) {
  r_.prepared = prepare_scene(scene);
  recorder_ = FrameRecorder{scene.output.frames, &r_.frames};
}

bool SceneRun::record(StepReport step) {
  accumulate(r_.solve, step.solve);
  r_.steps.push_back(std::move(step));
  // A spent wall-time budget ends the run as a divergence does: later steps would act on a
  // sheet their step before never brought where it was going.
  return !r_.solve.diverged && !r_.solve.out_of_time;
}

// The wall-time budget counts from the first step or solve (a notebook's pauses before it do
// not count; those between steps do).
void SceneRun::start_budget() {
  if (scene_->simulation.max_seconds > 0.0 && !r_.prepared.deadline)
    r_.prepared.deadline = std::chrono::steady_clock::now() +
                           std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                               std::chrono::duration<double>(scene_->simulation.max_seconds));
}

namespace {

// The frames recorded so far, carried to the new mesh (those of an earlier mesh, before a slit
// or a hole changed it, are left empty: drawn blank, as run_pictures does with such frames).
void carry_frames(std::vector<Frame>& frames, const SheetForm& from, const Sheet& to) {
  const Eigen::Index n = from.x.cols();
  const auto carry = [&](const Points& values) {
    return prolongate_on_mesh(from.reference, from.triangles, values, to.model.reference,
                              to.triangles);
  };
  for (Frame& f : frames) {
    if (f.x.cols() != n) {
      f = Frame{};
      continue;
    }
    Points stress = Points::Zero(3, n);
    if (static_cast<Eigen::Index>(f.stress.size()) == n)
      stress.row(0) = Eigen::Map<const Eigen::RowVectorXd>(f.stress.data(), n);
    const Points carried = carry(stress);
    f.x = carry(f.x);
    f.stress.resize(static_cast<size_t>(carried.cols()));
    for (Eigen::Index p = 0; p < carried.cols(); ++p)
      f.stress[static_cast<size_t>(p)] = carried(0, p);
  }
}

}  // namespace

ProtocolStep SceneRun::remesh_for(const ProtocolStep& given) {
  Membrane& m = r_.prepared.membrane;
  const ProtocolStep cut =
      cut_on_paper(m, given, 0.25 * scene_max_edge(*scene_), scene_->mesh.tolerance);
  auto own = std::make_unique<Scene>(*scene_);
  own->protocol = applied_steps_;
  own->protocol.push_back(cut);
  // The scene's steps after this one, so that their patterns are meshed as they were at the
  // start (a step made by hand has none).
  const auto& steps = scene_->protocol;
  for (size_t k = 0; k < steps.size(); ++k)
    if (&steps[k] == &given || (!given.pointer.empty() && steps[k].pointer == given.pointer)) {
      own->protocol.insert(own->protocol.end(), steps.begin() + static_cast<long>(k) + 1,
                           steps.end());
      break;
    }
  const SheetForm now = form_of(m);
  PreparedScene p = remesh_for_cut(*own, applied_steps_.size(), forms_, now);
  p.deadline = r_.prepared.deadline;
  r_.prepared = std::move(p);
  carry_frames(r_.frames, now, r_.prepared.membrane.sheet);
  own_scene_ = std::move(own);
  scene_ = own_scene_.get();
  return cut;
}

bool SceneRun::apply(const ProtocolStep& given, const Points* start) {
  if (diverged()) throw std::logic_error("the run diverged: no further step can be applied");
  start_budget();
  const auto* drawn = given.as<CutStep>();
  const bool continuum = r_.prepared.membrane.sheet.continuum();
  const bool remesh = continuum && drawn && !drawn->on_paper && moved_;
  if (remesh && start) throw std::logic_error("a cut that re-meshes is not solved from a form");
  const ProtocolStep step = remesh ? remesh_for(given) : given;
  if (continuum) forms_.push_back(form_of(r_.prepared.membrane));
  applied_steps_.push_back(step);
  moved_ = moved_ || moves_sheet(step);
  StepEffects effects;
  const Path path = apply_step(r_.prepared, step, effects);
  for (StressFeature& f : effects.features) r_.features.push_back(std::move(f));
  if (effects.curvature_map) r_.curvature_map = std::move(effects.curvature_map);
  State& s = r_.prepared.membrane.state;
  if (start) {  // the step's change in full, solved once from the given form
    if (start->cols() != s.x.cols()) throw std::invalid_argument("a start form per particle");
    if (path.kind == Path::Kind::gradual) path.set(1.0);
    s.x = *start;
    s.v.setZero();
    effects.report.solve =
        solve_scene_step(*scene_, r_.prepared, s, effects.report.name, progress_, &recorder_);
    recorder_.record(r_.prepared.membrane.sheet.model, s.x,
                     r_.prepared.membrane.sheet.material.thickness);
  } else {
    effects.report.solve =
        follow_path(*scene_, r_.prepared, s, effects.report.name, path, progress_, recorder_).solve;
  }
  if (const auto* cm = step.as<CurvatureMapStep>()) curvature_field_ = cm->curvature;
  return record(std::move(effects.report));
}

bool SceneRun::solve() {
  if (diverged()) throw std::logic_error("the run diverged: it cannot be solved further");
  start_budget();
  State& s = r_.prepared.membrane.state;
  return record(
      {"solve", solve_scene_step(*scene_, r_.prepared, s, "solve", progress_, &recorder_), 0});
}

namespace {

// What keeps a form from crossing itself, for the scene as it was run.
std::string contact_advice(const Scene& scene) {
  if (scene.model == SheetModel::lattice)
    return "The lattice has no self-contact: run the continuum with it (--set model=continuum "
           "--set simulation.self_contact=true), or try another perturbation or seed";
  if (!scene.simulation.self_contact.on)
    return std::string("Run it with self-contact (--set simulation.self_contact=true") +
           (scene.simulation.solver == Solver::newton ? "" : " --set simulation.solver=newton") +
           ")";
  return "Self-contact keeps points off triangles, not an edge off an edge: a finer mesh or a "
         "larger simulation.self_contact.gap";
}

}  // namespace

std::vector<std::string> run_warnings(const Scene& scene, const RunResult& r) {
  std::vector<std::string> out;
  if (const auto coarse = coarse_grid(scene)) out.push_back(coarse->message);
  if (r.solve.diverged) return out;
  if (r.self_intersection.pairs > 0)
    out.push_back("the form passes through itself: " + crossing_summary(r.self_intersection) +
                  " (final.obj's frame); no real sheet takes this form there. " +
                  contact_advice(scene) +
                  " (docs/measures.md, \"A form that passes through itself\")");
  for (const StepReport& step : r.steps)
    if (step.partly_covered > 0)
      out.push_back(step.pointer + ": " + std::to_string(step.partly_covered) +
                    " triangles of the mesh lie across the pattern's outline, each resin or latex "
                    "throughout by its centroid: the mesh does not follow the pattern there "
                    "(docs/model.md, \"Meshes that follow the pattern\")");
  // The other forms simulation.explore found, each written to branches/k/ (the one release 0,
  // the scene's own, ended in is the run's form, said above).
  for (size_t k = 0; k < r.branches.size(); ++k)
    if (r.branches[k].run.self_intersection.pairs > 0 &&
        std::find(r.branches[k].releases.begin(), r.branches[k].releases.end(), 0) ==
            r.branches[k].releases.end())
      out.push_back("simulation.explore: form " + std::to_string(k + 1) + " (branches/" +
                    std::to_string(k + 1) + "/) passes through itself: " +
                    crossing_summary(r.branches[k].run.self_intersection));
  return out;
}

RunResult SceneRun::result() const {
  RunResult r = r_;
  note_budget(*scene_, r);
  if (!r.solve.diverged) summarize_run(r, curvature_field_);
  return r;
}

RunResult SceneRun::finish() {
  note_budget(*scene_, r_);
  if (!r_.solve.diverged) summarize_run(r_, curvature_field_);
  return std::move(r_);
}

namespace {

// The protocol carried out on the scene's own grid, every path followed.
RunResult run_on_own_grid(const Scene& scene, const ProgressFn& progress) {
  SceneRun run(scene, progress);
  if (scene.protocol.empty()) run.solve();
  for (const ProtocolStep& step : scene.protocol)
    if (!run.apply(step)) break;
  return run.finish();
}

}  // namespace

RunResult run_scene(const Scene& scene, const ProgressFn& progress) {
  RunResult r =
      has_levels(scene) ? run_multilevel(scene, progress) : run_on_own_grid(scene, progress);
  if (scene.simulation.explore > 1 && !r.solve.diverged) explore_branches(scene, r, progress);
  // Once per run, not per grid level or explored release (after a level's own advice, if any).
  std::vector<std::string> warnings = run_warnings(scene, r);
  r.warnings.insert(r.warnings.end(), warnings.begin(), warnings.end());
  return r;
}

}  // namespace membra
