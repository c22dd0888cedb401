#include "membra/process/memory_estimate.hpp"

#include <fstream>
#include <sstream>
#include <string>

#include "membra/core/input_error.hpp"

namespace membra {

double estimate_memory(const Scene& scene) {
  const double particles = static_cast<double>(scene.grid.nx) * scene.grid.ny;
  const double per_particle = solver_info(scene.simulation.solver).bytes_per_particle;
  const double frames = static_cast<double>(scene.output.frames) * particles * 32.0;
  return particles * per_particle + frames + 64e6;  // + the program and its renderer
}

double machine_memory() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0.0;
  while (in >> key >> kb) {
    if (key == "MemTotal:") return kb * 1024.0;
    in.ignore(1 << 10, '\n');
  }
  return 0.0;
}

void check_memory(const Scene& scene, double available) {
  const double need = estimate_memory(scene);
  if (available <= 0.0 || need <= available) return;
  std::ostringstream msg;
  msg.precision(3);
  msg << scene.grid.nx << " x " << scene.grid.ny << " particles with the "
      << solver_name(scene.simulation.solver) << " solver need about " << need / 1e9
      << " GB, more than this machine's " << available / 1e9 << " GB; use a coarser resolution"
      << (solver_info(scene.simulation.solver).bytes_per_particle >
                  solver_info(Solver::static_fire).bytes_per_particle
              ? " or the static solver (2.5 kB per particle)"
              : "");
  throw InputError("/sheet/resolution", msg.str());
}

}  // namespace membra
