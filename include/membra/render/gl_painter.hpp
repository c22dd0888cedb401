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
  std::string unit;   // the unit of lo and hi, e.g. "1/m^2"; shown in a readable one
  double lo = 0.0, hi = 1.0;
  ColourMap map = ColourMap::diverging;
};

// Where a form passes through itself, in the pictures and the viewer: a colour that no colour
// map, spring family or frame uses.
inline const Rgb kCrossingColour{1.0f, 0.0f, 1.0f};

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
  // Unlit line segments: endpoints in pairs, `width` image pixels wide (wider than 1 only in a
  // context that is not forward-compatible, as the renderer's; the viewer's lines stay 1 pixel).
  void lines(const std::vector<Vec3>& endpoints, const Rgb& color,
             const Eigen::Matrix4f& view_projection, float width = 1.0f);
  // The edges of the triangles `which` (indices into `triangles`; others are skipped), unlit.
  void outline(const Points& x, const std::vector<Triangle>& triangles,
               const std::vector<int>& which, const Rgb& color,
               const Eigen::Matrix4f& view_projection, float width = 1.0f);
  // Unlit points of `size` pixels.
  void points(const std::vector<Vec3>& points, const Rgb& color, float size,
              const Eigen::Matrix4f& view_projection);
  // Unlit filled triangles given in pixels of a width x height viewport (origin top-left).
  void pixel_triangles(const std::vector<Vec3>& corners, const std::vector<Rgb>& colors, int width,
                       int height);
  // The form's soft shadow on the plane z = ground_z below it, lit from straight above, with a
  // penumbra of radius `blur` (world units). Drawn before the form, with the depth test off;
  // the framebuffer, viewport, clear colour and scissor are as they were after it, the bound
  // program, vertex array and texture of unit 0 are its own.
  void shadow(const Points& x, const std::vector<Triangle>& triangles, double ground_z, double blur,
              const Eigen::Matrix4f& view_projection);
  // A line of antialiased text (font.hpp), its box's top-left corner at pixel (x, y) of a width
  // x height viewport (origin top-left), `pixel_height` pixels high.
  void text(const std::string& str, float x, float y, float pixel_height, const Rgb& color,
            int width, int height);
  // The title at the top-left, shrunk when it would not fit the width.
  void heading(const std::string& title, int width, int height);
  // The colour bar with five ticks labelled in readable units (core/readable_units.hpp) and the
  // unit above it, in the right fifth of the viewport below the heading band; the labels shrink
  // rather than leave the viewport.
  void legend(const Legend& legend, int width, int height);
  // A scale bar at the bottom-left: a round length (1, 2 or 5 times a power of ten, in mm) about
  // a fifth of the viewport wide, for a view that shows `pixels_per_metre` (orthographic views
  // only: a perspective or a slanted view has no one scale).
  void scale_bar(double pixels_per_metre, int width, int height);
  // The pictures' text height for a viewport `height` pixels high (1/34 of it, at least 9 and at
  // most 64 image pixels), and the band the heading takes.
  float text_size(int height) const;
  float heading_band(int height) const;
  // Framebuffer pixels per image pixel (the renderer's supersampling), so that the bounds on
  // the text's size hold in the image.
  void set_pixel_scale(float scale) { pixel_scale_ = scale; }

 private:
  // The bar's 64 colour steps from lo (bottom) to hi (top), in pixels.
  void colour_bar(const Legend& legend, float x0, float x1, float top, float bottom, int width,
                  int height);

  struct Impl;
  std::unique_ptr<Impl> impl_;
  float pixel_scale_ = 1.0f;
};

}  // namespace membra
