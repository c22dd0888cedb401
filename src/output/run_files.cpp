#include "membra/output/run_files.hpp"

#include "membra/io/gltf.hpp"
#include "membra/io/mesh_svg.hpp"
#include "membra/io/obj.hpp"
#include "membra/io/ply.hpp"
#include "membra/io/stencil.hpp"
#include "membra/model/triangle_resin.hpp"

namespace membra {

void stage_run_files(const Scene& scene, const RunResult& r, const RunStaging& s, OutputSet& out) {
  const auto& mesh = r.prepared.membrane.sheet;
  const auto& x = r.prepared.membrane.state.x;
  const RunColors& c = s.colors;
  const std::vector<bool> resin = triangle_resin(mesh);
  const std::vector<Vec2> uv = flat_uv(mesh.model.reference);
  out.add("final.obj", [&](std::ostream& os) {
    write_obj(os, x, mesh.triangles, ObjLayers{uv, resin, "final.mtl"});
  });
  out.add("final.mtl", [&](std::ostream& os) { write_mtl(os); });
  out.add("final.ply", [&](std::ostream& os) {
    write_ply(os, x, mesh.triangles, s.curvature_rgb,
              {{"gaussian_curvature", c.curvature}, {"stress", c.stress}});
  });
  out.add("final.glb", [&](std::ostream& os) {
    GlbSheet g{x,  mesh.triangles, s.curvature_rgb, s.stress_rgb, c.curvature, c.stress, {},
               uv, resin};
    g.extras["name"] = scene.name;
    g.extras["curvature_range"] = {c.k_lo, c.k_hi};  // 1/m^2, the colours' ends
    g.extras["stress_range"] = {c.s_lo, c.s_hi};     // MPa
    write_glb(os, g);
  });
  // The continuum sheet's mesh on the natural sheet, its resin triangles filled.
  if (mesh.continuum()) {
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
  // The stencil at true scale, the bottom face's coats on a layer of their own.
  if (s.top || s.bottom) {
    out.add("pattern.svg",
            [&](std::ostream& os) { write_svg(os, s.outlines, s.frame, s.underside); });
    out.add("pattern.dxf",
            [&](std::ostream& os) { write_dxf(os, s.outlines, s.frame, s.underside); });
  }
}

}  // namespace membra
