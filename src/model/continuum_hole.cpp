#include "membra/model/continuum_hole.hpp"

#include <algorithm>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "membra/model/continuum_sheet.hpp"
#include "membra/model/continuum_slit.hpp"

namespace membra {
namespace continuum_hole {
namespace {

// Which triangles stay: those whose centroid lies outside the hole on the frame, at its paper
// position times the frame's stretch. That is where the mesh put the hole's outline, whatever
// an earlier hole has since moved.
std::vector<bool> triangles_kept(const Membrane& m, const Pattern& hole) {
  const Points& x = m.sheet.model.reference;
  std::vector<bool> keep;
  for (const Triangle& t : m.sheet.triangles) {
    const Vec3 centroid = (x.col(t[0]) + x.col(t[1]) + x.col(t[2])) / 3.0;
    keep.push_back(!hole.contains(centroid.head<2>().cwiseProduct(m.stretch)));
  }
  return keep;
}

// Which added springs stay: those whose middle lies outside the hole on the frame (as for the
// triangles). A spring along an edge the hole took can keep both its particles, on the hole's
// rim, and would tie them across it.
std::vector<bool> springs_kept(const Membrane& m, const Pattern& hole) {
  const Model& model = m.sheet.model;
  std::vector<bool> keep;
  for (int s = 0; s < model.added_springs.size(); ++s) {
    const auto [a, b] = model.added_springs.ids(s);
    const Vec3 middle = 0.5 * (model.reference.col(a) + model.reference.col(b));
    keep.push_back(!hole.contains(middle.head<2>().cwiseProduct(m.stretch)));
  }
  return keep;
}

// The sheet's particles, triangles and element sets without what the hole removed. The
// continuum's triangle sets hold one element per triangle of the sheet, in its order, and lose
// the hole's triangles (a triangle inside it may keep all three corners, on its edge); added
// springs lose those across the hole (keep_springs); every set is then carried over by its
// particles, losing the elements of the particles the hole took (the table covers the new sheet
// after).
Sheet sheet_without(const Sheet& old, const std::vector<bool>& keep_tri,
                    const std::vector<bool>& keep_springs, std::vector<int>& new_of_old) {
  Model filtered = old.model;
  filtered.added_springs.filter(keep_springs);
  filtered.for_each_set([&](auto& set) {
    using Set = std::decay_t<decltype(set)>;
    if constexpr (std::is_same_v<Set, MembraneTriangles> || std::is_same_v<Set, ShellTriangles>) {
      if (set.size() == 0) return;
      if (set.size() != static_cast<int>(keep_tri.size()))
        throw std::logic_error("continuum hole: a triangle set that is not one per triangle");
      set.filter(keep_tri);
    }
  });
  new_of_old.assign(static_cast<size_t>(old.model.num_particles()), -1);
  Sheet n;  // everything but the particles, triangles and elements as before
  n.grid = old.grid;
  n.material = old.material;
  n.stiffness = old.stiffness;
  n.options = old.options;
  n.mesh = old.mesh;
  int next = 0;
  for (size_t k = 0; k < old.triangles.size(); ++k) {
    if (!keep_tri[k]) continue;
    Triangle t = old.triangles[k];
    for (int c = 0; c < 3; ++c) {
      int& id = new_of_old[static_cast<size_t>(t[c])];
      if (id < 0) id = next++;
      t[c] = id;
    }
    n.triangles.push_back(t);
  }
  Model& nm = n.model;
  nm.reference = Points::Zero(3, next);
  for (size_t p = 0; p < new_of_old.size(); ++p)
    if (new_of_old[p] >= 0)
      nm.reference.col(new_of_old[p]) = old.model.reference.col(static_cast<int>(p));
  const Rebuild rebuild{old, n, new_of_old};
  nm.for_each_set_with(filtered, [&](auto& set, const auto& from) { set.carry(from, rebuild); });
  lump_masses(n);
  nm.table.cover(nm.mass);  // the table, if any, takes the new masses
  return n;
}

// The mesh's record after the hole: its counts now (report.json's "mesh" counts what runs), and
// the rim the frame holds renumbered.
void update_mesh_record(const Sheet& sheet, const std::vector<int>& new_of_old, SheetMesh& mesh) {
  mesh.vertices = sheet.model.num_particles();
  mesh.triangles = static_cast<int>(sheet.triangles.size());
  std::vector<int> rim;
  std::vector<Vec2> normal;
  for (size_t k = 0; k < mesh.rim.size(); ++k) {
    const int p = new_of_old[static_cast<size_t>(mesh.rim[k])];
    if (p < 0) continue;
    rim.push_back(p);
    normal.push_back(mesh.rim_normal[k]);
  }
  mesh.rim = std::move(rim);
  mesh.rim_normal = std::move(normal);
}

}  // namespace
}  // namespace continuum_hole

using continuum_hole::sheet_without;
using continuum_hole::springs_kept;
using continuum_hole::triangles_kept;
using continuum_hole::update_mesh_record;

int punch_continuum_hole(Membrane& m, const Pattern& hole, std::vector<Vec2>* where) {
  const std::vector<bool> keep_tri = triangles_kept(m, hole);
  if (std::none_of(keep_tri.begin(), keep_tri.end(), [](bool k) { return k; }))
    throw std::invalid_argument("the hole removes the whole sheet");
  if (std::all_of(keep_tri.begin(), keep_tri.end(), [](bool k) { return k; })) return 0;
  std::vector<int> new_of_old;
  Sheet rest = sheet_without(m.sheet, keep_tri, springs_kept(m, hole), new_of_old);
  if (rest.model.num_particles() == m.sheet.model.num_particles())
    throw std::invalid_argument(
        "the hole is smaller than the mesh's elements there: it would take triangles but no "
        "particle (enlarge it, or raise sheet.mesh.elements_across)");
  Membrane n = make_membrane(std::move(rest));
  update_mesh_record(n.sheet, new_of_old, n.sheet.mesh);
  carry_process_state(m, new_of_old, n);
  update_elements(n);
  int removed = 0;
  for (size_t p = 0; p < new_of_old.size(); ++p) {
    if (new_of_old[p] >= 0) continue;
    ++removed;
    if (where) where->push_back(m.sheet.model.reference.col(static_cast<int>(p)).head<2>());
  }
  m = std::move(n);
  separate_pinched_particles(m);  // where the hole's edge reached an earlier slit's tip
  return removed;
}

}  // namespace membra
