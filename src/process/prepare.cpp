#include "membra/process/prepare.hpp"

#include <stdexcept>

#include "membra/core/input_error.hpp"
#include "membra/model/benchmark_problem.hpp"
#include "membra/model/pins.hpp"
#include "membra/process/memory_estimate.hpp"

namespace membra {
namespace {

// P(n): spacing 1 m, k = 1 N/m, unit masses; the force scale k x h = 1 N makes the tolerance
// absolute, as the problem defines it.
PreparedScene prepare_benchmark(const Scene& scene) {
  BenchmarkProblem b = make_benchmark_problem(scene.benchmark_n);
  const GridSheet grid(scene.grid);
  Sheet sheet{grid,
              scene.sheet.material,
              std::move(b.model),
              std::move(b.triangles),
              LatticeStiffness{1.0, 0.5, 0.1},
              scene.sheet};
  PreparedScene p{make_membrane(std::move(sheet)), 0, 1.0, std::nullopt};
  p.membrane.state = b.start;
  p.membrane.sheet.model.gravity = Vec3::Zero();
  p.membrane.sheet.model.velocity_damping = scene.simulation.damping;
  return p;
}

// The particles the sheet's outline keeps (none removed for a rectangle).
NodeMask outline_mask(const Scene& scene) {
  if (scene.outline != "disk") return {};
  // The ellipse inscribed in the rectangle, with a hair of slack so nodes on it stay.
  const double a = 0.5 * scene.grid.width, b = 0.5 * scene.grid.height;
  return [a, b](double x, double y) {
    const double u = (x - a) / a, v = (y - b) / b;
    return u * u + v * v <= 1.0 + 1e-9;
  };
}

}  // namespace

int pin(const std::vector<PinSpec>& pins, const std::string& where, PreparedScene& p) {
  try {
    return apply_pins(pins, p.membrane.sheet.grid, p.membrane.sheet.model);
  } catch (const std::invalid_argument& e) {
    throw InputError(where, e.what());
  }
}

PreparedScene prepare_scene(const Scene& scene) {
  check_memory(scene, machine_memory());  // before allocating anything
  if (scene.benchmark_n > 0) return prepare_benchmark(scene);
  PreparedScene p{make_membrane(build_sheet(scene.grid, scene.sheet, outline_mask(scene))), 0, 0.0,
                  std::nullopt};
  p.pinned = pin(scene.pins, "/pins", p);
  Model& m = p.membrane.sheet.model;
  m.gravity = Vec3(0.0, 0.0, -scene.simulation.gravity);
  m.velocity_damping = scene.simulation.damping;
  const LatticeStiffness& k = p.membrane.sheet.stiffness;
  p.force_scale = (k.stretch > 0.0 ? k.stretch : k.shear) * p.membrane.sheet.grid.hx();
  return p;
}

}  // namespace membra
