#include "membra/model/continuum_sheet.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>

#include "membra/core/units.hpp"
#include "membra/model/segment_distance.hpp"

namespace membra {
namespace {

// Triangles a mesh may have before we refuse it: about 1 GB of model and factorization.
constexpr double kMaxTriangles = 2e6;

std::string mm(double metres) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", metres / units::mm);
  return buf;
}

}  // namespace

double default_max_edge(double width, double height) {
  return std::min(width, height) / 20.0;
}

namespace {

MeshSpec resolved(const ContinuumSpec& s) {
  if (!(s.width > 0.0) || !(s.height > 0.0))
    throw std::invalid_argument("sheet: size must be positive");
  MeshSpec m = s.mesh;
  if (m.max_edge == 0.0) m.max_edge = default_max_edge(s.width, s.height);
  if (!(m.max_edge > 0.0)) throw std::invalid_argument("sheet.mesh.max_edge: must be positive");
  if (m.elements_across < 1)
    throw std::invalid_argument("sheet.mesh.elements_across: must be at least 1");
  if (!(m.min_angle_deg > 0.0) || m.min_angle_deg > 33.0)
    throw std::invalid_argument("sheet.mesh.min_angle: must be in (0, 33] degrees");
  if (!(m.grading > 0.0)) throw std::invalid_argument("sheet.mesh.grading: must be positive");
  if (!(m.tolerance > 0.0)) throw std::invalid_argument("sheet.mesh.tolerance: must be positive");
  return m;
}

// The rim: the particles on edges that only one triangle has, with the outward normal.
void find_rim(const std::vector<Triangle>& tris, const Points& x, SheetMesh& mesh) {
  const std::map<std::pair<int, int>, int> count = edge_counts(tris);
  std::map<int, Vec2> normal;
  for (const Triangle& t : tris)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (count.at(std::minmax(a, b)) != 1) continue;
      const Vec2 e = x.col(b).head<2>() - x.col(a).head<2>();
      const Vec2 out(e.y(), -e.x());  // counter-clockwise triangles: the outside is on the right
      normal.try_emplace(a, Vec2::Zero()).first->second += out;
      normal.try_emplace(b, Vec2::Zero()).first->second += out;
    }
  for (const auto& [p, n] : normal) {
    mesh.rim.push_back(p);
    mesh.rim_normal.push_back(n.normalized());
  }
}

}  // namespace

std::string mesh_line(const SheetMesh& m) {
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "%d vertices, %d triangles, smallest angle %.1f deg, edges %.2f-%.3g mm "
                "(narrowest feature %.3g mm)",
                m.vertices, m.triangles, m.min_angle_deg, m.min_edge / units::mm,
                m.spec.max_edge / units::mm, m.narrowest.width / units::mm);
  return buf;
}

Polygon2 sheet_outline(double width, double height, bool disk, double tolerance) {
  if (!disk) return {{0.0, 0.0}, {width, 0.0}, {width, height}, {0.0, height}};
  const double a = 0.5 * width, b = 0.5 * height, r = std::max(a, b);
  const double step = 2.0 * std::acos(std::max(-1.0, 1.0 - tolerance / r));
  const int n = std::max(16, static_cast<int>(std::ceil(2.0 * std::numbers::pi / step)));
  Polygon2 out;
  for (int k = 0; k < n; ++k) {
    const double t = 2.0 * std::numbers::pi * k / n;
    out.emplace_back(a + a * std::cos(t), b + b * std::sin(t));
  }
  return out;
}

namespace {

[[noreturn]] void too_many_triangles(double count) {
  throw std::invalid_argument("sheet.mesh: about " + std::to_string(static_cast<long>(count)) +
                              " triangles, more than membra meshes (2 million); raise max_edge "
                              "or lower elements_across");
}

// The size the slits ask for at p: each slit's length / (2 elements_across) along it, growing
// at the grading rate away from it (infinity without slits).
double slit_size(const ContinuumSpec& s, const MeshSpec& m, const Vec2& p) {
  double h = std::numeric_limits<double>::infinity();
  for (const Polyline2& line : s.slits) {
    double length = 0.0;
    for (size_t k = 0; k + 1 < line.size(); ++k) length += (line[k + 1] - line[k]).norm();
    h = std::min(h, length / (2.0 * m.elements_across) + m.grading * polyline_distance(p, line));
  }
  return h;
}

}  // namespace

