#include "membra/geometry/conforming_mesh.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_criteria_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>

namespace membra {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Delaunay_mesh_vertex_base_2<Kernel>;
using FaceBase = CGAL::Delaunay_mesh_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;
using Point = Cdt::Point;

// CGAL's size-and-shape criteria with the size read off a field at each triangle's centroid:
// a triangle whose longest edge exceeds the local size is refined first (imperatively), then
// those whose smallest angle is below the bound.
class FieldCriteria : public CGAL::Delaunay_mesh_criteria_2<Cdt> {
 public:
  using Base = CGAL::Delaunay_mesh_criteria_2<Cdt>;
  using Size = std::function<double(const Vec2&)>;

  struct Quality : std::pair<double, double> {  // (squared minimum sine, size ratio)
    Quality() = default;
    Quality(double sine, double size) : std::pair<double, double>(sine, size) {}
    double sine() const { return first; }
    double size() const { return second; }
    bool operator<(const Quality& q) const {  // q1 < q2: q1 refined before q2
      if (size() > 1.0) return q.size() > 1.0 ? size() > q.size() : true;
      if (q.size() > 1.0) return false;
      return sine() < q.sine();
    }
  };

  class Is_bad : public Base::Is_bad {
   public:
    Is_bad(double bound, const Size* size) : Base::Is_bad(bound, Kernel()), size_(size) {}
    CGAL::Mesh_2::Face_badness operator()(const Quality& q) const {
      if (q.size() > 1.0) return CGAL::Mesh_2::IMPERATIVELY_BAD;
      return q.sine() < this->B ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
    }
    CGAL::Mesh_2::Face_badness operator()(const Cdt::Face_handle& f, Quality& q) const {
      const Point &a = f->vertex(0)->point(), &b = f->vertex(1)->point(),
                  &c = f->vertex(2)->point();
      std::array<double, 3> l2 = {CGAL::to_double(CGAL::squared_distance(b, c)),
                                  CGAL::to_double(CGAL::squared_distance(c, a)),
                                  CGAL::to_double(CGAL::squared_distance(a, b))};
      std::sort(l2.begin(), l2.end());
      const Vec2 centroid((a.x() + b.x() + c.x()) / 3.0, (a.y() + b.y() + c.y()) / 3.0);
      const double h = (*size_)(centroid);
      q.second = l2[2] / (h * h);
      if (q.size() > 1.0) {
        q.first = 1.0;
        return CGAL::Mesh_2::IMPERATIVELY_BAD;
      }
      const double area2 = 2.0 * CGAL::to_double(CGAL::area(a, b, c));
      q.first = area2 * area2 / (l2[2] * l2[1]);
      return q.sine() < this->B ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
    }

   private:
    const Size* size_;
  };

  FieldCriteria(double min_angle_deg, Size size)
      : Base(std::pow(std::sin(min_angle_deg * std::numbers::pi / 180.0), 2)),
        size_(std::move(size)) {}
  Is_bad is_bad_object() const { return Is_bad(this->bound(), &size_); }

