#include "membra/render/renderer.hpp"

#define GL_GLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>
#include <png.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "membra/core/stop_request.hpp"
#include "membra/geometry/orbit_camera.hpp"
#include "membra/render/font.hpp"
#include "membra/render/gl_painter.hpp"

namespace membra {

Rgb Image::pixel(int px, int py) const {
  const size_t i = (static_cast<size_t>(py) * width + px) * 3;
  return {rgb[i] / 255.0f, rgb[i + 1] / 255.0f, rgb[i + 2] / 255.0f};
}

struct Renderer::Impl {
  int width, height;
  int ss = 1;  // supersampling: the framebuffer is ss times the image on each side
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  GLuint fbo = 0, color_rb = 0, depth_rb = 0;
  std::unique_ptr<GlPainter> painter;
  std::vector<std::uint8_t> readback;  // the framebuffer's RGBA, kept between pictures
};

Renderer::Renderer(int width, int height) : impl_(std::make_unique<Impl>()) {
  if (width < 16 || height < 16 || width > 8192 || height > 8192)
    throw RenderError("image size must be within 16..8192 pixels per side");
  Impl& r = *impl_;
  r.width = width;
  r.height = height;
  auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!get_platform_display) throw RenderError("EGL has no eglGetPlatformDisplayEXT");
  r.display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (r.display == EGL_NO_DISPLAY || !eglInitialize(r.display, nullptr, nullptr))
    throw RenderError("cannot open a surfaceless EGL display (is Mesa's libegl-mesa0 installed?)");
  const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                   EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config;
  EGLint count = 0;
  if (!eglChooseConfig(r.display, config_attribs, &config, 1, &count) || count < 1)
    throw RenderError("no suitable EGL configuration");
  eglBindAPI(EGL_OPENGL_API);
  const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                    3,
                                    EGL_CONTEXT_MINOR_VERSION,
                                    3,
                                    EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                    EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                    EGL_NONE};
  r.context = eglCreateContext(r.display, config, EGL_NO_CONTEXT, context_attribs);
  if (r.context == EGL_NO_CONTEXT) throw RenderError("cannot create an OpenGL 3.3 core context");
  if (!eglMakeCurrent(r.display, EGL_NO_SURFACE, EGL_NO_SURFACE, r.context))
    throw RenderError("cannot make the OpenGL context current");

  // Antialiasing by supersampling: drawn 3x (2x for large images) on each side and averaged
  // down, which smooths the mesh's silhouette, the shadow and the text alike.
  GLint max_size = 4096;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  // At most 36 M framebuffer pixels (about 430 MB with depth and the read-back buffer, which
  // the renderer keeps while it lives: 39 MB at the default 1200 x 900): large pictures
  // are sampled less, 8192 x 6144 not at all.
  const double pixels = static_cast<double>(width) * height;
  r.ss = std::clamp(std::min(3, max_size / std::max(width, height)), 1, 3);
  while (r.ss > 1 && pixels * r.ss * r.ss > 36e6) --r.ss;
  const int fw = r.ss * width, fh = r.ss * height;
  glGenFramebuffers(1, &r.fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, r.fbo);
  glGenRenderbuffers(1, &r.color_rb);
  glBindRenderbuffer(GL_RENDERBUFFER, r.color_rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, fw, fh);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, r.color_rb);
  glGenRenderbuffers(1, &r.depth_rb);
  glBindRenderbuffer(GL_RENDERBUFFER, r.depth_rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, fw, fh);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, r.depth_rb);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw RenderError("incomplete framebuffer");

  r.painter = std::make_unique<GlPainter>();
  r.painter->set_pixel_scale(static_cast<float>(r.ss));
}

Renderer::~Renderer() {
  if (!impl_ || impl_->display == EGL_NO_DISPLAY) return;
  eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, impl_->context);
  impl_->painter.reset();  // its GL names belong to the context
  eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (impl_->context != EGL_NO_CONTEXT) eglDestroyContext(impl_->display, impl_->context);
  // No eglTerminate: every renderer of the process gets the same display, and terminating it
  // would break the others still drawing (a run's panels are drawn while its main renderer
  // lives). The display is released at exit.
}

