#include "membra/process/run.hpp"

#include "membra/core/input_error.hpp"
#include "membra/measure/hole_edge.hpp"
#include "membra/measure/stress_tensor.hpp"
#include "membra/model/added_springs.hpp"
#include "membra/model/benchmark_problem.hpp"
#include "membra/model/cut.hpp"
#include "membra/model/forces.hpp"
#include "membra/model/grow.hpp"
#include "membra/model/pins.hpp"
#include "membra/process/memory_estimate.hpp"
#include "membra/solve/dynamics.hpp"
#include "membra/solve/newton_solver.hpp"
#include "membra/solve/static_solver.hpp"

namespace membra {
namespace {

// Records frames: the state and the stress of its springs at that moment.
struct FrameRecorder {
  int wanted = 0;
  std::vector<Frame>* frames = nullptr;
  void record(const Model& m, const Points& x, double thickness) {
    if (!frames || static_cast<int>(frames->size()) >= wanted) return;
    frames->push_back({x, vertex_stress(m, spring_stress(m, x, thickness))});
  }
};

// Solves for equilibrium with the scene's solver: FIRE for "static", shifted Newton for
// "newton", damped time stepping otherwise.
// `tolerance` < 0: the scene's.
SolveReport solve(const Scene& scene, const PreparedScene& p, State& s, const std::string& stage,
                  const std::function<void(const Progress&)>& progress,
                  FrameRecorder* recorder = nullptr, double tolerance = -1.0) {
  if (tolerance < 0.0) tolerance = scene.simulation.tolerance;
  auto staged = [&](const Progress& pr) {
    if (!progress) return;
    Progress q = pr;
    q.stage = stage;
    progress(q);
  };
  const Model& m = p.membrane.sheet.model;
  if (scene.simulation.solver == "newton") {
    NewtonOptions o;
    o.tolerance = tolerance;
    o.force_scale = p.force_scale;
    o.progress = staged;
    return solve_newton(m, s, o);
  }
  if (scene.simulation.solver == "static") {
    StaticOptions o;
    o.tolerance = tolerance;
    o.force_scale = p.force_scale;
    o.max_iterations = scene.simulation.max_iterations;
    o.progress = staged;
    return solve_static(m, s, o);
  }
  DynamicsOptions o;
  o.method = scene.simulation.solver;
  o.dt = scene.simulation.dt;
  o.steps = scene.simulation.steps;
  o.tolerance = scene.simulation.tolerance;
  o.force_scale = p.force_scale;
  o.stop_when_converged = scene.simulation.stop_when_converged;
  o.progress = staged;
  if (recorder && recorder->wanted > 0) {
    // Evenly over the run, at the first check past each frame time.
    const long every = std::max<long>(1, o.steps / recorder->wanted);
    const double t = p.membrane.sheet.material.thickness;
    o.on_check = [&, every, t, next = every](const State& st, long step) mutable {
      if (step < next) return;
      recorder->record(m, st.x, t);
      next += every * ((step - next) / every + 1);
    };
  }
  return run_dynamics(m, s, o);
}

void accumulate(SolveReport& total, const SolveReport& r) {
  total.iterations += r.iterations;
  total.force_passes += r.force_passes;
  total.wall_seconds += r.wall_seconds;
  total.residual = r.residual;
  total.residual_relative = r.residual_relative;
  total.converged = r.converged;
  total.diverged = r.diverged;
  total.message = r.message;
}

// Follows a change of the model along a path: with an equilibrium solver, set(k / n) and a solve
// for k = 1..n (quasi-static: the sheet stays near equilibrium and picks the branch a slow
// process would); with time stepping, set(1) and one run of dynamics from the current state.
StepReport follow_path(const Scene& scene, const PreparedScene& p, State& s,
                       const std::string& name, int increments,
                       const std::function<void(double)>& set,
                       const std::function<void(const Progress&)>& progress,
                       FrameRecorder& recorder) {
  StepReport rep{name, {}, 0};
  if (!scene.simulation.is_static()) {
    set(1.0);
    rep.solve = solve(scene, p, s, name, progress, &recorder);
    return rep;
  }
  const double thickness = p.membrane.sheet.material.thickness;
  for (int k = 1; k <= increments && !rep.solve.diverged; ++k) {
    set(static_cast<double>(k) / increments);
    const std::string stage = name + " " + std::to_string(k) + "/" + std::to_string(increments);
    // Intermediate increments only carry the sheet along the path: a looser tolerance there
    // (simulation.path_tolerance) saves their slow tails; the last one is solved in full.
    const double tolerance =
        k < increments ? scene.simulation.path_tolerance : scene.simulation.tolerance;
    accumulate(rep.solve, solve(scene, p, s, stage, progress, nullptr, tolerance));
    recorder.record(p.membrane.sheet.model, s.x, thickness);
  }
  return rep;
}

int pin(const std::vector<PinSpec>& pins, const std::string& where, PreparedScene& p) {
  try {
    return apply_pins(pins, p.membrane.sheet.grid, p.membrane.sheet.model);
  } catch (const std::invalid_argument& e) {
    throw InputError(where, e.what());
  }
}

}  // namespace

PreparedScene prepare_scene(const Scene& scene) {
  check_memory(scene, machine_memory());  // before allocating anything
  if (scene.benchmark_n > 0) {
    // P(n): spacing 1 m, k = 1 N/m, unit masses; the force scale k x h = 1 N makes the
    // tolerance absolute, as the problem defines it.
    BenchmarkProblem b = make_benchmark_problem(scene.benchmark_n);
    const GridSheet grid(scene.grid);
    Sheet sheet{grid,
                scene.sheet.material,
                std::move(b.model),
                std::move(b.triangles),
                LatticeStiffness{1.0, 0.5, 0.1},
                scene.sheet};
    PreparedScene p{make_membrane(std::move(sheet)), 0, 1.0};
    p.membrane.state = b.start;
    p.membrane.sheet.model.gravity = Vec3::Zero();
    p.membrane.sheet.model.velocity_damping = scene.simulation.damping;
    return p;
  }
  NodeMask mask;
  if (scene.outline == "disk") {
    // The ellipse inscribed in the rectangle, with a hair of slack so nodes on it stay.
    const double a = 0.5 * scene.grid.width, b = 0.5 * scene.grid.height;
    mask = [a, b](double x, double y) {
      const double u = (x - a) / a, v = (y - b) / b;
      return u * u + v * v <= 1.0 + 1e-9;
    };
  }
  PreparedScene p{make_membrane(build_sheet(scene.grid, scene.sheet, mask)), 0, 0.0};
  p.pinned = pin(scene.pins, "/pins", p);
  Model& m = p.membrane.sheet.model;
  m.gravity = Vec3(0.0, 0.0, -scene.simulation.gravity);
  m.velocity_damping = scene.simulation.damping;
  const LatticeStiffness& k = p.membrane.sheet.stiffness;
  p.force_scale = (k.stretch > 0.0 ? k.stretch : k.shear) * p.membrane.sheet.grid.hx();
  return p;
}

RunResult run_scene(const Scene& scene, const std::function<void(const Progress&)>& progress) {
  RunResult r;
  r.prepared = prepare_scene(scene);
  FrameRecorder recorder{scene.output.frames, &r.frames};
  const double thickness = r.prepared.membrane.sheet.material.thickness;
  Membrane& mem = r.prepared.membrane;
  State& s = mem.state;
  auto record = [&](StepReport step) {
    accumulate(r.solve, step.solve);
    r.steps.push_back(std::move(step));
    return !r.solve.diverged;
  };

  if (scene.protocol.empty()) {
    record({"solve", solve(scene, r.prepared, s, "solve", progress, &recorder), 0});
  }
  std::function<double(const Vec2&)> curvature_field;  // of the last curvature_map step
  for (const ProtocolStep& step : scene.protocol) {
    bool ok = true;
    switch (step.kind) {
      case ProtocolStep::Kind::stretch:
        stretch_frame(mem, step.lambda.x(), step.lambda.y(), step.hold);
        ok = record({"stretch", solve(scene, r.prepared, s, "stretch", progress), 0});
        break;
      case ProtocolStep::Kind::impregnate: {
        const int n = impregnate(mem, *step.pattern, step.resin, step.resin_side, step.bilayer);
        if (n == 0)
          throw InputError(step.pointer + "/pattern",
                           "the pattern covers no spring of the sheet (is it between grid nodes, "
                           "or outside the stretched sheet?)");
        ok = record({"impregnate", {}, n});
        break;
      }
      case ProtocolStep::Kind::release: {
        // The latex returns to its natural length in increments (dynamics: at once, from the
        // stretched state, as the paper's tool does).
        perturb(mem, step.perturbation, step.seed);
        begin_release(mem);
        ok = record(follow_path(
            scene, r.prepared, s, "release", step.increments,
            [&](double t) { set_release_level(mem, 1.0 - t); }, progress, recorder));
        break;
      }
      case ProtocolStep::Kind::grow: {
        std::vector<double> ratios;
        try {
          ratios = growth_ratios(mem, step.grow);
        } catch (const std::invalid_argument& e) {
          throw InputError(step.pointer + "/factor", e.what());
        }
        perturb(mem, step.perturbation, step.seed);
        double applied = 0.0;  // share of the growth applied so far
        ok = record(follow_path(
            scene, r.prepared, s, "grow", step.increments,
            [&](double t) {
              apply_growth(mem, ratios, t - applied);
              applied = t;
            },
            progress, recorder));
        break;
      }
      case ProtocolStep::Kind::curvature_map: {
        const Model& model = mem.sheet.model;
        std::vector<double> target(static_cast<size_t>(model.num_particles()));
        for (int q = 0; q < model.num_particles(); ++q)
          target[q] = step.curvature(model.reference.col(q).head<2>());
        const ConformalFactor cf = conformal_factor(mem.sheet, target);
        CurvatureMapResult cm;
        cm.step = step.pointer;
        cm.reached = cf.reached;
        cm.message = cf.message;
        r.curvature_map = cm;
        const std::vector<double> ratios = conformal_growth(model, cf.u);
        perturb(mem, step.perturbation, step.seed);
        double applied = 0.0;
        ok = record(follow_path(
            scene, r.prepared, s, "curvature_map", step.increments,
            [&](double t) {
              apply_growth(mem, ratios, t - applied);
              applied = t;
            },
            progress, recorder));
        curvature_field = step.curvature;
        break;
      }
      case ProtocolStep::Kind::add_springs: {
        AddSpringsSpec spec = step.add;
        if (spec.stiffness <= 0.0) spec.stiffness = mem.sheet.stiffness.stretch;
        const int first = mem.sheet.model.springs.size();
        const int added = add_springs(mem, spec);
        if (added == 0)
          throw InputError(step.pointer + "/pattern",
                           "the region covers no spring of the sheet (is it between grid nodes, "
                           "or outside the sheet?)");
        std::vector<double> start;
        const Springs& sp = mem.sheet.model.springs;
        for (int k = first; k < sp.size(); ++k)
          start.push_back((s.x.col(sp.b[k]) - s.x.col(sp.a[k])).norm());
        perturb(mem, step.perturbation, step.seed);
        StepReport rep = follow_path(
            scene, r.prepared, s, "add_springs", step.increments,
            [&](double t) { set_added_springs_level(mem, first, start, spec.rest_factor, t); },
            progress, recorder);
        rep.springs_added = added;
        ok = record(rep);
        break;
      }
      case ProtocolStep::Kind::cut: {
        StepReport rep{"cut", {}, 0};
        if (!step.cut_line.empty()) {
          StressFeature f{step.pointer + "/line", "cut", {}};
          rep.springs_cut = cut_along(mem, step.cut_line, &f.where);
          if (rep.springs_cut == 0)
            throw InputError(step.pointer + "/line", "the cut crosses no spring of the sheet");
          r.features.push_back(std::move(f));
        }
        if (step.hole) {
          StressFeature f{step.pointer + "/hole", "hole", {}};
          try {
            rep.particles_removed = punch_hole(mem, *step.hole, &f.where);
          } catch (const std::invalid_argument& e) {
            throw InputError(step.pointer + "/hole", e.what());
          }
          if (rep.particles_removed == 0)
            throw InputError(step.pointer + "/hole", "the hole covers no particle of the sheet");
          r.features.push_back(std::move(f));
        }
        rep.solve = solve(scene, r.prepared, s, "cut", progress);
        ok = record(rep);
        break;
      }
      case ProtocolStep::Kind::load:
        if (step.gravity) mem.sheet.model.gravity = Vec3(0.0, 0.0, -*step.gravity);
        r.prepared.pinned += pin(step.pins, step.pointer + "/pins", r.prepared);
        ok = record({"load", solve(scene, r.prepared, s, "load", progress), 0});
        break;
    }
    if (!ok) break;
  }
  if (r.solve.diverged) return r;
  const Model& m = mem.sheet.model;
  r.elastic_energy = elastic_energy(m, s.x);
  // The bilayer hinges hold the linear part of the plate energy: reported with the bending.
  r.bending_energy = bending_energy(m, s.x) + hinge_energy(m, s.x);
  r.gravity_energy = gravity_energy(m, s.x);
  r.kinetic_energy = kinetic_energy(m, s.v);
  r.shape = summarize_shape(s.x, m.reference);
  r.curvature = gaussian_curvature(s.x, mem.sheet.triangles);
  smooth_density_on_grid(mem.sheet.grid, r.curvature);
  r.form = classify_form(r.curvature);
  r.stress = spring_stress(m, s.x, mem.sheet.material.thickness);
  // A small residual does not tell a minimum from a soft saddle.
  r.stability = check_stability(m, s.x, mem.sheet.stiffness.stretch);
  if (r.curvature_map) {
    // Compared over the interior: a tenth of the sheet's smaller side in from the edge, where
    // the edge's own (geodesic) curvature and the smoothing of the measure do not reach.
    CurvatureMapResult& cm = *r.curvature_map;
    cm.target.resize(static_cast<size_t>(m.num_particles()));
    for (int q = 0; q < m.num_particles(); ++q)
      cm.target[q] = curvature_field(m.reference.col(q).head<2>());
    cm.margin = 0.1 * std::min(mem.sheet.grid.width(), mem.sheet.grid.height());
    cm.match = match_curvature(mem.sheet, cm.target, r.curvature.density, cm.margin);
  }
  if (!r.features.empty()) {
    // Peak within 1.5 spacings (the particles on the new edge) against the median far away.
    const GridSheet& g = mem.sheet.grid;
    const auto principal = max_principal_stress(node_stress(g, m, s.x, thickness));
    const double near = 1.5 * std::max(g.hx(), g.hy());
    const double far = 0.25 * std::min(g.width(), g.height());
    for (const StressFeature& f : r.features) {
      StressConcentration c = stress_concentration(m, principal, f, near, far);
      if (f.kind == "hole") {
        const HoleEdge e = hole_edge(g, principal, f.where);
        c.has_edge = e.valid;
        c.edge_stress = e.value;
        c.edge_angle = e.angle;
        c.hole_radius = e.radius;
        if (e.valid && c.far_field_stress > 0.0)
          c.edge_concentration = e.value / c.far_field_stress;
      }
      r.concentrations.push_back(c);
    }
  }
  return r;
}

}  // namespace membra