 private:
  Size size_;
};

// The edge a-b as points a, ..., (not b) so that no piece is longer than the size at its middle:
// the mesher then rarely needs to split a boundary.
void split_edge(const Vec2& a, const Vec2& b, const std::function<double(const Vec2&)>& size,
                std::vector<Vec2>& out) {
  const double len = (b - a).norm(), h = size(0.5 * (a + b));
  const int n = std::max(1, static_cast<int>(std::ceil(len / h)));
  for (int k = 0; k < n; ++k) out.push_back(a + (static_cast<double>(k) / n) * (b - a));
}

// Which outline edge a point lies on (within eps), moving it exactly onto it; -1 for none.
int snap_to_outline(const std::vector<Vec2>& outline, double eps, Vec2& p) {
  for (size_t k = 0; k < outline.size(); ++k) {
    const Vec2 &a = outline[k], &b = outline[(k + 1) % outline.size()];
    const Vec2 e = b - a;
    const double t = std::clamp((p - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
    if ((p - (a + t * e)).norm() > eps) continue;
    p = t == 0.0 ? a : (t == 1.0 ? b : a + t * e);
    return static_cast<int>(k);
  }
  return -1;
}

// The vertices inserted so far by position, so that two constraints' points closer than eps
// become one vertex: two points a hair apart (a slit ending on a hole's edge, each drawn
// inexactly) would leave a sliver whose refinement never ends.
class VertexSnap {
 public:
  explicit VertexSnap(double eps) : eps_(eps) {}
  Cdt::Vertex_handle insert(Cdt& cdt, const Vec2& p) {
    const long i = std::lround(p.x() / eps_), j = std::lround(p.y() / eps_);
    for (long di = -1; di <= 1; ++di)
      for (long dj = -1; dj <= 1; ++dj) {
        const auto cell = cells_.find({i + di, j + dj});
        if (cell == cells_.end()) continue;
        for (const auto& [q, h] : cell->second)
          if ((q - p).norm() <= eps_) return h;
      }
    const Cdt::Vertex_handle h = cdt.insert(Point(p.x(), p.y()));
    cells_[{i, j}].push_back({p, h});
    return h;
  }

 private:
  double eps_;
  std::map<std::pair<long, long>, std::vector<std::pair<Vec2, Cdt::Vertex_handle>>> cells_;
};

void insert_chain(Cdt& cdt, VertexSnap& snap, const std::vector<Vec2>& points, bool closed) {
  std::vector<Cdt::Vertex_handle> handles;
  for (const Vec2& p : points) handles.push_back(snap.insert(cdt, p));
  const size_t edges = closed ? handles.size() : handles.size() - 1;
  for (size_t i = 0; i < edges; ++i) {
    const auto a = handles[i], b = handles[(i + 1) % handles.size()];
    if (a != b) cdt.insert_constraint(a, b);
  }
}

// The constraints: each feature polygon's vertices snapped onto the outline where they touch it
// (within eps) and its edges along the outline left out, so that no two constraints overlap; the
// outline then split at those vertices and to size between them, so no short edge is left
// where a feature meets the sheet's edge.
// The closed constraints with every open constraint's end that lies on one of their edges (within
// eps) made a vertex of it, so that the two share that point exactly (VertexSnap).
std::vector<std::vector<Vec2>> with_ends_on_edges(const MeshRequest& r, double eps) {
  std::vector<std::vector<Vec2>> polys = r.constraints;
  for (const std::vector<Vec2>& line : r.open_constraints) {
    if (line.size() < 2) continue;
    for (const Vec2& end : {line.front(), line.back()})
      for (std::vector<Vec2>& poly : polys)
        for (size_t k = 0; k < poly.size(); ++k) {
          const Vec2 a = poly[k], e = poly[(k + 1) % poly.size()] - a;
          const double t = (end - a).dot(e) / e.squaredNorm();
          if (t <= 0.0 || t >= 1.0 || (end - (a + t * e)).norm() > eps) continue;
          if ((end - a).norm() > eps && (end - (a + e)).norm() > eps)
            poly.insert(poly.begin() + static_cast<long>(k) + 1, end);
          break;
        }
  }
  return polys;
}

void insert_constraints(Cdt& cdt, const MeshRequest& r, double eps) {
  const std::vector<Vec2>& outline = r.outline;
  VertexSnap snap(eps);
  std::vector<std::vector<std::pair<double, Vec2>>> on_edge(outline.size());
  const auto insert = [&](std::vector<Vec2> poly, bool closed) {
    if (poly.size() < 2) return;
    std::vector<int> on(poly.size());
    for (size_t k = 0; k < poly.size(); ++k) {
      on[k] = snap_to_outline(outline, eps, poly[k]);
      if (on[k] >= 0)
        on_edge[static_cast<size_t>(on[k])].push_back(
            {(poly[k] - outline[static_cast<size_t>(on[k])]).norm(), poly[k]});
    }
    const size_t edges = closed ? poly.size() : poly.size() - 1;
    for (size_t i = 0; i < edges; ++i) {
      const size_t j = (i + 1) % poly.size();
      if (on[i] >= 0 && on[i] == on[j]) continue;  // along the outline
      std::vector<Vec2> piece;
      split_edge(poly[i], poly[j], r.size, piece);
      piece.push_back(poly[j]);
      insert_chain(cdt, snap, piece, false);
    }
  };
  for (const std::vector<Vec2>& poly : with_ends_on_edges(r, eps)) insert(poly, true);
  for (const std::vector<Vec2>& line : r.open_constraints) insert(line, false);
  std::vector<Vec2> rim;
  for (size_t k = 0; k < outline.size(); ++k) {
    auto& stops = on_edge[k];
    std::sort(stops.begin(), stops.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    Vec2 from = outline[k];
    for (const auto& [t, p] : stops) {
      if ((p - from).norm() <= eps) continue;
      split_edge(from, p, r.size, rim);
      from = p;
    }
    split_edge(from, outline[(k + 1) % outline.size()], r.size, rim);
  }
  insert_chain(cdt, snap, rim, true);
}

bool inside(const std::vector<Vec2>& poly, const Vec2& p) {
  bool in = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 &a = poly[i], &b = poly[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

PlanarMesh extract(const Cdt& cdt, const std::vector<Vec2>& outline) {
  PlanarMesh mesh;
  std::map<Cdt::Vertex_handle, int> index;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const Point &a = f->vertex(0)->point(), &b = f->vertex(1)->point(), &c = f->vertex(2)->point();
    const Vec2 centroid((a.x() + b.x() + c.x()) / 3.0, (a.y() + b.y() + c.y()) / 3.0);
    // Both tests: CGAL's own marking drops the slivers left between a curved outline's chord and
    // the two halves it was split into (the split point, an inexact construction, lies a hair
    // inside the chord), whose centroids the polygon test counts as inside; the polygon test
    // drops what a feature reaching past the outline encloses, which CGAL counts as inside.
    if (!f->is_in_domain() || !inside(outline, centroid)) continue;
    std::array<int, 3> t;
    for (int k = 0; k < 3; ++k) {
      const auto [it, fresh] = index.try_emplace(f->vertex(k), static_cast<int>(index.size()));
      if (fresh) mesh.vertices.emplace_back(f->vertex(k)->point().x(), f->vertex(k)->point().y());
      t[static_cast<size_t>(k)] = it->second;
    }
    mesh.triangles.push_back(t);  // CGAL's faces are counter-clockwise
  }
  return mesh;
}

}  // namespace

PlanarMesh conforming_mesh(const MeshRequest& request) {
  if (request.outline.size() < 3) throw std::invalid_argument("mesh: outline of < 3 points");
  Cdt cdt;
  double extent = 0.0;
  for (const Vec2& p : request.outline) extent = std::max(extent, p.cwiseAbs().maxCoeff());
  insert_constraints(cdt, request, 1e-7 * extent);
  CGAL::Delaunay_mesher_2<Cdt, FieldCriteria> mesher(
      cdt, FieldCriteria(request.min_angle_deg, request.size));
  mesher.init();
  while (!mesher.is_refinement_done()) {
    mesher.step_by_step_refine_mesh();
    if (static_cast<long>(cdt.number_of_vertices()) > request.max_vertices)
      throw std::runtime_error("more than " + std::to_string(request.max_vertices) +
                               " vertices; raise max_edge or lower elements_across");
  }
  return extract(cdt, request.outline);
}

double PlanarMesh::min_angle_deg() const {
  double lo = 180.0;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec2 &p = vertices[t[k]], &a = vertices[t[(k + 1) % 3]], &b = vertices[t[(k + 2) % 3]];
      const Vec2 u = a - p, v = b - p;
      lo = std::min(lo, std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v)));
    }
  return lo * 180.0 / std::numbers::pi;
}

double PlanarMesh::min_edge() const {
  double lo = std::numeric_limits<double>::infinity();
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k)
      lo = std::min(lo, (vertices[t[k]] - vertices[t[(k + 1) % 3]]).norm());
  return lo;
}

double PlanarMesh::max_edge() const {
  double hi = 0.0;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k)
      hi = std::max(hi, (vertices[t[k]] - vertices[t[(k + 1) % 3]]).norm());
  return hi;
}

}  // namespace membra
