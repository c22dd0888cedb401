#include "membra/render/renderer.hpp"

#define GL_GLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>
#include <stb_easy_font.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace membra {
namespace {

const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 color;
uniform mat4 view_projection;
uniform mat3 view_rotation;
uniform int lit;
out vec3 shade;
void main() {
  gl_Position = view_projection * vec4(position, 1.0);
  if (lit == 1) {
    // Two-sided Lambert light from the viewer's upper left, plus ambient.
    vec3 n = normalize(view_rotation * normal);
    float d = abs(dot(n, normalize(vec3(-0.3, 0.4, 1.0))));
    shade = color * (0.35 + 0.65 * d);
  } else {
    shade = color;
  }
}
)";

const char* kFragmentShader = R"(#version 330 core
in vec3 shade;
out vec4 out_color;
void main() { out_color = vec4(shade, 1.0); }
)";

GLuint compile(GLenum type, const char* src) {
  const GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &src, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[1024];
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    throw RenderError(std::string("shader compilation failed: ") + log);
  }
  return s;
}

// Interleaved vertex: position, normal, colour.
struct Vertex {
  float p[3], n[3], c[3];
};

}  // namespace

Rgb Image::pixel(int px, int py) const {
  const size_t i = (static_cast<size_t>(py) * width + px) * 3;
  return {rgb[i] / 255.0f, rgb[i + 1] / 255.0f, rgb[i + 2] / 255.0f};
}

struct Renderer::Impl {
  int width, height;
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  GLuint fbo = 0, color_rb = 0, depth_rb = 0, program = 0, vao = 0, vbo = 0;

  void draw(const std::vector<Vertex>& v, GLenum mode, const float* vp, const float* rot, int lit) {
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(Vertex)), v.data(),
                 GL_STREAM_DRAW);
    for (GLuint a = 0; a < 3; ++a) {
      glEnableVertexAttribArray(a);
      glVertexAttribPointer(a, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                            reinterpret_cast<void*>(static_cast<uintptr_t>(a * 3 * sizeof(float))));
    }
    glUniformMatrix4fv(glGetUniformLocation(program, "view_projection"), 1, GL_FALSE, vp);
    glUniformMatrix3fv(glGetUniformLocation(program, "view_rotation"), 1, GL_FALSE, rot);
    glUniform1i(glGetUniformLocation(program, "lit"), lit);
    glDrawArrays(mode, 0, static_cast<GLsizei>(v.size()));
  }
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

  glGenFramebuffers(1, &r.fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, r.fbo);
  glGenRenderbuffers(1, &r.color_rb);
  glBindRenderbuffer(GL_RENDERBUFFER, r.color_rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, r.color_rb);
  glGenRenderbuffers(1, &r.depth_rb);
  glBindRenderbuffer(GL_RENDERBUFFER, r.depth_rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, r.depth_rb);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw RenderError("incomplete framebuffer");

  r.program = glCreateProgram();
  glAttachShader(r.program, compile(GL_VERTEX_SHADER, kVertexShader));
  glAttachShader(r.program, compile(GL_FRAGMENT_SHADER, kFragmentShader));
  glLinkProgram(r.program);
  GLint ok = 0;
  glGetProgramiv(r.program, GL_LINK_STATUS, &ok);
  if (!ok) throw RenderError("shader program failed to link");
  glGenVertexArrays(1, &r.vao);
  glGenBuffers(1, &r.vbo);
}

Renderer::~Renderer() {
  if (!impl_ || impl_->display == EGL_NO_DISPLAY) return;
  eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (impl_->context != EGL_NO_CONTEXT) eglDestroyContext(impl_->display, impl_->context);
  eglTerminate(impl_->display);
}