namespace {

// The orbit camera that frames the points tightly: their extent as the camera sees them, plus
// the margin, fills the viewport of the given aspect, whatever the form's size or shape.
OrbitCamera framing(const Points& x, const Camera& cam, double aspect) {
  OrbitCamera orbit;
  orbit.azimuth = cam.azimuth;
  orbit.elevation = cam.elevation;
  if (x.cols() == 0) return orbit;
  const Eigen::Matrix3d rot = orbit.rotation();
  const Eigen::Matrix3Xd seen = rot * x;
  const Vec3 lo = seen.rowwise().minCoeff(), hi = seen.rowwise().maxCoeff();
  const Vec3 mid = 0.5 * (lo + hi), ext = (hi - lo).cwiseMax(1e-12);
  orbit.target = rot.transpose() * mid;
  orbit.half_height = 0.5 * cam.margin * std::max(ext.y(), ext.x() / aspect);
  orbit.depth = cam.margin * std::max(ext.norm(), 1e-12);
  return orbit;
}

// The framebuffer read back and averaged down, ss x ss of its pixels to each of the image's,
// rows from the top (OpenGL's start at the bottom), in one pass over a read-back buffer kept
// between pictures: a fresh 40 MB buffer, copied once to flip it and again to average it, was
// half of a picture's time without its shadow (docs/performance.md, "Pictures").
Image read_image(int width, int height, int ss, std::vector<std::uint8_t>& rgba) {
  const int fw = ss * width, fh = ss * height, n = ss * ss;
  rgba.resize(static_cast<size_t>(fw) * fh * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, fw, fh, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  Image img = blank_image(width, height);
  std::vector<int> sum(static_cast<size_t>(width) * 3);
  for (int y = 0; y < height; ++y) {
    std::fill(sum.begin(), sum.end(), 0);
    for (int dy = 0; dy < ss; ++dy) {
      const std::uint8_t* row = rgba.data() + static_cast<size_t>(fh - 1 - (y * ss + dy)) * fw * 4;
      for (int x = 0; x < width; ++x) {
        int* s = &sum[static_cast<size_t>(x) * 3];
        for (const std::uint8_t* p = row + static_cast<size_t>(x) * ss * 4;
             p < row + static_cast<size_t>(x + 1) * ss * 4; p += 4) {
          s[0] += p[0];
          s[1] += p[1];
          s[2] += p[2];
        }
      }
    }
    std::uint8_t* out = img.rgb.data() + static_cast<size_t>(y) * width * 3;
    for (size_t i = 0; i < sum.size(); ++i)
      out[i] = static_cast<std::uint8_t>((sum[i] + n / 2) / n);
  }
  return img;
}

}  // namespace

Image Renderer::render(const Points& x, const std::vector<Triangle>& tris,
                       const std::vector<Rgb>& colors, const Camera& cam, const Legend* legend,
                       const std::string& caption, const std::vector<int>& outlined) {
  // A stop asked for (Ctrl-C) while a run's pictures are drawn: before another large render.
  if (const int sig = stop_requested()) throw Interrupted(sig, "while writing the outputs");
  Impl& r = *impl_;
  const int fw = r.ss * r.width, fh = r.ss * r.height;
  eglMakeCurrent(r.display, EGL_NO_SURFACE, EGL_NO_SURFACE, r.context);
  glBindFramebuffer(GL_FRAMEBUFFER, r.fbo);
  glViewport(0, 0, fw, fh);
  glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  std::string title = legend ? legend->title : "";
  if (!caption.empty()) title = title.empty() ? caption : caption + " \u00b7 " + title;
  // The form takes the image below the heading and left of the legend.
  const double band = title.empty() ? 0.0 : r.painter->heading_band(fh) / static_cast<double>(fh);
  const double mesh_w = legend ? 0.8 : 1.0, mesh_h = 1.0 - band;
  // The shadow's ground a little below the form; it is framed with the form.
  double ground = 0.0, size = 0.0;
  if (x.cols()) {
    ground = x.row(2).minCoeff();
    size = (x.rowwise().maxCoeff() - x.rowwise().minCoeff()).norm();
    ground -= 0.02 * size;
  }
  Points framed(3, 2 * x.cols());
  framed << x, x;
  if (x.cols()) framed.block(2, x.cols(), 1, x.cols()).setConstant(ground);
  const double aspect = mesh_w * fw / (mesh_h * fh);
  const OrbitCamera orbit = framing(framed, cam, aspect);
  Eigen::Matrix4d squeeze = Eigen::Matrix4d::Identity();
  squeeze(0, 0) = mesh_w;
  squeeze(0, 3) = -(1.0 - mesh_w);
  squeeze(1, 1) = mesh_h;
  squeeze(1, 3) = -band;
  const Eigen::Matrix4f vp = (squeeze * orbit.view_projection(aspect)).cast<float>();
  const Eigen::Matrix3f rotf = orbit.rotation().cast<float>();

  if (cam.shadow && x.cols()) r.painter->shadow(x, tris, ground, 0.03 * size, vp);
  glEnable(GL_DEPTH_TEST);
  r.painter->mesh(x, tris, colors, vp, rotf);
  glDisable(GL_DEPTH_TEST);
  r.painter->outline(x, tris, outlined, kCrossingColour, vp, 2.0f);
  // The projection maps half_height world units to half the form's band of framebuffer rows.
  if (cam.scale_bar && x.cols())
    r.painter->scale_bar(mesh_h * fh / (2.0 * orbit.half_height), fw, fh);
  if (legend) r.painter->legend(*legend, fw, fh);
  if (!title.empty()) r.painter->heading(title, fw, fh);
  return read_image(r.width, r.height, r.ss, r.readback);
}

Image read_pixels(int width, int height) {
  std::vector<std::uint8_t> rgba;
  return read_image(width, height, 1, rgba);  // one framebuffer pixel to each of the image's
}

Image draw_pattern(const Pattern* pattern, const Box2& frame, double pixels_per_mm,
                   const Pattern* underside) {
  const Vec2 size = (frame.max - frame.min) * 1e3 * pixels_per_mm;
  Image img{std::max(16, static_cast<int>(std::lround(size.x()))),
            std::max(16, static_cast<int>(std::lround(size.y()))),
            {}};
  img.rgb.assign(static_cast<size_t>(img.width) * img.height * 3, 255);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const Vec2 p(frame.min.x() + (x + 0.5) / img.width * (frame.max.x() - frame.min.x()),
                   frame.max.y() - (y + 0.5) / img.height * (frame.max.y() - frame.min.y()));
      std::uint8_t* px = &img.rgb[(static_cast<size_t>(y) * img.width + x) * 3];
      if (x == 0 || y == 0 || x == img.width - 1 || y == img.height - 1) {
        px[0] = 220, px[1] = 0, px[2] = 0;  // the frame
      } else if (pattern && pattern->contains(p)) {
        px[0] = px[1] = px[2] = 0;
      } else if (underside && underside->contains(p)) {
        px[0] = 32, px[1] = 96, px[2] = 192;  // #2060c0, pattern.svg's resin_bottom
      }
    }
  return img;
}

