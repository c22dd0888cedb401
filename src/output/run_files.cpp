#include "membra/output/run_files.hpp"

#include "membra/io/gltf.hpp"
#include "membra/io/mesh_svg.hpp"
#include "membra/io/obj.hpp"
#include "membra/io/ply.hpp"
#include "membra/io/stencil.hpp"
#include "membra/measure/colormap.hpp"
#include "membra/measure/stress.hpp"

namespace membra {

RunColors run_colors(const RunResult& r, const PictureOptions& opts) {
  RunColors c;
  for (double k : r.curvature.density) c.curvature.push_back(k * 1e-6);  // 1/m^2 to 1/mm^2
  for (double sv : r.vertex_stress) c.stress.push_back(sv * 1e-6);
  std::tie(c.k_lo, c.k_hi) = symmetric_percentile_range(c.curvature, kCurvaturePercentile, 1e-6);
  if (opts.curvature_range.size() == 2)
    c.k_lo = opts.curvature_range[0], c.k_hi = opts.curvature_range[1];
  std::tie(c.s_lo, c.s_hi) = symmetric_range(c.stress, 1e-3);
  if (opts.stress_range.size() == 2) c.s_lo = opts.stress_range[0], c.s_hi = opts.stress_range[1];
  return c;
}

std::vector<ColourScale> run_scales(const RunColors& c) {
  return {{"Gaussian curvature", "1/mm^2", c.k_lo, c.k_hi}, {"Stress", "MPa", c.s_lo, c.s_hi}};
}

void stage_run_files(const Scene& scene, const RunResult& r, const PictureOptions& opts,
                     OutputSet& out) {
  const auto& mesh = r.prepared.membrane.sheet;
  const auto& x = r.prepared.membrane.state.x;
  out.add("final.obj", [&](std::ostream& os) { write_obj(os, x, mesh.triangles); });
  const RunColors c = run_colors(r, opts);
  const std::vector<Rgb> k_colors = colorize(c.curvature, c.k_lo, c.k_hi);
  out.add("final.ply", [&](std::ostream& os) {
    write_ply(os, x, mesh.triangles, k_colors,
              {{"gaussian_curvature", c.curvature}, {"stress", c.stress}});
  });
  out.add("final.glb", [&](std::ostream& os) {
    GlbSheet g{x,
               mesh.triangles,
               k_colors,
               colorize(c.stress, c.s_lo, c.s_hi),
               c.curvature,
               c.stress,
               nlohmann::json::object()};
    g.extras["name"] = scene.name;
    g.extras["curvature_range"] = {c.k_lo, c.k_hi};  // 1/mm^2, the colours' ends
    g.extras["stress_range"] = {c.s_lo, c.s_hi};     // MPa
    write_glb(os, g);
  });
  // The continuum sheet's mesh on the natural sheet, its resin triangles filled.
  if (mesh.continuum()) {
    const MembraneTriangles& mt = mesh.model.membrane_triangles;
    std::vector<bool> resin(static_cast<size_t>(mt.size()));
    for (int i = 0; i < mt.size(); ++i)
      resin[static_cast<size_t>(i)] = mt.resin[static_cast<size_t>(i)].volume > 0.0;
    out.add("mesh.svg", [&](std::ostream& os) {
      write_mesh_svg(os, mesh.model.reference, mesh.triangles, resin, mesh.grid.width(),
                     mesh.grid.height());
    });
  }
  // Each stable form an exploration found (simulation.explore), as a mesh.
  for (size_t b = 0; b < r.branches.size(); ++b) {
    const auto& xb = r.branches[b].run.prepared.membrane.state.x;
    out.add("branches/" + std::to_string(b + 1) + "/final.obj", [&](std::ostream& os) {
      write_obj(os, xb, r.branches[b].run.prepared.membrane.sheet.triangles);
    });
  }
  // The stencil at true scale (outlines traced every 0.25 mm).
  // Coats on the bottom face go on a layer of their own.
  const PatternPtr top = scene_pattern(scene, false), bottom = scene_pattern(scene, true);
  if (top || bottom) {
    const Box2 frame = scene_frame(scene);
    const auto trace = [&](const PatternPtr& p) {
      return p ? trace_outlines(*p, frame, 0.25e-3) : std::vector<Polygon2>{};
    };
    const auto outlines = trace(top), underside = trace(bottom);
    out.add("pattern.svg", [&](std::ostream& os) { write_svg(os, outlines, frame, underside); });
    out.add("pattern.dxf", [&](std::ostream& os) { write_dxf(os, outlines, frame, underside); });
  }
}

}  // namespace membra
