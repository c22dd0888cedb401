// The one solver switch: every solver's name leads back to it, names are unique, scenes see only
// the solvers they may choose, and each equilibrium solver finds the same equilibrium of a small
// pinned sheet pulled at one edge.
#include <gtest/gtest.h>

#include <set>

#include "membra/geometry/grid_sheet.hpp"
#include "membra/model/sheet.hpp"
#include "membra/solve/solver.hpp"
#include "membra/solve/static_solver.hpp"

namespace membra {
namespace {

TEST(SolverSwitch, EveryNameLeadsBackToItsSolver) {
  std::set<std::string_view> names;
  for (const SolverInfo& s : solver_table()) {
    EXPECT_TRUE(names.insert(s.name).second) << s.name;
    ASSERT_TRUE(solver_from_name(s.name).has_value());
    EXPECT_EQ(*solver_from_name(s.name), s.id);
    EXPECT_EQ(solver_name(s.id), s.name);
    EXPECT_GT(s.bytes_per_particle, 0.0);
  }
  EXPECT_FALSE(solver_from_name("euler").has_value());
  const auto scene_names = solver_names();
  EXPECT_EQ(std::vector<std::string_view>(scene_names.begin(), scene_names.begin() + 2),
            (std::vector<std::string_view>{"static", "newton"}));
  EXPECT_EQ(std::count(scene_names.begin(), scene_names.end(), "dr_unit"), 0);
  EXPECT_EQ(solver_names(false).size(), solver_table().size());
}

// A 9 x 9 latex sheet, 50 mm, left edge pinned, right edge moved 5 mm out and pinned, weightless.
struct PulledSheet {
  Sheet sheet;
  State start;
};

PulledSheet pulled_sheet() {
  GridSpec g{0.05, 0.05, 9, 9};
  SheetOptions o;
  o.material = *material_preset("latex");
  PulledSheet p{build_sheet(g, o, {}), {}};
  Model& m = p.sheet.model;
  m.gravity = Vec3::Zero();
  p.start = State{m.reference, Points::Zero(3, m.num_particles())};
  for (int j = 0; j < 9; ++j) {
    m.pin(p.sheet.grid.particle(0, j));
    const int r = p.sheet.grid.particle(8, j);
    p.start.x(0, r) += 0.005;
    m.pin(r);
  }
  return p;
}

TEST(SolverSwitch, TheEquilibriumSolversAgreeOnAPulledSheet) {
  PulledSheet p = pulled_sheet();
  const Sheet& sheet = p.sheet;
  const Model& m = sheet.model;
  const State& start = p.start;
  SolverSettings settings;
  settings.tolerance = 1e-9;
  settings.force_scale = sheet.stiffness.stretch * sheet.grid.hx();
  settings.newton_iterations = 200;
  std::vector<Points> ends;
  for (const Solver s : {Solver::static_fire, Solver::dr_unit, Solver::newton}) {
    State st = start;
    const SolveReport r = solve_with(s, m, st, settings);
    ASSERT_TRUE(r.converged) << solver_name(s) << ": " << r.message;
    ends.push_back(st.x);
  }
  // Within what the tolerance leaves: 1e-9 of the force scale moves a particle ~1e-9 spacings.
  for (const Points& x : ends) EXPECT_LT((x - ends[0]).cwiseAbs().maxCoeff(), 1e-8);
}

// FIRE carried on in slices (the viewer's frames) keeps the forces each slice ends with for the
// next: slices give the bits of one run, and a reset after the model changed forgets them.
TEST(SolverSwitch, FireInSlicesIsFireInOneRunAndAResetForgetsItsForces) {
  PulledSheet p = pulled_sheet();
  const Sheet& sheet = p.sheet;
  Model& m = p.sheet.model;
  const State& start = p.start;
  StaticOptions so;
  so.tolerance = 1e-14;  // no early stop
  so.force_scale = sheet.stiffness.stretch * sheet.grid.hx();
  State whole = start, sliced = start;
  StaticRelaxation one(m, whole.x, so), slices(m, sliced.x, so);
  (void)one.advance(m, whole, 300);
  for (int k = 0; k < 6; ++k) (void)slices.advance(m, sliced, 50);
  EXPECT_EQ(whole.x, sliced.x);
  // Gravity on: a reset relaxation goes as a new one from the same point.
  m.gravity = Vec3(0.0, 0.0, -9.81);
  State fresh = sliced;
  slices.reset(m, sliced.x);
  StaticRelaxation started(m, fresh.x, so);
  (void)slices.advance(m, sliced, 40);
  (void)started.advance(m, fresh, 40);
  EXPECT_EQ(sliced.x, fresh.x);
  EXPECT_LT(sliced.x.row(2).minCoeff(), 0.0);  // it sags
}

}  // namespace
}  // namespace membra
