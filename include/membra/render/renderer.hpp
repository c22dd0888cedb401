#pragma once
// Offscreen rendering of a coloured triangle mesh to an RGB image, with a colour-bar legend.
// Uses OpenGL 3.3 core through EGL's surfaceless platform (Mesa), so it needs no display; the
// viewer can draw with the same code into its window.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "membra/core/vec.hpp"
#include "membra/geometry/triangulation.hpp"
#include "membra/measure/colormap.hpp"
#include "membra/model/pattern.hpp"
#include "membra/render/gl_painter.hpp"

namespace membra {

class RenderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Where the camera looks from: azimuth around +z from +x, elevation above the xy-plane (deg).
struct Camera {
  double azimuth = -60.0;
  double elevation = 35.0;
  double margin = 1.1;     // the form's extent as seen fills 1/margin of the picture
  bool shadow = true;      // a soft shadow on the ground below the form
  bool scale_bar = false;  // a scale bar in mm (for views straight along an axis)
};

// An RGB image, rows from the top.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  Rgb pixel(int x, int y) const;
};

class Renderer {
 public:
  // Creates a headless OpenGL context and a width x height framebuffer. Throws RenderError when
  // no EGL/OpenGL 3.3 is available.
  Renderer(int width, int height);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Shaded mesh (positions in any unit, per-vertex colours) on a white background with its soft
  // shadow, orthographic from the camera and framed tightly, with the legend on the right when
  // given and a heading (caption, then the legend's title) at the top. Antialiased by
  // supersampling; every label stays inside the image. The triangles `outlined` (indices into
  // `triangles`: where the form passes through itself) are outlined in magenta over everything.
  Image render(const Points& x, const std::vector<Triangle>& triangles,
               const std::vector<Rgb>& colors, const Camera& camera, const Legend* legend,
               const std::string& caption = {}, const std::vector<int>& outlined = {});

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The framebuffer currently bound for reading (width x height, from its lower-left corner) as
// an image with rows from the top. Needs a current OpenGL context.
Image read_pixels(int width, int height);

// The pattern seen from above on its frame (m): resin black on white with a red frame line,
// `pixels_per_mm` pixels per mm (CPU, no OpenGL needed). Either pattern may be null; the
// `underside`'s (coats on the bottom face) is blue, as in pattern.svg.
Image draw_pattern(const Pattern* pattern, const Box2& frame, double pixels_per_mm,
                   const Pattern* underside = nullptr);

// Copies `src` into `dst` with its top-left corner at (x, y), clipped to dst.
void blit(Image& dst, const Image& src, int x, int y);
// An image of the given size filled with white.
Image blank_image(int width, int height);

// The image encoded as PNG bytes.
std::vector<std::uint8_t> encode_png(const Image& image);
// Writes an image as PNG. Throws RenderError naming the file on failure.
void write_png(const std::filesystem::path& file, const Image& image);

}  // namespace membra
