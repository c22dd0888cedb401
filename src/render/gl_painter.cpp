#include "membra/render/gl_painter.hpp"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <tuple>
#include <vector>

#include "membra/core/readable_units.hpp"
#include "membra/render/font.hpp"
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
    // Two-sided: a key light from the upper left, high above the viewer (so that a dome's
    // crown and flanks differ), and a soft fill from the viewer, plus ambient.
    vec3 n = normalize(view_rotation * normal);
    float key = abs(dot(n, normalize(vec3(-0.45, 0.85, 0.45))));
    float fill = abs(dot(n, vec3(0.0, 0.0, 1.0)));
    shade = color * (0.25 + 0.55 * key + 0.25 * fill);
  } else {
    shade = color;
  }
}
)";

const char* kFragmentShader = R"(#version 330 core
in vec3 shade;
uniform float alpha;
out vec4 out_color;
void main() { out_color = vec4(shade, alpha); }
)";

// Text: a coverage texture (stb_truetype's) tinted with the ink colour.
const char* kTextVertexShader = R"(#version 330 core
layout(location = 0) in vec2 position;
layout(location = 1) in vec2 uv;
uniform mat4 pixels;
out vec2 tex;
void main() {
  gl_Position = pixels * vec4(position, 0.0, 1.0);
  tex = uv;
}
)";

const char* kTextFragmentShader = R"(#version 330 core
in vec2 tex;
uniform sampler2D coverage;
uniform vec3 ink;
out vec4 out_color;
void main() { out_color = vec4(ink, texture(coverage, tex).r); }
)";

// The soft shadow's passes over the whole viewport: a triangle that covers it, from the vertex id.
const char* kScreenVertexShader = R"(#version 330 core
out vec2 uv;
void main() {
  uv = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  gl_Position = vec4(2.0 * uv - 1.0, 0.0, 1.0);
}
)";

// The silhouette's coverage averaged over the penumbra's disk: the share of the 40 shifted
// copies of the old drawing (one per tap) that cover this pixel.
const char* kBlurFragmentShader = R"(#version 330 core
in vec2 uv;
uniform sampler2D mask;
uniform vec2 taps[40];
out vec4 out_color;
void main() {
  float sum = 0.0;
  for (int k = 0; k < 40; ++k) sum += texture(mask, uv - taps[k]).r;
  out_color = vec4(sum / 40.0, 0.0, 0.0, 1.0);
}
)";

// Grey laid over the ground as 40 faint copies would (each 1.2 % opaque where it covers).
const char* kShadowFragmentShader = R"(#version 330 core
in vec2 uv;
uniform sampler2D coverage;
out vec4 out_color;
void main() {
  float n = 40.0 * texture(coverage, uv).r;
  out_color = vec4(0.25, 0.27, 0.3, 1.0 - pow(0.988, n));
}
)";

GLuint compile(GLenum type, const char* src);

GLuint link(const char* vertex, const char* fragment) {
  const GLuint program = glCreateProgram();
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, fragment);
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) throw RenderError("shader program failed to link");
  return program;
}

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
  GLuint text_program = 0, text_vao = 0, text_vbo = 0, texture = 0;
  // The shadow's silhouette and its blur, drawn off screen at a lower resolution.
  GLuint blur_program = 0, shadow_program = 0;
  GLuint mask_fbo = 0, mask_tex = 0, blur_fbo = 0, blur_tex = 0;
  int mask_w = 0, mask_h = 0;
  float alpha = 1.0f;

  // The two off-screen targets at w x h (kept while the size stays).
  void shadow_targets(int w, int h) {
    if (w == mask_w && h == mask_h) return;
    const float border[] = {0.0f, 0.0f, 0.0f, 0.0f};
    glActiveTexture(GL_TEXTURE0);
    for (auto [fbo, tex, format] :
         {std::tuple{mask_fbo, mask_tex, GL_R8}, std::tuple{blur_fbo, blur_tex, GL_R16F}}) {
      glBindTexture(GL_TEXTURE_2D, tex);
      glTexImage2D(GL_TEXTURE_2D, 0, format, w, h, 0, GL_RED, GL_FLOAT, nullptr);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
      glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
      glBindFramebuffer(GL_FRAMEBUFFER, fbo);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
      if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RenderError("incomplete shadow framebuffer");
    }
    mask_w = w;
    mask_h = h;
  }
  // A pass of `prog` over the whole of the current target, reading `tex` on unit 0.
  void screen_pass(GLuint prog, GLuint tex, const char* sampler) {
    glUseProgram(prog);
    glBindVertexArray(text_vao);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, tex);
    glUniform1i(glGetUniformLocation(prog, sampler), 0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }

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
    glUniform1f(glGetUniformLocation(program, "alpha"), alpha);
    glDrawArrays(mode, 0, static_cast<GLsizei>(v.size()));
  }
  void draw_flat(const std::vector<Vertex>& v, GLenum mode, const Eigen::Matrix4f& vp) {
    const Eigen::Matrix3f id = Eigen::Matrix3f::Identity();
    draw(v, mode, vp.data(), id.data(), 0);
  }
};

