#pragma once
// The continuum sheet (docs/model.md, "The continuum shell"): a triangle mesh of the natural
// sheet whose edges follow the outline and every resin boundary, with membrane triangles of the
// latex's law and shell triangles for its bending.
#include <string>
#include <vector>

#include "membra/geometry/conforming_mesh.hpp"
#include "membra/model/pattern_outline.hpp"
#include "membra/model/sheet.hpp"

namespace membra {

struct ContinuumSpec {
  double width = 0.2, height = 0.2;  // m, the natural sheet
  bool disk = false;                 // the ellipse inscribed in the rectangle
  // Boundaries the mesh must follow, on the natural sheet (m): resin outlines pulled back from
  // the frame they were drawn on.
  std::vector<Polygon2> features;
  // Open polylines the mesh must follow too: slits a cut will open (continuum_slit.hpp). The
  // elements along one are at most its length / (2 elements_across), growing away at the
  // grading rate.
  std::vector<Polyline2> slits;
  MeshSpec mesh;
  Material material = latex();
};

// The elements' largest edge when the scene gives none: a twentieth of the sheet's smaller side.
double default_max_edge(double width, double height);

// The mesh a spec asks for, with the size field it was made to. Throws std::invalid_argument
// naming the mesh setting at fault: a non-positive size, a feature narrower than the mesher can
// resolve, a mesh too large for memory.
struct SheetMeshing {
  PlanarMesh mesh;
  MeshSpec spec;  // max_edge resolved
  NarrowestFeature narrowest;
};
SheetMeshing mesh_sheet(const ContinuumSpec& spec);

// Builds the sheet on that mesh: masses lumped a third of each triangle's to its corners,
// membrane triangles of the material's law at rest on the natural sheet, shell hinges with the
// latex's plate stiffness (nu 1/2 for the incompressible laws), no pins, no gravity.
Sheet build_continuum_sheet(const ContinuumSpec& spec);

// The masses lumped a third of each of the sheet's triangles (at rest on the natural sheet) to its
// corners, every particle free.
void lump_masses(Sheet& sheet);

// "10633 vertices, 20880 triangles, smallest angle 25.1 deg, edges 0.41-10 mm": the mesh in a line.
std::string mesh_line(const SheetMesh& mesh);

// The outline of the natural sheet, counter-clockwise: the rectangle, or the inscribed ellipse
// sampled so its chords stray less than `tolerance`.
Polygon2 sheet_outline(double width, double height, bool disk, double tolerance);

}  // namespace membra