SheetMeshing mesh_sheet(const ContinuumSpec& s) {
  SheetMeshing out;
  out.spec = resolved(s);
  const MeshSpec& m = out.spec;
  // Elements no larger than max_edge: at least this many, known before the size field is built
  // (which for a max_edge far too small would itself take long).
  const double at_least = s.width * s.height / (std::sqrt(3.0) / 4.0 * m.max_edge * m.max_edge);
  if (at_least > kMaxTriangles) too_many_triangles(at_least);
  const Polygon2 outline = sheet_outline(s.width, s.height, s.disk, m.tolerance);
  std::vector<Polyline2> boundaries(s.features.begin(), s.features.end());
  boundaries.push_back(outline);
  const SizeField size(boundaries, Vec2::Zero(), Vec2(s.width, s.height),
                       {m.max_edge, m.elements_across, m.grading});
  out.narrowest = size.narrowest();
  const double finest = out.narrowest.width / m.elements_across;
  if (out.narrowest.width > 0.0 && finest < 10.0 * m.tolerance)
    throw std::invalid_argument(
        "sheet.mesh: a resin piece or gap only " + mm(out.narrowest.width) + " mm wide at (" +
        mm(out.narrowest.at.x()) + ", " + mm(out.narrowest.at.y()) +
        ") mm on the natural sheet is narrower than the mesher resolves (elements of " +
        mm(finest) + " mm, below 10 x the chord tolerance); widen it or lower elements_across");
  if (size.expected_triangles() > kMaxTriangles) too_many_triangles(size.expected_triangles());
  MeshRequest request;
  request.outline = outline;
  request.constraints = s.features;
  request.open_constraints = s.slits;
  request.size = [&size, &s, &m](const Vec2& p) { return std::min(size(p), slit_size(s, m, p)); };
  request.min_angle_deg = m.min_angle_deg;
  request.max_vertices = static_cast<long>(kMaxTriangles / 2);  // about two triangles a vertex
  out.mesh = conforming_mesh(request);
  return out;
}

void lump_masses(Sheet& sheet) {
  Model& m = sheet.model;
  const double per_area = sheet.material.thickness * sheet.material.density / 3.0;
  m.mass.assign(static_cast<size_t>(m.reference.cols()), 0.0);
  for (const Triangle& t : sheet.triangles) {
    const Vec3 &a = m.reference.col(t[0]), &b = m.reference.col(t[1]), &c = m.reference.col(t[2]);
    const double area = 0.5 * (b - a).cross(c - a).norm();
    for (int k : t) m.mass[static_cast<size_t>(k)] += area * per_area;
  }
  m.inv_mass.resize(m.mass.size());
  for (size_t p = 0; p < m.mass.size(); ++p) m.inv_mass[p] = 1.0 / m.mass[p];
}

Sheet build_continuum_sheet(const ContinuumSpec& s) {
  const Material& mat = s.material;
  if (!(mat.youngs_modulus > 0.0) || !(mat.thickness > 0.0) || !(mat.density > 0.0))
    throw std::invalid_argument("sheet.material: E, thickness and density must be positive");
  const SheetMeshing meshing = mesh_sheet(s);
  const PlanarMesh& pm = meshing.mesh;
  Sheet sheet;
  // A grid of the sheet's size without particles: the sheet's width and height for everyone
  // who reads them off the grid.
  sheet.grid = GridSheet(GridSpec{s.width, s.height, 2, 2}, std::vector<bool>(4, false));
  sheet.material = mat;
  sheet.options.material = mat;
  sheet.stiffness = homogenize(mat);  // the force scale of the convergence test
  Model& m = sheet.model;
  const int n = static_cast<int>(pm.vertices.size());
  m.reference = Points::Zero(3, n);
  for (int p = 0; p < n; ++p) m.reference.col(p).head<2>() = pm.vertices[static_cast<size_t>(p)];
  LawConstants law = law_constants(mat.law, mat.youngs_modulus);
  law.relaxed = mat.wrinkling == Wrinkling::relaxed;
  if (law.relaxed && !relaxable(mat.law))
    throw std::invalid_argument("a relaxed membrane needs an incompressible law, not " +
                                std::string(to_string(mat.law)));
  double edges = 0.0;
  for (const auto& t : pm.triangles) {
    const Vec3 &a = m.reference.col(t[0]), &b = m.reference.col(t[1]), &c = m.reference.col(t[2]);
    m.membrane_triangles.add(t, a, b, c, law, mat.thickness);
    sheet.triangles.emplace_back(t[0], t[1], t[2]);
    edges += (b - a).norm() + (c - b).norm() + (a - c).norm();
  }
  lump_masses(sheet);
  const double nu = relaxable(mat.law) ? 0.5 : 1.0 / 3.0, t = mat.thickness;
  const double d = mat.youngs_modulus * t * t * t / (12.0 * (1.0 - nu * nu));
  m.shell_triangles.add_mesh(pm.triangles, m.reference, d, nu);
  SheetMesh& mesh = sheet.mesh;
  mesh.spec = meshing.spec;
  mesh.vertices = n;
  mesh.triangles = static_cast<int>(pm.triangles.size());
  mesh.min_angle_deg = pm.min_angle_deg();
  mesh.min_edge = pm.min_edge();
  mesh.mean_edge = edges / (3.0 * mesh.triangles);
  mesh.narrowest = meshing.narrowest;
  find_rim(sheet.triangles, m.reference, mesh);
  return sheet;
}

}  // namespace membra