GlPainter::GlPainter() : impl_(std::make_unique<Impl>()) {
  Impl& r = *impl_;
  r.program = link(kVertexShader, kFragmentShader);
  r.text_program = link(kTextVertexShader, kTextFragmentShader);
  r.blur_program = link(kScreenVertexShader, kBlurFragmentShader);
  r.shadow_program = link(kScreenVertexShader, kShadowFragmentShader);
  glGenFramebuffers(1, &r.mask_fbo);
  glGenFramebuffers(1, &r.blur_fbo);
  glGenTextures(1, &r.mask_tex);
  glGenTextures(1, &r.blur_tex);
  glGenVertexArrays(1, &r.vao);
  glGenBuffers(1, &r.vbo);
  glGenVertexArrays(1, &r.text_vao);
  glGenBuffers(1, &r.text_vbo);
  glGenTextures(1, &r.texture);
}

GlPainter::~GlPainter() {
  // The context may already be gone when the owner tears down; deleting names is then harmless.
  if (!impl_) return;
  glDeleteBuffers(1, &impl_->vbo);
  glDeleteVertexArrays(1, &impl_->vao);
  glDeleteProgram(impl_->program);
  glDeleteBuffers(1, &impl_->text_vbo);
  glDeleteVertexArrays(1, &impl_->text_vao);
  glDeleteTextures(1, &impl_->texture);
  glDeleteProgram(impl_->text_program);
  glDeleteProgram(impl_->blur_program);
  glDeleteProgram(impl_->shadow_program);
  glDeleteFramebuffers(1, &impl_->mask_fbo);
  glDeleteFramebuffers(1, &impl_->blur_fbo);
  glDeleteTextures(1, &impl_->mask_tex);
  glDeleteTextures(1, &impl_->blur_tex);
}

void GlPainter::mesh(const Points& x, const std::vector<Triangle>& tris,
                     const std::vector<Rgb>& colors, const Eigen::Matrix4f& vp,
                     const Eigen::Matrix3f& rot) {
  const Points normals = vertex_normals(x, tris);
  std::vector<Vertex> verts;
  verts.reserve(tris.size() * 3);
  for (const Triangle& t : tris)
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = x.col(t[k]), n = normals.col(t[k]);
      const Rgb& c = colors[t[k]];
      verts.push_back({{float(p.x()), float(p.y()), float(p.z())},
                       {float(n.x()), float(n.y()), float(n.z())},
                       {c.x(), c.y(), c.z()}});
    }
  impl_->draw(verts, GL_TRIANGLES, vp.data(), rot.data(), 1);
}

void GlPainter::lines(const std::vector<Vec3>& endpoints, const Rgb& color,
                      const Eigen::Matrix4f& vp, float width) {
  std::vector<Vertex> v;
  v.reserve(endpoints.size());
  for (const Vec3& p : endpoints) v.push_back(flat_vertex(p, color));
  glLineWidth(width * pixel_scale_);
  impl_->draw_flat(v, GL_LINES, vp);
  glLineWidth(1.0f);
}