void blit(Image& dst, const Image& src, int x, int y) {
  for (int row = 0; row < src.height; ++row) {
    const int ty = y + row;
    if (ty < 0 || ty >= dst.height) continue;
    for (int col = 0; col < src.width; ++col) {
      const int tx = x + col;
      if (tx < 0 || tx >= dst.width) continue;
      const size_t from = (static_cast<size_t>(row) * src.width + col) * 3;
      const size_t to = (static_cast<size_t>(ty) * dst.width + tx) * 3;
      std::copy_n(&src.rgb[from], 3, &dst.rgb[to]);
    }
  }
}

Image blank_image(int width, int height) {
  return {width, height, std::vector<std::uint8_t>(static_cast<size_t>(width) * height * 3, 255)};
}

namespace {

// libpng reports errors by a long jump back to png_encode's setjmp: png_encode holds no C++
// object with a destructor after it, and the long jump leaves no catch block.
void append_bytes(png_structp png, png_bytep data, png_size_t size) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
  bool failed = false;
  try {
    out->insert(out->end(), data, data + size);
  } catch (...) {
    failed = true;
  }
  if (failed) png_error(png, "out of memory");
}

void no_flush(png_structp) {}  // the bytes go to memory (libpng's default flushes a FILE*)

bool png_encode(const Image& image, std::vector<std::uint8_t>& out) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, &out, append_bytes, no_flush);
  // zlib's level 3 with each row predicted from its left neighbour: 4x faster than stb's writer
  // and a quarter smaller (docs/performance.md, "Pictures").
  png_set_compression_level(png, 3);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y)
    png_write_row(png, image.rgb.data() + static_cast<size_t>(y) * image.width * 3);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image) {
  std::vector<std::uint8_t> png;
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != static_cast<size_t>(image.width) * image.height * 3 ||
      !png_encode(image, png))
    throw RenderError("cannot encode a " + std::to_string(image.width) + " x " +
                      std::to_string(image.height) + " PNG");
  return png;
}

void write_png(const std::filesystem::path& file, const Image& image) {
  std::vector<std::uint8_t> png;
  try {
    png = encode_png(image);
  } catch (const RenderError& e) {
    throw RenderError(file.string() + ": " + e.what());
  }
  std::ofstream out(file, std::ios::binary);
  out.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  out.close();
  if (!out) throw RenderError(file.string() + ": cannot write PNG");
}

}  // namespace membra
