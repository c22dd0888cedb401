#include "membra/render/gl_painter.hpp"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>
#include <stb_easy_font.h>

#include <cstdint>
#include <cstdio>

#include "membra/render/renderer.hpp"

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

Vertex flat_vertex(const Vec3& p, const Rgb& c) {
  return {{float(p.x()), float(p.y()), float(p.z())}, {0, 0, 1}, {c.x(), c.y(), c.z()}};
}

// Pixel coordinates (origin top-left) of a width x height viewport to clip space.
Eigen::Matrix4f pixel_matrix(int width, int height) {
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m(0, 0) = 2.0f / static_cast<float>(width);
  m(1, 1) = -2.0f / static_cast<float>(height);
  m(0, 3) = -1.0f;
  m(1, 3) = 1.0f;
  return m;
}

}  // namespace

struct GlPainter::Impl {
  GLuint program = 0, vao = 0, vbo = 0;

  void draw(const std::vector<Vertex>& v, GLenum mode, const float* vp, const float* rot, int lit) {
    if (v.empty()) return;
    glUseProgram(program);
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
  void draw_flat(const std::vector<Vertex>& v, GLenum mode, const Eigen::Matrix4f& vp) {
    const Eigen::Matrix3f id = Eigen::Matrix3f::Identity();
    draw(v, mode, vp.data(), id.data(), 0);
  }
};

GlPainter::GlPainter() : impl_(std::make_unique<Impl>()) {
  Impl& r = *impl_;
  r.program = glCreateProgram();
  const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, kFragmentShader);
  glAttachShader(r.program, vs);
  glAttachShader(r.program, fs);
  glLinkProgram(r.program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(r.program, GL_LINK_STATUS, &ok);
  if (!ok) throw RenderError("shader program failed to link");
  glGenVertexArrays(1, &r.vao);
  glGenBuffers(1, &r.vbo);
}

GlPainter::~GlPainter() {
  // The context may already be gone when the owner tears down; deleting names is then harmless.
  if (!impl_) return;
  glDeleteBuffers(1, &impl_->vbo);
  glDeleteVertexArrays(1, &impl_->vao);
  glDeleteProgram(impl_->program);
}

void GlPainter::mesh(const Points& x, const std::vector<Triangle>& tris,
                     const std::vector<Rgb>& colors, const Eigen::Matrix4f& vp,
                     const Eigen::Matrix3f& rot) {
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
  impl_->draw(verts, GL_TRIANGLES, vp.data(), rot.data(), 1);
}

void GlPainter::lines(const std::vector<Vec3>& endpoints, const Rgb& color,
                      const Eigen::Matrix4f& vp) {
  std::vector<Vertex> v;
  v.reserve(endpoints.size());
  for (const Vec3& p : endpoints) v.push_back(flat_vertex(p, color));
  impl_->draw_flat(v, GL_LINES, vp);
}

void GlPainter::points(const std::vector<Vec3>& pts, const Rgb& color, float size,
                       const Eigen::Matrix4f& vp) {
  std::vector<Vertex> v;
  v.reserve(pts.size());
  for (const Vec3& p : pts) v.push_back(flat_vertex(p, color));
  glPointSize(size);
  impl_->draw_flat(v, GL_POINTS, vp);
}

void GlPainter::pixel_triangles(const std::vector<Vec3>& corners, const std::vector<Rgb>& colors,
                                int width, int height) {
  std::vector<Vertex> v;
  v.reserve(corners.size());
  for (size_t i = 0; i < corners.size(); ++i) v.push_back(flat_vertex(corners[i], colors[i]));
  impl_->draw_flat(v, GL_TRIANGLES, pixel_matrix(width, height));
}

void GlPainter::text(const std::string& str, float x, float y, float scale, const Rgb& color,
                     int width, int height) {
  // stb_easy_font writes quads (x, y, z, packed colour) at 1 pixel per unit.
  std::vector<char> buffer(str.size() * 270 + 64);
  const int quads = stb_easy_font_print(0, 0, const_cast<char*>(str.c_str()), nullptr,
                                        buffer.data(), static_cast<int>(buffer.size()));
  const float* q = reinterpret_cast<const float*>(buffer.data());
  std::vector<Vertex> v;
  v.reserve(static_cast<size_t>(quads) * 6);
  for (int i = 0; i < quads; ++i) {
    Vertex c[4];
    for (int k = 0; k < 4; ++k) {
      const float* e = q + (i * 4 + k) * 4;
      c[k] = flat_vertex(Vec3(x + scale * e[0], y + scale * e[1], 0.0), color);
    }
    v.insert(v.end(), {c[0], c[1], c[2], c[0], c[2], c[3]});
  }
  impl_->draw_flat(v, GL_TRIANGLES, pixel_matrix(width, height));
}

void GlPainter::legend(const Legend& legend, int width, int height) {
  const float w = static_cast<float>(width), h = static_cast<float>(height);
  const float x0 = 0.84f * w, x1 = x0 + 0.03f * w;
  const float top = 0.15f * h, bottom = 0.85f * h;
  std::vector<Vec3> corners;
  std::vector<Rgb> colors;
  constexpr int steps = 64;
  for (int i = 0; i < steps; ++i) {
    const float fa = static_cast<float>(i) / steps, fb = static_cast<float>(i + 1) / steps;
    const float ya = bottom - (bottom - top) * fa, yb = bottom - (bottom - top) * fb;
    const Rgb ca = colormap(legend.lo + (legend.hi - legend.lo) * fa, legend.lo, legend.hi);
    const Rgb cb = colormap(legend.lo + (legend.hi - legend.lo) * fb, legend.lo, legend.hi);
    corners.insert(corners.end(), {Vec3(x0, ya, 0), Vec3(x1, ya, 0), Vec3(x1, yb, 0),
                                   Vec3(x0, ya, 0), Vec3(x1, yb, 0), Vec3(x0, yb, 0)});
    colors.insert(colors.end(), {ca, ca, cb, ca, cb, cb});
  }
  pixel_triangles(corners, colors, width, height);
  const Rgb ink(0.1f, 0.1f, 0.1f);
  char buf[64];
  for (int i = 0; i <= 4; ++i) {
    const double v = legend.lo + (legend.hi - legend.lo) * i / 4.0;
    std::snprintf(buf, sizeof buf, "%.3g", v);
    text(buf, x1 + 6.0f, bottom - (bottom - top) * static_cast<float>(i) / 4.0f - 7.0f, 2.0f, ink,
         width, height);
  }
  text(legend.title, 0.62f * w, 0.04f * h, 2.0f, ink, width, height);
  text(legend.unit, x0 - 6.0f, top - 26.0f, 2.0f, ink, width, height);
}

}  // namespace membra