void GlPainter::outline(const Points& x, const std::vector<Triangle>& tris,
                        const std::vector<int>& which, const Rgb& color, const Eigen::Matrix4f& vp,
                        float width) {
  std::vector<Vec3> ends;
  ends.reserve(which.size() * 6);
  for (const int t : which) {
    if (t < 0 || static_cast<size_t>(t) >= tris.size()) continue;
    const Triangle& tri = tris[static_cast<size_t>(t)];
    for (int k = 0; k < 3; ++k) {
      ends.push_back(x.col(tri[k]));
      ends.push_back(x.col(tri[(k + 1) % 3]));
    }
  }
  if (!ends.empty()) lines(ends, color, vp, width);
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

namespace {

// Where a world point lands in the viewport, in texture coordinates (0 to 1 across).
Eigen::Vector2f viewport_uv(const Eigen::Matrix4f& vp, const Vec3& p) {
  const Eigen::Vector4f c = vp * Eigen::Vector4f(float(p.x()), float(p.y()), float(p.z()), 1.0f);
  return 0.5f * (c.head<2>() / std::max(c.w(), 1e-6f) + Eigen::Vector2f::Ones());
}

// The penumbra's 40 offsets (a Vogel spiral over a disk of radius `blur` on the ground) as the
// viewport sees them (the pictures' cameras are orthographic: the same everywhere), and the part
// of the viewport the shadow can darken (texture coordinates).
struct ShadowTaps {
  static constexpr int copies = 40;
  std::vector<float> uv;  // x, y of each offset
  float reach = 0.0f;     // the largest offset, in viewport pixels
  Eigen::Vector2f lo = Eigen::Vector2f::Ones(), hi = Eigen::Vector2f::Zero();
};

ShadowTaps shadow_taps(const std::vector<Vec3>& ground, double blur, const Eigen::Matrix4f& vp,
                       int width, int height) {
  ShadowTaps t;
  Vec3 centre = Vec3::Zero();
  for (const Vec3& p : ground) {
    centre += p;
    const Eigen::Vector2f q = viewport_uv(vp, p);
    t.lo = t.lo.cwiseMin(q);
    t.hi = t.hi.cwiseMax(q);
  }
  centre /= static_cast<double>(ground.size());
  const Eigen::Vector2f mid = viewport_uv(vp, centre);
  float far = 0.0f;
  for (int c = 0; c < ShadowTaps::copies; ++c) {
    const double r = blur * std::sqrt((c + 0.5) / ShadowTaps::copies), a = 2.39996323 * c;
    const Eigen::Vector2f d =
        viewport_uv(vp, centre + Vec3(r * std::cos(a), r * std::sin(a), 0)) - mid;
    t.uv.push_back(d.x());
    t.uv.push_back(d.y());
    far = std::max(far, d.norm());
    t.reach = std::max(t.reach, std::hypot(d.x() * float(width), d.y() * float(height)));
  }
  // The silhouette's box grown by the farthest offset, and as much again for the mask's coarse
  // pixels.
  t.lo = (t.lo.array() - 2.0f * far).cwiseMax(0.0f);
  t.hi = (t.hi.array() + 2.0f * far).cwiseMin(1.0f);
  return t;
}

// The scissor box over the part [lo, hi] (texture coordinates) of a viewport (x, y, width,
// height in window pixels).
void scissor(const Eigen::Vector2f& lo, const Eigen::Vector2f& hi, const GLint* viewport) {
  const float w = static_cast<float>(viewport[2]), h = static_cast<float>(viewport[3]);
  const int x0 = static_cast<int>(std::floor(lo.x() * w)),
            y0 = static_cast<int>(std::floor(lo.y() * h));
  const int x1 = static_cast<int>(std::ceil(hi.x() * w)),
            y1 = static_cast<int>(std::ceil(hi.y() * h));
  glScissor(viewport[0] + x0, viewport[1] + y0, std::max(0, x1 - x0), std::max(0, y1 - y0));
}

// The caller's target as the shadow's off-screen passes find it, put back when they are done:
// the framebuffer, its viewport, the clear colour and the scissor test.
struct SavedTarget {
  GLint framebuffer = 0, viewport[4] = {0, 0, 1, 1}, box[4] = {0, 0, 1, 1};
  GLfloat clear[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  GLboolean scissored = GL_FALSE;
  SavedTarget() {
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &framebuffer);
    glGetIntegerv(GL_VIEWPORT, viewport);
    glGetIntegerv(GL_SCISSOR_BOX, box);
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
    scissored = glIsEnabled(GL_SCISSOR_TEST);
  }
  // Back to the caller's framebuffer and viewport (the scissor test as the caller's pass wants).
  void bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(framebuffer));
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  }
  ~SavedTarget() {
    bind();
    glClearColor(clear[0], clear[1], clear[2], clear[3]);
    glScissor(box[0], box[1], box[2], box[3]);
    if (scissored)
      glEnable(GL_SCISSOR_TEST);
    else
      glDisable(GL_SCISSOR_TEST);
  }
  SavedTarget(const SavedTarget&) = delete;
  SavedTarget& operator=(const SavedTarget&) = delete;
};

}  // namespace

