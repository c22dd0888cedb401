#pragma once
// A cut on the continuum sheet after it has moved off its frame (docs/deformation.md, "Cuts
// after the sheet has moved"): drawn where the sheet lies now, seen from above, as the
// lattice's cuts are. Its line or hole is pulled back to the natural sheet (model/top_view.hpp),
// the sheet is meshed again with it as a boundary, and the run so far is carried over to the new
// mesh: every earlier step is applied at once, from the form the run had at its start carried
// over, and the sheet is left in the form it has now. The cut itself then acts on a mesh that
// follows it, as a cut on the frame does.
#include <vector>

#include "membra/geometry/triangulation.hpp"
#include "membra/process/prepare.hpp"
#include "membra/process/protocol.hpp"
#include "membra/process/scene.hpp"

namespace membra {

// A form of the sheet with the mesh it is on (meshes lose triangles to holes as a run goes).
struct SheetForm {
  Points reference;                 // natural-sheet points of the vertices
  std::vector<Triangle> triangles;  // the sheet's triangles then
  Points x;                         // the positions
};
SheetForm form_of(const Membrane& m);

// Whether `step` moves the sheet off its frame: a release, a growth, a curvature map or gravity.
// (Added springs that shorten move it on the frame too; a cut after them is still pulled back by
// the frame's stretch.)
bool moves_sheet(const ProtocolStep& step);

// Whether the sheet has left its frame before protocol step `index`.
bool moved_before(const Scene& scene, size_t index);

// Whether protocol step `index` of a continuum scene is a cut that must be pulled back and
// meshed: drawn after the sheet moved, and not pulled back yet.
bool cut_remeshes(const Scene& scene, size_t index);

// Whether any step of the scene is such a cut.
bool any_cut_remeshes(const Scene& scene);

// The cut pulled back through the sheet `m` as it lies: on_paper, its line and hole at the
// natural-sheet points times the frame's stretch, sampled at most `spacing` (m) apart, a hole's
// outlines traced to the chord `tolerance` (m). Throws InputError at the step's /line or /hole
// when it does not lie on the sheet.
ProtocolStep cut_on_paper(const Membrane& m, const ProtocolStep& step, double spacing,
                          double tolerance);

// The membrane of `scene` (whose protocol holds the pulled-back cut at `cut_index`) carried to
// the cut: each earlier step applied at once from its starting form (`forms[k]`, carried over
// by mesh_prolongation), then the sheet left in the form `now`. Throws InputError as
// prepare_scene does (a hole the mesher cannot follow).
PreparedScene remesh_for_cut(const Scene& scene, size_t cut_index,
                             const std::vector<SheetForm>& forms, const SheetForm& now);

}  // namespace membra
