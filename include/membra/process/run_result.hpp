#pragma once
// What a run of a scene produced: the final state (in its prepared membrane), what each step did,
// the recorded frames, and the end-of-run summary (energies, shape, curvature, stress, cuts,
// stability).
#include <optional>
#include <string>
#include <vector>

#include "membra/geometry/rigid_fit.hpp"
#include "membra/measure/curvature.hpp"
#include "membra/measure/self_intersection.hpp"
#include "membra/measure/shape.hpp"
#include "membra/measure/stress.hpp"
#include "membra/measure/stress_concentration.hpp"
#include "membra/model/curvature_map.hpp"
#include "membra/process/prepare.hpp"
#include "membra/solve/solve_report.hpp"
#include "membra/solve/stability.hpp"

namespace membra {

// What one protocol step (or the single solve of a scene without protocol) did.
struct StepReport {
  std::string name;           // the step's kind ("stretch", "impregnate", ...) or "solve"
  SolveReport solve;          // the solve after the step (iterations 0 if none was needed)
  int resin_springs = 0;      // impregnate: springs that received resin
  int partly_covered = 0;     // impregnate, continuum: triangles across the pattern's outline
  int springs_added = 0;      // add_springs
  int springs_cut = 0;        // cut: springs a cut line removed
  int particles_removed = 0;  // cut: particles a hole removed
  std::string pointer = {};   // the step's place in the scene ("/protocol/k"), for messages
};

// One recorded instant of a run, for animations and contact sheets.
struct Frame {
  Points x;                    // positions, m
  std::vector<double> stress;  // mean spring stress at each particle, Pa
};

// A curvature_map step's outcome: the target, how much of it was reachable, how well the final
// form matches it.
struct CurvatureMapResult {
  std::string step;            // "/protocol/N"
  std::vector<double> target;  // 1/m^2 per particle of the final sheet
  double reached = 1.0;        // share of the map the conformal factor carries
  std::string message;         // why not all of it, when reached < 1
  double margin = 0.0;         // m: the interior compared lies this far from the edge
  CurvatureMatch match;
};

struct Branch;

// One solve of a grid in a multilevel run (process/multilevel.hpp): its size, how it began and
// its solves' totals.
struct GridLevel {
  int nx = 0, ny = 0;         // a lattice's grid
  double max_edge = 0.0;      // m: a continuum level's mesh (0 on a lattice)
  int elements_across = 0;    // the continuum level's mesh
  int vertices = 0;           // the continuum level's mesh
  bool from_coarser = false;  // started from the coarser grid's form (else: followed the path)
  SolveReport solve;
};

struct RunResult {
  PreparedScene prepared;  // prepared.membrane.state holds the final state
  SolveReport solve;       // totals over all solves; residual and convergence of the last
  std::vector<StepReport> steps;
  double elastic_energy = 0.0;  // J, springs
  double bending_energy = 0.0;  // J, bending elements and bilayer hinges
  double gravity_energy = 0.0;  // J
  double support_energy = 0.0;  // J, the table's contact (simulation.support)
  double contact_energy = 0.0;  // J, the sheet's contact with itself (simulation.self_contact)
  double kinetic_energy = 0.0;  // J
  TableReading table;           // what the table does (simulation.support "table")
  ContactReading contact;       // what self-contact does (simulation.self_contact)
  ShapeSummary shape;
  GaussianCurvature curvature;  // densities smoothed on the grid
  std::string form;             // classify_form(curvature)
  // The same of the global form (global_form in shape.hpp): wrinkles finer than the window
  // averaged out, so a bowl with a wrinkled rim reads as a bowl.
  GaussianCurvature curvature_global;
  std::string form_global;
  StressRanges stress;                // over the elements, for the sheet's thickness
  std::vector<double> vertex_stress;  // Pa, per particle (measure/stress.hpp), final state
  std::vector<Frame> frames;          // scene.output.frames instants (dynamic solves, release path)
  // The motion that placed the final state, its frames included, in the reading pose
  // (measure/reading_pose.hpp) after the energies and the stability were measured: positions
  // are R x + t of the simulation's. Identity for a form still held (pins or gravity).
  RigidMotion pose;
  bool posed = false;
  std::vector<StressFeature> features;              // the cuts and holes, in step order
  std::vector<StressConcentration> concentrations;  // stress at each feature, final state
  std::optional<CurvatureMapResult> curvature_map;  // scenes with a curvature_map step
  StabilityReport stability;                        // of the final state
  SelfIntersection self_intersection;  // of the final state: where it passes through itself
  // simulation.explore > 1: the distinct stable forms its releases ended in (explore.hpp),
  // most often found first; empty otherwise. This result is release 0's (the scene's own
  // imperfection), one of them when it is stable.
  std::vector<Branch> branches;
  // simulation.multilevel: every grid's solve, coarsest first, the scene's own last (whose
  // solve is `solve`); empty when the run used one grid.
  std::vector<GridLevel> levels;
  // Advice the run's user should see before trusting the form, e.g. a grid too coarse for the
  // pattern (grid_resolution.hpp); each a sentence naming the scene field.
  std::vector<std::string> warnings;
  bool out_of_time = false;  // stopped unconverged at simulation.max_seconds
  int explored = 0;          // releases made (0: no exploration)
  int unsettled = 0;         // of them, ended unconverged or at a saddle (in no branch)
};

// An end state worth keeping, listing as a branch or carrying to a finer grid: converged, within
// the budget, and a minimum wherever the stability check ran.
inline bool settled(const RunResult& r) {
  return r.solve.converged && !r.solve.diverged && !r.solve.saddle && !r.out_of_time &&
         (r.stability.stable || !r.stability.checked);
}

// One stable form found by exploring, with the first release that ended in it.
struct Branch {
  RunResult run;              // that release's result (its own branches empty)
  std::vector<int> releases;  // every release that ended in this form (0: the scene's own)
};

}  // namespace membra