void GlPainter::shadow(const Points& x, const std::vector<Triangle>& tris, double ground_z,
                       double blur, const Eigen::Matrix4f& vp) {
  // The form flattened onto the ground, lit from straight above, with a penumbra: what drawing
  // it 40 times at offsets spread over a disk of radius `blur`, each copy 1.2 % grey, gives —
  // computed as the silhouette drawn once off screen and averaged over the same 40 offsets, at
  // a resolution the penumbra hides (a tenth of its radius per pixel), then laid over the
  // ground where it can fall. The 40 full-size copies were most of a run's picture time
  // (docs/performance.md, "Pictures").
  if (tris.empty()) return;
  const SavedTarget saved;
  std::vector<Vertex> verts;
  std::vector<Vec3> ground;
  verts.reserve(tris.size() * 3);
  ground.reserve(tris.size() * 3);
  for (const Triangle& t : tris)
    for (int k = 0; k < 3; ++k) {
      ground.emplace_back(x(0, t[k]), x(1, t[k]), ground_z);
      verts.push_back(flat_vertex(ground.back(), Rgb(1.0f, 1.0f, 1.0f)));
    }
  const GLint* viewport = saved.viewport;
  const ShadowTaps taps = shadow_taps(ground, blur, vp, viewport[2], viewport[3]);
  const int shrink = std::max(1, static_cast<int>(taps.reach / 10.0f));
  Impl& r = *impl_;
  r.shadow_targets(std::max(1, viewport[2] / shrink), std::max(1, viewport[3] / shrink));
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, r.mask_w, r.mask_h);
  glBindFramebuffer(GL_FRAMEBUFFER, r.mask_fbo);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  r.draw_flat(verts, GL_TRIANGLES, vp);
  glBindFramebuffer(GL_FRAMEBUFFER, r.blur_fbo);
  glClear(GL_COLOR_BUFFER_BIT);  // no earlier shadow's coverage just outside the box
  glEnable(GL_SCISSOR_TEST);
  const GLint mask_viewport[4] = {0, 0, r.mask_w, r.mask_h};
  scissor(taps.lo, taps.hi, mask_viewport);
  glUseProgram(r.blur_program);
  glUniform2fv(glGetUniformLocation(r.blur_program, "taps"), ShadowTaps::copies, taps.uv.data());
  r.screen_pass(r.blur_program, r.mask_tex, "mask");
  saved.bind();
  scissor(taps.lo, taps.hi, viewport);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  r.screen_pass(r.shadow_program, r.blur_tex, "coverage");
  glDisable(GL_BLEND);
}