Image Renderer::render(const Points& x, const std::vector<Triangle>& tris,
                       const std::vector<Rgb>& colors, const Camera& cam, const Legend* legend) {
  Impl& r = *impl_;
  eglMakeCurrent(r.display, EGL_NO_SURFACE, EGL_NO_SURFACE, r.context);
  glBindFramebuffer(GL_FRAMEBUFFER, r.fbo);
  glViewport(0, 0, r.width, r.height);
  glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glUseProgram(r.program);

  // Orthographic camera fitted to the bounding sphere; the mesh takes the left part of the image
  // when a legend is drawn.
  const double az = cam.azimuth * std::numbers::pi / 180,
               el = cam.elevation * std::numbers::pi / 180;
  const Vec3 eye(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  const Vec3 fwd = -eye;
  Vec3 right = fwd.cross(Vec3::UnitZ());
  if (right.norm() < 1e-9) right = Vec3::UnitX();
  right.normalize();
  const Vec3 up = right.cross(fwd);
  Eigen::Matrix3d rot;
  rot.row(0) = right;
  rot.row(1) = up;
  rot.row(2) = -fwd;
  const Vec3 centre =
      x.cols() ? Vec3(0.5 * (x.rowwise().minCoeff() + x.rowwise().maxCoeff())) : Vec3::Zero();
  double radius = 1e-12;
  for (Eigen::Index p = 0; p < x.cols(); ++p) radius = std::max(radius, (x.col(p) - centre).norm());
  const double mesh_w = legend ? 0.8 : 1.0;  // share of the width for the mesh
  const double aspect = mesh_w * r.width / r.height;
  const double sy = 1.0 / (radius * cam.margin * std::max(1.0, 1.0 / aspect));
  const double sx = sy / aspect;
  Eigen::Matrix4f vp = Eigen::Matrix4f::Identity();
  Eigen::Matrix3d s =
      Eigen::Vector3d(sx * mesh_w, sy, -0.5 / (radius * cam.margin)).asDiagonal() * rot;
  vp.topLeftCorner<3, 3>() = s.cast<float>();
  vp.topRightCorner<3, 1>() =
      (-(s * centre) + Vec3(legend ? -(1.0 - mesh_w) : 0.0, 0.0, 0.0)).cast<float>();
  const Eigen::Matrix3f rotf = rot.cast<float>();

  // Smooth normals (area-weighted).
  Points normals = Points::Zero(3, x.cols());
  for (const Triangle& t : tris) {
    const Vec3 n = (x.col(t[1]) - x.col(t[0])).cross(x.col(t[2]) - x.col(t[0]));
    for (int k = 0; k < 3; ++k) normals.col(t[k]) += n;
  }
  std::vector<Vertex> verts;
  verts.reserve(tris.size() * 3);
  for (const Triangle& t : tris)
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = x.col(t[k]), n = normals.col(t[k]).normalized();
      const Rgb& c = colors[t[k]];
      verts.push_back({{float(p.x()), float(p.y()), float(p.z())},
                       {float(n.x()), float(n.y()), float(n.z())},
                       {c.x(), c.y(), c.z()}});
    }
  glEnable(GL_DEPTH_TEST);
  r.draw(verts, GL_TRIANGLES, vp.data(), rotf.data(), 1);
  glDisable(GL_DEPTH_TEST);

  if (legend) {
    // Pixel coordinates (origin top-left) to clip space.
    const float w = static_cast<float>(r.width), h = static_cast<float>(r.height);
    const Eigen::Matrix4f px = [&] {
      Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
      m(0, 0) = 2.0f / w;
      m(1, 1) = -2.0f / h;
      m(0, 3) = -1.0f;
      m(1, 3) = 1.0f;
      return m;
    }();
    const Eigen::Matrix3f id = Eigen::Matrix3f::Identity();
    std::vector<Vertex> bar;
    const float x0 = 0.84f * w, x1 = x0 + 0.03f * w;
    const float top = 0.15f * h, bottom = 0.85f * h;
    constexpr int steps = 64;
    for (int i = 0; i < steps; ++i) {
      const float fa = static_cast<float>(i) / steps, fb = static_cast<float>(i + 1) / steps;
      const float ya = bottom - (bottom - top) * fa, yb = bottom - (bottom - top) * fb;
      const Rgb ca = colormap(legend->lo + (legend->hi - legend->lo) * fa, legend->lo, legend->hi);
      const Rgb cb = colormap(legend->lo + (legend->hi - legend->lo) * fb, legend->lo, legend->hi);
      auto v = [](float a, float b, const Rgb& c) {
        return Vertex{{a, b, 0.0f}, {0, 0, 1}, {c.x(), c.y(), c.z()}};
      };
      bar.insert(bar.end(), {v(x0, ya, ca), v(x1, ya, ca), v(x1, yb, cb), v(x0, ya, ca),
                             v(x1, yb, cb), v(x0, yb, cb)});
    }
    r.draw(bar, GL_TRIANGLES, px.data(), id.data(), 0);

    // Labels with stb_easy_font (quads in pixels at scale 1; drawn at 2x).
    std::vector<Vertex> text;
    auto label = [&](const std::string& str, float lx, float ly) {
      static char buffer[60000];
      const int quads =
          stb_easy_font_print(0, 0, const_cast<char*>(str.c_str()), nullptr, buffer, sizeof buffer);
      const float* q = reinterpret_cast<const float*>(buffer);
      for (int i = 0; i < quads; ++i) {
        Vertex c[4];
        for (int k = 0; k < 4; ++k) {
          const float* e = q + (i * 4 + k) * 4;  // x, y, z, packed colour
          c[k] = {{lx + 2.0f * e[0], ly + 2.0f * e[1], 0.0f}, {0, 0, 1}, {0.1f, 0.1f, 0.1f}};
        }
        text.insert(text.end(), {c[0], c[1], c[2], c[0], c[2], c[3]});
      }
    };
    char buf[64];
    for (int i = 0; i <= 4; ++i) {
      const double v = legend->lo + (legend->hi - legend->lo) * i / 4.0;
      std::snprintf(buf, sizeof buf, "%.3g", v);
      label(buf, x1 + 6.0f, bottom - (bottom - top) * static_cast<float>(i) / 4.0f - 7.0f);
    }
    label(legend->title, 0.62f * w, 0.04f * h);
    label(legend->unit, x0 - 6.0f, top - 26.0f);
    r.draw(text, GL_TRIANGLES, px.data(), id.data(), 0);
  }

  Image img{r.width, r.height,
            std::vector<std::uint8_t>(static_cast<size_t>(r.width) * r.height * 3)};
  std::vector<std::uint8_t> rgba(static_cast<size_t>(r.width) * r.height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, r.width, r.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  for (int yy = 0; yy < r.height; ++yy)  // OpenGL rows start at the bottom
    for (int xx = 0; xx < r.width; ++xx)
      for (int c = 0; c < 3; ++c)
        img.rgb[(static_cast<size_t>(yy) * r.width + xx) * 3 + c] =
            rgba[(static_cast<size_t>(r.height - 1 - yy) * r.width + xx) * 4 + c];
  return img;
}

Image draw_pattern(const Pattern& pattern, const Box2& frame, double pixels_per_mm) {
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
      } else if (pattern.contains(p)) {
        px[0] = px[1] = px[2] = 0;
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

std::vector<std::uint8_t> encode_png(const Image& image) {
  std::vector<std::uint8_t> png;
  stbi_write_png_to_func(
      [](void* ctx, void* data, int size) {
        auto* out = static_cast<std::vector<std::uint8_t>*>(ctx);
        const auto* bytes = static_cast<std::uint8_t*>(data);
        out->insert(out->end(), bytes, bytes + size);
      },
      &png, image.width, image.height, 3, image.rgb.data(), image.width * 3);
  return png;
}

void write_png(const std::filesystem::path& file, const Image& image) {
  if (!stbi_write_png(file.c_str(), image.width, image.height, 3, image.rgb.data(),
                      image.width * 3))
    throw RenderError(file.string() + ": cannot write PNG");
}

}  // namespace membra
