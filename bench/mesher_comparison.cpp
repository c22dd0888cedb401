// CGAL's conforming mesher (membra's) against Gmsh's on the examples' continuum sheets: the same
// outlines and the same size field, each mesher's time, triangles and smallest angle
// (docs/model.md, "Why CGAL"). Built only where libgmsh-dev is installed (not in CI):
//   build/bench/membra_mesher_comparison examples/exp3_parallel.json ...
#include <gmsh.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>

#include "membra/io/scene.hpp"
#include "membra/process/prepare.hpp"

namespace {

using namespace membra;

struct Row {
  double seconds = 0.0, min_angle = 0.0, mean_edge = 0.0;
  size_t vertices = 0, triangles = 0;
};

void measure(const std::vector<Vec2>& v, const std::vector<std::array<int, 3>>& tris, Row& r) {
  const PlanarMesh m{v, tris};
  r.vertices = v.size(), r.triangles = tris.size(), r.min_angle = m.min_angle_deg();
  double sum = 0.0;
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k) sum += (v[t[k]] - v[t[(k + 1) % 3]]).norm();
  r.mean_edge = sum / (3.0 * tris.size());
}

// The outline as an OpenCASCADE surface, each feature polygon as a surface, fragmented so that
// the mesh conforms to every outline; the size from the same field as CGAL's.
Row gmsh_mesh(const ContinuumSpec& spec, const SizeField& size) {
  const auto start = std::chrono::steady_clock::now();
  gmsh::model::add("sheet");
  auto polygon = [](const std::vector<Vec2>& poly) {
    std::vector<int> points, lines;
    for (const Vec2& p : poly) points.push_back(gmsh::model::occ::addPoint(p.x(), p.y(), 0.0));
    for (size_t i = 0; i < points.size(); ++i)
      lines.push_back(gmsh::model::occ::addLine(points[i], points[(i + 1) % points.size()]));
    return gmsh::model::occ::addPlaneSurface({gmsh::model::occ::addCurveLoop(lines)});
  };
  const int sheet = polygon(sheet_outline(spec.width, spec.height, spec.disk, 2e-5));
  gmsh::vectorpair tools;
  for (const auto& f : spec.features) tools.push_back({2, polygon(f)});
  gmsh::vectorpair out;
  std::vector<gmsh::vectorpair> map;
  if (!tools.empty()) gmsh::model::occ::fragment({{2, sheet}}, tools, out, map);
  gmsh::model::occ::synchronize();
  gmsh::model::mesh::setSizeCallback(
      [&size](int, int, double x, double y, double) { return size(Vec2(x, y)); });
  gmsh::model::mesh::generate(2);
  std::vector<size_t> tags;
  std::vector<double> xyz, param;
  gmsh::model::mesh::getNodes(tags, xyz, param);
  std::map<size_t, int> index;
  std::vector<Vec2> v;
  for (size_t k = 0; k < tags.size(); ++k) {
    index[tags[k]] = static_cast<int>(v.size());
    v.emplace_back(xyz[3 * k], xyz[3 * k + 1]);
  }
  std::vector<size_t> elements, nodes;
  gmsh::model::mesh::getElementsByType(2, elements, nodes);
  std::vector<std::array<int, 3>> tris;
  for (size_t k = 0; k + 2 < nodes.size(); k += 3)
    tris.push_back({index[nodes[k]], index[nodes[k + 1]], index[nodes[k + 2]]});
  Row r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  measure(v, tris, r);
  gmsh::model::remove();
  return r;
}

Row cgal_mesh(const ContinuumSpec& spec) {
  const auto start = std::chrono::steady_clock::now();
  const SheetMeshing m = mesh_sheet(spec);
  Row r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  measure(m.mesh.vertices, m.mesh.triangles, r);
  return r;
}

void compare(const char* file) {
  try {
    const Scene scene = load_scene(file, {"model=continuum"});
    const ContinuumSpec spec = continuum_spec(scene);
    const Row c = cgal_mesh(spec);  // includes its size field
    const MeshSpec m = mesh_sheet(spec).spec;
    std::vector<Polyline2> boundaries(spec.features.begin(), spec.features.end());
    boundaries.push_back(sheet_outline(spec.width, spec.height, spec.disk, m.tolerance));
    const SizeField size(boundaries, Vec2::Zero(), Vec2(spec.width, spec.height),
                         {m.max_edge, m.elements_across, m.grading});
    const Row g = gmsh_mesh(spec, size);
    for (const auto& [name, r] : {std::pair{"cgal", c}, std::pair{"gmsh", g}})
      std::printf("%-26s %-6s %9.3f %9zu %9zu %8.1f %9.2f\n", scene.name.c_str(), name, r.seconds,
                  r.vertices, r.triangles, r.min_angle, r.mean_edge * 1e3);
  } catch (const std::string& e) {  // Gmsh throws its last error as a string
    std::printf("%s: gmsh: %s\n", file, e.c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  std::printf("%-26s %-6s %9s %9s %9s %8s\n", "scene", "mesher", "seconds", "vertices", "triangles",
              "min_deg");
  for (int a = 1; a < argc; ++a) compare(argv[a]);
  gmsh::finalize();
  return 0;
}