void GlPainter::text(const std::string& str, float x, float y, float pixel_height, const Rgb& color,
                     int width, int height) {
  if (str.empty()) return;
  const TextBitmap t = Font::standard().rasterize(str, pixel_height);
  if (pixel_height <= 0.0f) return;
  Impl& r = *impl_;
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, r.texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, t.width, t.height, 0, GL_RED, GL_UNSIGNED_BYTE,
               t.coverage.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  // Whole pixels, so that the glyphs' coverage lands on the pixels it was computed for.
  const float x0 = std::round(x) - 1.0f, y0 = std::round(y) - 1.0f;
  const float x1 = x0 + static_cast<float>(t.width), y1 = y0 + static_cast<float>(t.height);
  const float quad[] = {x0, y0, 0, 0, x1, y0, 1, 0, x1, y1, 1, 1,
                        x0, y0, 0, 0, x1, y1, 1, 1, x0, y1, 0, 1};
  glUseProgram(r.text_program);
  glBindVertexArray(r.text_vao);
  glBindBuffer(GL_ARRAY_BUFFER, r.text_vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STREAM_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 4 * sizeof(float), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 4 * sizeof(float),
                        reinterpret_cast<void*>(2 * sizeof(float)));
  glUniformMatrix4fv(glGetUniformLocation(r.text_program, "pixels"), 1, GL_FALSE,
                     pixel_matrix(width, height).data());
  glUniform3f(glGetUniformLocation(r.text_program, "ink"), color.x(), color.y(), color.z());
  glUniform1i(glGetUniformLocation(r.text_program, "coverage"), 0);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDrawArrays(GL_TRIANGLES, 0, 6);
  glDisable(GL_BLEND);
}

float GlPainter::text_size(int height) const {
  return std::clamp(static_cast<float>(height) / 34.0f, 9.0f * pixel_scale_, 64.0f * pixel_scale_);
}

float GlPainter::heading_band(int height) const {
  return 2.4f * text_size(height);
}

void GlPainter::heading(const std::string& title, int width, int height) {
  const float margin = 0.5f * text_size(height);
  const float room = static_cast<float>(width) - 2.0f * margin;
  const float least = 7.0f * pixel_scale_;  // smaller than this is no longer legible
  float px = 1.3f * text_size(height);
  const Font& font = Font::standard();
  // Shrunk to fit the width; where even the least legible size is too wide, shortened with an
  // ellipsis rather than cut off by the image's edge.
  // The width is not quite proportional to the size (glyphs fall on whole pixels): shrunk again
  // until it fits, each time by at least half a per cent.
  for (float w = font.width(title, px); w > room && px > least; w = font.width(title, px))
    px = std::max(least, std::min(0.995f * px, px * room / w));
  // (A title that fits once shrunk is drawn whole: it was cut before when the ellipsis alone
  // would not have fitted beside it.)
  std::string shown = title;
  if (!title.empty() && font.width(title, px) > room) do {
      shown.pop_back();
      while (!shown.empty() && (static_cast<unsigned char>(shown.back()) & 0xC0) == 0x80)
        shown.pop_back();  // a whole UTF-8 sequence at a time
      if (shown.empty()) return;
    } while (font.width(shown + "\u2026", px) > room);
  text(shown == title ? title : shown + "\u2026", margin, margin, px, Rgb(0.1f, 0.1f, 0.1f), width,
       height);
}

