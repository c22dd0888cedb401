#pragma once
// Draws meshes, lines, points, text and colour-bar legends with OpenGL 3.3 core into whatever
// context is current: the headless Renderer (EGL) and the viewer's window (GLFW) share it.
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "membra/core/vec.hpp"
#include "membra/geometry/triangulation.hpp"
#include "membra/measure/colormap.hpp"

namespace membra {

// A colour bar: the map's range and what it shows.
struct Legend {
  std::string title;  // e.g. "Gaussian curvature"
  std::string unit;   // e.g. "1/mm^2"
  double lo = 0.0, hi = 1.0;
};

class GlPainter {
 public:
  // Compiles the shaders; an OpenGL 3.3 core context must be current (throws RenderError).
  GlPainter();
  ~GlPainter();
  GlPainter(const GlPainter&) = delete;
  GlPainter& operator=(const GlPainter&) = delete;

  // Lit, smooth-shaded triangles with per-vertex colours; `view_projection` maps world to clip
  // space and `rotation` (rows right, up, back) turns normals towards the viewer.
  void mesh(const Points& x, const std::vector<Triangle>& triangles, const std::vector<Rgb>& colors,
            const Eigen::Matrix4f& view_projection, const Eigen::Matrix3f& rotation);
  // Unlit line segments: endpoints in pairs.
  void lines(const std::vector<Vec3>& endpoints, const Rgb& color,
             const Eigen::Matrix4f& view_projection);
  // Unlit points of `size` pixels.
  void points(const std::vector<Vec3>& points, const Rgb& color, float size,
              const Eigen::Matrix4f& view_projection);
  // Unlit filled triangles given in pixels of a width x height viewport (origin top-left).
  void pixel_triangles(const std::vector<Vec3>& corners, const std::vector<Rgb>& colors, int width,
                       int height);
  // Text in pixels (origin top-left, `scale` x stb_easy_font's 7-pixel glyphs).
  void text(const std::string& str, float x, float y, float scale, const Rgb& color, int width,
            int height);
  // The colour bar with five labelled ticks, title and unit, in the right sixth of the viewport.
  void legend(const Legend& legend, int width, int height);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace membra
