#pragma once
// The files of a finished run, staged in an OutputSet: the meshes and the stencil (the pictures
// are render/run_pictures.hpp's). They write what run_staging.hpp computed.
#include "membra/output/output_set.hpp"
#include "membra/output/run_staging.hpp"
#include "membra/process/run.hpp"

namespace membra {

// Stages final.obj, final.ply (curvature colours, curvature and stress properties), final.glb
// (both colourings and both values, io/gltf.hpp), the continuum's mesh.svg, each
// explored branch's branches/N/final.obj and, when the scene has resin, the stencil pattern.svg
// and pattern.dxf, in `out` (not committed).
void stage_run_files(const Scene& scene, const RunResult& r, const RunStaging& s, OutputSet& out);

}  // namespace membra