void GlPainter::legend(const Legend& legend, int width, int height) {
  const float w = static_cast<float>(width), h = static_cast<float>(height);
  const Ticks ticks = readable_ticks(legend.lo, legend.hi, legend.unit, 5);
  const float margin = 0.5f * text_size(height);
  const float x0 = 0.82f * w, x1 = x0 + std::max(6.0f, 0.022f * w);
  // Labels as large as the pictures' text, smaller when the widest would not fit right of the
  // bar; none at all where even 7 image pixels would not fit (an image a few dozen pixels wide).
  float px = text_size(height);
  const Font& font = Font::standard();
  float widest = font.width(ticks.unit, px) - (x1 - x0) - 0.4f * px;
  for (const auto& l : ticks.labels) widest = std::max(widest, font.width(l, px));
  const float room = w - margin - (x1 + 0.4f * px);
  if (widest > room) px *= room / widest;
  const bool labelled = px >= 7.0f * pixel_scale_;
  if (!labelled) px = text_size(height);
  const float top = heading_band(height) + (labelled ? 2.2f * px : 0.0f);
  const float bottom = h - 1.5f * px - margin;
  if (bottom - top < 4.0f) return;  // no room for a bar
  colour_bar(legend, x0, x1, top, bottom, width, height);
  if (!labelled) return;
  const Rgb ink(0.1f, 0.1f, 0.1f);
  // Five ticks, or the ends and the middle where five would overlap.
  const int step = (bottom - top) / 4.0f >= 1.2f * px ? 1 : 2;
  for (int i = 0; i <= 4; i += step) {
    const float y = bottom - (bottom - top) * static_cast<float>(i) / 4.0f;
    text(ticks.labels[static_cast<size_t>(i)], x1 + 0.4f * px, y - 0.6f * px, px, ink, width,
         height);
  }
  text(ticks.unit, x0, top - 1.8f * px, px, ink, width, height);
}

void GlPainter::colour_bar(const Legend& legend, float x0, float x1, float top, float bottom,
                           int width, int height) {
  std::vector<Vec3> corners;
  std::vector<Rgb> colors;
  constexpr int steps = 64;
  for (int i = 0; i < steps; ++i) {
    const float fa = static_cast<float>(i) / steps, fb = static_cast<float>(i + 1) / steps;
    const float ya = bottom - (bottom - top) * fa, yb = bottom - (bottom - top) * fb;
    const Rgb ca =
        colormap(legend.lo + (legend.hi - legend.lo) * fa, legend.lo, legend.hi, legend.map);
    const Rgb cb =
        colormap(legend.lo + (legend.hi - legend.lo) * fb, legend.lo, legend.hi, legend.map);
    corners.insert(corners.end(), {Vec3(x0, ya, 0), Vec3(x1, ya, 0), Vec3(x1, yb, 0),
                                   Vec3(x0, ya, 0), Vec3(x1, yb, 0), Vec3(x0, yb, 0)});
    colors.insert(colors.end(), {ca, ca, cb, ca, cb, cb});
  }
  pixel_triangles(corners, colors, width, height);
}

void GlPainter::scale_bar(double pixels_per_metre, int width, int height) {
  if (!(pixels_per_metre > 0.0)) return;
  const double want_mm = 0.2 * width / pixels_per_metre * 1e3;
  const double decade = std::pow(10.0, std::floor(std::log10(want_mm)));
  double mm = decade;
  for (double step : {2.0, 5.0, 10.0})
    if (step * decade <= want_mm) mm = step * decade;
  const float px = text_size(height);
  const float len = static_cast<float>(mm * 1e-3 * pixels_per_metre);
  const float x0 = 1.2f * px, bottom = static_cast<float>(height) - 1.2f * px;
  const float top = bottom - 0.35f * px;
  const Rgb ink(0.15f, 0.15f, 0.15f);
  std::vector<Vec3> corners;
  const auto box = [&](float a, float b, float y0, float y1) {
    corners.insert(corners.end(), {Vec3(a, y0, 0), Vec3(b, y0, 0), Vec3(b, y1, 0), Vec3(a, y0, 0),
                                   Vec3(b, y1, 0), Vec3(a, y1, 0)});
  };
  box(x0, x0 + len, top, bottom);                     // the bar
  box(x0, x0 + 0.15f * px, top - 0.5f * px, bottom);  // its end ticks
  box(x0 + len - 0.15f * px, x0 + len, top - 0.5f * px, bottom);
  pixel_triangles(corners, std::vector<Rgb>(corners.size(), ink), width, height);
  char label[32];
  std::snprintf(label, sizeof label, "%g mm", mm);
  text(label, x0, top - 1.8f * px, px, ink, width, height);
}

}  // namespace membra
