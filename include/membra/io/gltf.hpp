#pragma once
// Binary glTF 2.0 (.glb) of a coloured sheet, for Blender, three.js and any other glTF viewer:
// positions in metres (glTF's unit) with glTF's y up, smooth normals, the flat sheet as
// TEXCOORD_0, the curvature colours as COLOR_0 (shown by default), the stress colours as COLOR_1,
// the values themselves as the custom attributes _CURVATURE (1/m^2) and _STRESS (MPa), and the
// triangles split into two primitives by material, "latex" and "resin" (docs/outputs.md).
// Written and read with tinygltf (Debian's libtinygltf-dev).
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "membra/core/vec.hpp"
#include "membra/geometry/triangulation.hpp"
#include "membra/measure/colormap.hpp"

namespace membra {

struct GlbSheet {
  Points x;  // m (written in mm)
  std::vector<Triangle> triangles;
  std::vector<Rgb> curvature_colors, stress_colors;  // sRGB, as in the pictures
  std::vector<double> curvature, stress;             // 1/m^2, MPa
  nlohmann::json extras;    // merged into the asset's extras (names, colour ranges)
  std::vector<Vec2> uv;     // per vertex, the flat sheet (flat_uv); empty: no TEXCOORD_0
  std::vector<bool> resin;  // per triangle; empty: all latex
};

// Writes the sheet as .glb (colours converted to glTF's linear space; v of the texture
// coordinates flipped, glTF counting from the top). Throws InputError when the arrays' sizes
// disagree.
void write_glb(std::ostream& out, const GlbSheet& sheet);

// Reads a .glb written by write_glb back (positions in m, colours converted back to sRGB, the
// latex triangles first, then the resin's);
// throws InputError naming the file when it cannot be parsed or lacks an attribute.
GlbSheet read_glb(const std::filesystem::path& file);

// sRGB to linear (glTF's vertex colours) and back, per channel in [0, 1].
float srgb_to_linear(float c);
float linear_to_srgb(float c);

}  // namespace membra
