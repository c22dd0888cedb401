#include "membra/io/run.hpp"

#include "membra/io/input_error.hpp"
#include "membra/model/forces.hpp"
#include "membra/solve/dynamics.hpp"
#include "membra/solve/static_solver.hpp"

namespace membra {

PreparedScene prepare_scene(const Scene& scene) {
  PreparedScene p{build_sheet(scene.grid, scene.sheet), State{}, 0, 0.0};
  try {
    p.pinned = apply_pins(scene.pins, p.sheet.grid, p.sheet.model);
  } catch (const std::invalid_argument& e) {
    throw InputError("/pins", e.what());
  }
  Model& m = p.sheet.model;
  m.gravity = Vec3(0.0, 0.0, -scene.simulation.gravity);
  m.velocity_damping = scene.simulation.damping;
  p.state = State::at_rest(m);
  const double k =
      p.sheet.stiffness.stretch > 0.0 ? p.sheet.stiffness.stretch : p.sheet.stiffness.shear;
  p.force_scale = k * p.sheet.grid.hx();
  return p;
}

RunResult run_scene(const Scene& scene, const std::function<void(const Progress&)>& progress) {
  RunResult r{prepare_scene(scene), {}, 0.0, 0.0, 0.0, 0.0, {}};
  const Model& m = r.prepared.sheet.model;
  State& s = r.prepared.state;
  if (scene.simulation.solver == "static") {
    StaticOptions o;
    o.tolerance = scene.simulation.tolerance;
    o.force_scale = r.prepared.force_scale;
    o.max_iterations = scene.simulation.max_iterations;
    o.progress = progress;
    r.solve = solve_static(m, s, o);
  } else {
    DynamicsOptions o;
    o.method = scene.simulation.solver;
    o.dt = scene.simulation.dt;
    o.steps = scene.simulation.steps;
    o.tolerance = scene.simulation.tolerance;
    o.force_scale = r.prepared.force_scale;
    o.stop_when_converged = scene.simulation.stop_when_converged;
    o.progress = progress;
    r.solve = run_dynamics(m, s, o);
  }
  if (r.solve.diverged) return r;
  r.elastic_energy = elastic_energy(m, s.x);
  r.bending_energy = bending_energy(m, s.x);
  r.gravity_energy = gravity_energy(m, s.x);
  r.kinetic_energy = kinetic_energy(m, s.v);
  r.shape = summarize_shape(s.x);
  return r;
}

}  // namespace membra
