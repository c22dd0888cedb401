#include "membra/model/continuum_slit.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <utility>

#include "membra/model/continuum_sheet.hpp"
#include "membra/model/segment_distance.hpp"

namespace membra {
namespace continuum_slit {
namespace {

using Edge = std::pair<int, int>;
constexpr double kOnLine = 1e-6;  // m: how close to the line a mesh vertex lies when on it

Edge edge_key(int a, int b) {
  return {std::min(a, b), std::max(a, b)};
}

// The mesh's inner edges on the line, on the frame: both ends and the midpoint within kOnLine
// (an edge along the outline or a hole's edge has nothing to open).
std::set<Edge> slit_edges(const Membrane& m, const std::vector<Vec2>& line) {
  const Points& ref = m.sheet.model.reference;
  const auto on = [&](const Vec2& paper) {
    return polyline_distance(paper.cwiseProduct(m.stretch), line) < kOnLine;
  };
  std::map<Edge, int> sides;
  for (const Triangle& t : m.sheet.triangles)
    for (int e = 0; e < 3; ++e) {
      const Vec2 a = ref.col(t[e]).head<2>(), b = ref.col(t[(e + 1) % 3]).head<2>();
      if (on(a) && on(b) && on(0.5 * (a + b))) ++sides[edge_key(t[e], t[(e + 1) % 3])];
    }
  std::set<Edge> out;
  for (const auto& [edge, n] : sides)
    if (n == 2) out.insert(edge);
  return out;
}

int root_of(std::vector<int>& parent, int i) {
  while (parent[static_cast<size_t>(i)] != i) i = parent[static_cast<size_t>(i)];
  return i;
}

// The triangles' corners after the split: around each particle its triangles fall into fans
// joined across the edges the slit leaves (all of them, off the slit); the first fan keeps the
// particle, each other one gets a new particle (numbered from `particles` on). So a particle
// where triangles meet only at a corner (a hole's edge that reached an earlier slit's tip) is
// split too, whatever the order of the cuts. copy_of lists the originals.
std::vector<Triangle> split_corners(const Sheet& sheet, const std::set<Edge>& slit,
                                    std::vector<int>& copy_of) {
  const int particles = sheet.model.num_particles();
  std::vector<std::vector<int>> around(static_cast<size_t>(particles));
  for (size_t t = 0; t < sheet.triangles.size(); ++t)
    for (int c = 0; c < 3; ++c)
      around[static_cast<size_t>(sheet.triangles[t][c])].push_back(static_cast<int>(t));
  std::vector<Triangle> corners = sheet.triangles;
  for (int p = 0; p < particles; ++p) {
    const std::vector<int>& fan = around[static_cast<size_t>(p)];
    std::vector<int> parent(fan.size());
    std::iota(parent.begin(), parent.end(), 0);
    for (size_t i = 0; i < fan.size(); ++i)
      for (size_t j = i + 1; j < fan.size(); ++j)
        for (int c = 0; c < 3; ++c) {
          const int w = sheet.triangles[static_cast<size_t>(fan[i])][c];
          const Triangle& other = sheet.triangles[static_cast<size_t>(fan[j])];
          if (w == p || (other.array() != w).all() || slit.contains(edge_key(p, w))) continue;
          parent[static_cast<size_t>(root_of(parent, static_cast<int>(i)))] =
              root_of(parent, static_cast<int>(j));
        }
    std::map<int, int> id_of_root;  // the first fan keeps p
    for (size_t i = 0; i < fan.size(); ++i) {
      const int root = root_of(parent, static_cast<int>(i));
      auto [it, fresh] = id_of_root.try_emplace(root, p);
      if (fresh && id_of_root.size() > 1) {
        it->second = particles + static_cast<int>(copy_of.size());
        copy_of.push_back(p);
      }
      Triangle& t = corners[static_cast<size_t>(fan[i])];
      for (int c = 0; c < 3; ++c)
        if (t[c] == p) t[c] = it->second;
    }
  }
  return corners;
}

// The copies appended to the model and the state, pinned, held and on the rim as their originals,
// and the sheet's triangles set to `corners` (its masses lumped from them).
void add_copies(Membrane& m, const std::vector<int>& copy_of, std::vector<Triangle> corners) {
  Model& model = m.sheet.model;
  const int n = model.num_particles(), added = static_cast<int>(copy_of.size());
  std::vector<bool> pinned(static_cast<size_t>(n + added));
  for (int p = 0; p < n + added; ++p)
    pinned[static_cast<size_t>(p)] = model.pinned(p < n ? p : copy_of[static_cast<size_t>(p - n)]);
  const auto grow = [&](Points& x) {
    x.conservativeResize(Eigen::NoChange, n + added);
    for (int k = 0; k < added; ++k) x.col(n + k) = x.col(copy_of[static_cast<size_t>(k)]);
  };
  grow(model.reference);
  grow(m.state.x);
  grow(m.state.v);
  m.sheet.triangles = std::move(corners);
  lump_masses(m.sheet);
  model.table.cover(model.mass);  // the new lips on the table too, if there is one
  model.self_contact.recover(m.sheet.triangles, model.reference);
  for (int p = 0; p < n + added; ++p)
    if (pinned[static_cast<size_t>(p)]) model.pin(p);
  const std::set<int> frame(m.frame.begin(), m.frame.end());
  SheetMesh& mesh = m.sheet.mesh;
  const std::vector<int> rim = mesh.rim;
  for (int k = 0; k < added; ++k) {
    const int original = copy_of[static_cast<size_t>(k)];
    if (frame.contains(original)) m.frame.push_back(n + k);
    for (size_t r = 0; r < rim.size(); ++r)
      if (rim[r] == original)
        mesh.rim.push_back(n + k), mesh.rim_normal.push_back(mesh.rim_normal[r]);
  }
  mesh.vertices = n + added;
}

}  // namespace
}  // namespace continuum_slit

namespace continuum_slit {
namespace {

// The sheet with its triangles' corners as split: the particles, the frame, the state, the
// membrane's and the shell's corners. Returns the number of particles added.
int apply_split(Membrane& m, const std::set<Edge>& slit) {
  std::vector<int> copy_of;
  std::vector<Triangle> corners = split_corners(m.sheet, slit, copy_of);
  if (copy_of.empty()) return 0;
  Model& model = m.sheet.model;
  if (model.membrane_triangles.size() != static_cast<int>(corners.size()) ||
      model.shell_triangles.size() != static_cast<int>(corners.size()))
    throw std::logic_error("continuum slit: the sheet's triangles and its element sets' differ");
  std::vector<std::array<int, 3>> ids;
  for (size_t t = 0; t < corners.size(); ++t) {
    const Triangle& was = m.sheet.triangles[t];
    const std::array<int, 3> same{was[0], was[1], was[2]};
    const auto& shell = model.shell_triangles.v[t];
    if (model.membrane_triangles.v[t] != same ||
        std::array<int, 3>{shell[0], shell[1], shell[2]} != same)
      throw std::logic_error("continuum slit: the sheet's triangles and its element sets' differ");
    ids.push_back({corners[t][0], corners[t][1], corners[t][2]});
  }
  add_copies(m, copy_of, std::move(corners));
  model.membrane_triangles.v = ids;
  model.shell_triangles.split_corners(ids);
  return static_cast<int>(copy_of.size());
}

}  // namespace
}  // namespace continuum_slit

int cut_continuum_slit(Membrane& m, const std::vector<Vec2>& line, std::vector<Vec2>* where) {
  using namespace continuum_slit;
  if (line.size() < 2) throw std::invalid_argument("a cut needs at least two points");
  const std::set<Edge> slit = slit_edges(m, line);
  if (slit.empty()) return 0;
  apply_split(m, slit);
  if (where)
    for (const auto& [a, b] : slit)
      where->push_back(0.5 *
                       (m.sheet.model.reference.col(a) + m.sheet.model.reference.col(b)).head<2>());
  return static_cast<int>(slit.size());
}

int separate_pinched_particles(Membrane& m) {
  return continuum_slit::apply_split(m, {});
}

}  // namespace membra
