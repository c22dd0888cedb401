#include "viewer_window.hpp"

#define GL_GLEXT_PROTOTYPES 1
#define GLFW_INCLUDE_NONE
#include <GL/glcorearb.h>
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

#include "membra/core/input_error.hpp"
#include "membra/core/readable_units.hpp"
#include "membra/core/units.hpp"
#include "membra/io/scene.hpp"
#include "membra/output/output_set.hpp"
#include "membra/view/flat_view.hpp"
#include "membra/view/picking.hpp"
#include "membra/view/session_files.hpp"
#include "viewer_window_impl.hpp"

namespace membra::viewer {
namespace {

// The sheet's box along x, y and z as it stands, "218 x 163 x 81 mm".
std::string overall_size(const Points& x) {
  if (x.cols() == 0) return "";
  const Vec3 size = x.rowwise().maxCoeff() - x.rowwise().minCoeff();
  return box_dimensions(size.x(), size.y(), size.z());
}

const std::array<Rgb, 4> kFamilyColors = {Rgb(0.15f, 0.15f, 0.15f), Rgb(0.45f, 0.45f, 0.7f),
                                          Rgb(0.6f, 0.4f, 0.2f), Rgb(0.0f, 0.5f, 0.5f)};

}  // namespace

void ViewerWindow::Impl::sizes(int& w, int& h) const {
  glfwGetFramebufferSize(window, &w, &h);
}

// Frame coordinates under the mouse at window pixel (px, py), if it is over the sheet.
std::optional<Vec2> ViewerWindow::Impl::frame_point(const ViewerSession& s, const ViewSettings& v,
                                                    double px, double py) const {
  int w, h;
  sizes(w, h);
  const int sw = mesh_width(std::max(1, w - scene_x()));
  if (px < scene_x()) return std::nullopt;
  if (v.flat) return flat_view(s, sw, h).to_frame(px - scene_x(), py);
  const Membrane& m = s.membrane();
  const auto hit = pick(v.camera.ray(px - scene_x(), py, sw, h), m.state.x, m.sheet.triangles);
  if (!hit) return std::nullopt;
  return Vec2(hit->point.head<2>());
}

FlatView ViewerWindow::Impl::flat_view(const ViewerSession& s, int w, int h) {
  FlatView f;
  const Membrane& m = s.membrane();
  f.box.extend(Vec2::Zero());
  f.box.extend(Vec2(m.stretch.x() * m.sheet.grid.width(), m.stretch.y() * m.sheet.grid.height()));
  for (Eigen::Index p = 0; p < m.state.x.cols(); ++p)
    f.box.extend(Vec2(m.state.x.col(p).head<2>()));
  f.width = w;
  f.height = h;
  return f;
}

void ViewerWindow::Impl::fit_camera(const ViewerSession& s, ViewSettings& v) const {
  const Points& x = s.membrane().state.x;
  if (x.cols() == 0) return;
  const Vec3 c = 0.5 * (x.rowwise().minCoeff() + x.rowwise().maxCoeff());
  double r = 1e-9;
  for (Eigen::Index p = 0; p < x.cols(); ++p) r = std::max(r, (x.col(p) - c).norm());
  v.camera.fit(c, r, 1.25);
  v.camera_fitted = true;
}

void ViewerWindow::Impl::apply_tool(ViewerSession& s, const ViewSettings& v, const Vec2& at,
                                    bool first) {
  switch (tool) {
    case Tool::paint:
    case Tool::erase:
      if (first) s.begin_edit();
      report(s.paint(at, v.brush_radius, tool == Tool::erase), "painted");
      break;
    case Tool::hole:
      if (first) report(s.hole(at, hole_radius), "hole punched");
      break;
    case Tool::pin:
      if (first) report(s.toggle_pin(at), "pin toggled");
      break;
    default:
      break;
  }
}

// The mouse as GLFW and ImGui see it, in framebuffer pixels.
Pointer ViewerWindow::Impl::read_pointer() const {
  const ImGuiIO& io = ImGui::GetIO();
  Pointer p;
  glfwGetCursorPos(window, &p.x, &p.y);
  // Window coordinates to framebuffer pixels (equal unless the display scales).
  int fw, fh, ww, wh;
  glfwGetFramebufferSize(window, &fw, &fh);
  glfwGetWindowSize(window, &ww, &wh);
  p.x *= static_cast<double>(fw) / std::max(1, ww);
  p.y *= static_cast<double>(fh) / std::max(1, wh);
  p.down = {glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS,
            glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS,
            glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS};
  p.wheel = io.MouseWheel;
  p.shift = io.KeyShift;
  p.over_panel = io.WantCaptureMouse;
  return p;
}

void ViewerWindow::Impl::handle_mouse(ViewerSession& s, ViewSettings& v, const Pointer& ptr) {
  const double mx = ptr.x, my = ptr.y;
  const double dx = mx - last_x, dy = my - last_y;
  last_x = mx;
  last_y = my;
  if (ptr.over_panel && !dragging) return;
  if (!ptr.over_panel && ptr.wheel != 0.0 && !v.flat) v.camera.zoom(std::pow(1.1, ptr.wheel));

  for (int b : {GLFW_MOUSE_BUTTON_LEFT, GLFW_MOUSE_BUTTON_RIGHT, GLFW_MOUSE_BUTTON_MIDDLE}) {
    const bool down = ptr.down[static_cast<size_t>(b)];
    if (down && !dragging && mx >= scene_x()) {
      dragging = true;
      drag_button = b;
      if (b == GLFW_MOUSE_BUTTON_LEFT && tool != Tool::orbit) {
        if (const auto at = frame_point(s, v, mx, my)) {
          if (tool == Tool::cut) cut_start = cut_end = at;
          apply_tool(s, v, *at, true);
        }
      }
    } else if (!down && dragging && drag_button == b) {
      dragging = false;
      if (tool == Tool::paint || tool == Tool::erase) s.end_edit();
      if (tool == Tool::cut && cut_start && cut_end && b == GLFW_MOUSE_BUTTON_LEFT)
        report(s.cut(*cut_start, *cut_end), "cut");
      cut_start.reset();
      cut_end.reset();
    }
  }
  if (!dragging) return;
  if (drag_button == GLFW_MOUSE_BUTTON_LEFT && tool != Tool::orbit) {
    if (const auto at = frame_point(s, v, mx, my)) {
      if (tool == Tool::cut) cut_end = at;
      if (tool == Tool::paint || tool == Tool::erase) apply_tool(s, v, *at, false);
    }
    return;
  }
  int w, h;
  sizes(w, h);
  if (v.flat) return;
  if (drag_button == GLFW_MOUSE_BUTTON_MIDDLE ||
      (drag_button == GLFW_MOUSE_BUTTON_RIGHT && ptr.shift))
    v.camera.pan(dx, dy, h);
  else
    v.camera.orbit(-0.4 * dx, 0.4 * dy);
}

void ViewerWindow::Impl::handle_keys(ViewerSession& s, ViewSettings& v) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureKeyboard) return;
  if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_Z)) {
    if (io.KeyShift)
      report(s.redo() ? "" : "nothing to redo", "redone");
    else
      report(s.undo() ? "" : "nothing to undo", "undone");
  }
  if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_Y))
    report(s.redo() ? "" : "nothing to redo", "redone");
  if (ImGui::IsKeyPressed(GLFW_KEY_SPACE)) v.playing = !v.playing;
  if (ImGui::IsKeyPressed(GLFW_KEY_R) && !io.KeyCtrl) v.camera_fitted = false;
}

void ViewerWindow::Impl::draw_scene(const ViewerSession& s, ViewSettings& v) {
  int w, h;
  sizes(w, h);
  const int legend_w = std::max(1, w - scene_x());
  const int sw = mesh_width(legend_w);
  glViewport(scene_x(), 0, sw, h);
  const Membrane& m = s.membrane();
  const Points& x = m.state.x;
  // A new stage (stretched, reset, loaded) changes the sheet's size: look at all of it.
  if (!drawn_stage || *drawn_stage != s.stage()) {
    if (s.stage() != Stage::released && s.stage() != Stage::impregnated) v.camera_fitted = false;
    drawn_stage = s.stage();
  }
  if (!v.camera_fitted) fit_camera(s, v);
  Eigen::Matrix4f vp;
  Eigen::Matrix3f rot;
  if (v.flat) {
    vp = flat_view(s, sw, h).view_projection().cast<float>();
    rot = Eigen::Matrix3f::Identity();
  } else {
    vp = v.camera.view_projection(static_cast<double>(sw) / h).cast<float>();
    rot = v.camera.rotation().cast<float>();
  }
  const ColorField field = color_field(s, v.color);
  if (v.show_surface) {
    if (!v.flat) glEnable(GL_DEPTH_TEST);
    painter->mesh(x, m.sheet.triangles, field_colors(field, v.range), vp, rot);
    glDisable(GL_DEPTH_TEST);
  }
  draw_springs_and_particles(m, v, vp);
  draw_frame_and_cut(m, v, vp);
  draw_crossings(s, vp);
  // Both views are orthographic: one scale in the plane of the screen (docs/viewer.md).
  painter->scale_bar(v.flat ? flat_view(s, sw, h).scale() : h / (2.0 * v.camera.half_height), sw,
                     h);
  Legend legend{field.title, field.unit, field.lo, field.hi};
  if (v.range) std::tie(legend.lo, legend.hi) = *v.range;
  glViewport(scene_x(), 0, legend_w, h);
  painter->legend(legend, legend_w, h);
  painter->heading(legend.title + " \u00b7 " + overall_size(x), legend_w, h);
  glViewport(0, 0, w, h);
}

// The springs of the shown families, the pinned particles and (when shown) all particles.
void ViewerWindow::Impl::draw_springs_and_particles(const Membrane& m, const ViewSettings& v,
                                                    const Eigen::Matrix4f& vp) {
  const Points& x = m.state.x;
  const Springs& sp = m.sheet.model.springs;
  for (size_t f = 0; f < 4; ++f) {
    if (!v.show_springs[f]) continue;
    std::vector<Vec3> ends;
    for (int i = 0; i < sp.size(); ++i)
      if (static_cast<size_t>(sp.family[i]) == f) {
        ends.push_back(x.col(sp.a[i]));
        ends.push_back(x.col(sp.b[i]));
      }
    const AddedSprings& added = m.sheet.model.added_springs;
    if (f == static_cast<size_t>(SpringFamily::added))
      for (int i = 0; i < added.size(); ++i) {
        ends.push_back(x.col(added.a[i]));
        ends.push_back(x.col(added.b[i]));
      }
    painter->lines(ends, kFamilyColors[f], vp);
  }
  std::vector<Vec3> pinned, all;
  for (int p = 0; p < m.sheet.model.num_particles(); ++p) {
    if (m.sheet.model.pinned(p)) pinned.push_back(x.col(p));
    if (v.show_particles) all.push_back(x.col(p));
  }
  painter->points(all, Rgb(0.1f, 0.1f, 0.1f), 3.0f, vp);
  painter->points(pinned, Rgb(0.0f, 0.0f, 0.0f), 5.0f, vp);
}

// The triangles of a settled form that pass through each other, outlined over everything (the
// depth test is off) in magenta, which nothing else in the view uses (the colour maps, the
// springs' families, the frame): where the form is not one a real sheet can take.
void ViewerWindow::Impl::draw_crossings(const ViewerSession& s, const Eigen::Matrix4f& vp) {
  painter->outline(s.membrane().state.x, s.membrane().sheet.triangles, s.crossings().triangles,
                   kCrossingColour, vp);
}

// The frame's outline in the 2-D view and the cut being dragged.
void ViewerWindow::Impl::draw_frame_and_cut(const Membrane& m, const ViewSettings& v,
                                            const Eigen::Matrix4f& vp) {
  if (v.flat) {
    // The frame: the stretched sheet's outline.
    const double fw = m.stretch.x() * m.sheet.grid.width(),
                 fh = m.stretch.y() * m.sheet.grid.height();
    painter->lines({Vec3(0, 0, 0), Vec3(fw, 0, 0), Vec3(fw, 0, 0), Vec3(fw, fh, 0), Vec3(fw, fh, 0),
                    Vec3(0, fh, 0), Vec3(0, fh, 0), Vec3(0, 0, 0)},
                   Rgb(0.85f, 0.0f, 0.0f), vp);
  }
  if (cut_start && cut_end)
    painter->lines(
        {Vec3(cut_start->x(), cut_start->y(), 0.0), Vec3(cut_end->x(), cut_end->y(), 0.0)},
        Rgb(0.0f, 0.0f, 0.0f), vp);
}

ViewerWindow::ViewerWindow(int width, int height, bool visible) : impl_(std::make_unique<Impl>()) {
  if (!glfwInit()) throw RenderError("cannot open a window: no display (run under xvfb-run?)");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
  impl_->window = glfwCreateWindow(width, height, "membra", nullptr, nullptr);
  if (!impl_->window) {
    glfwTerminate();
    throw RenderError("cannot create an OpenGL 3.3 core window");
  }
  glfwMakeContextCurrent(impl_->window);
  glfwSwapInterval(0);  // draw as fast as asked; the loop paces itself
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini litter
  ImGui::StyleColorsLight();
  ImGui_ImplGlfw_InitForOpenGL(impl_->window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  impl_->painter = std::make_unique<GlPainter>();
}

ViewerWindow::~ViewerWindow() {
  impl_->painter.reset();
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(impl_->window);
  glfwTerminate();
}

bool ViewerWindow::should_close() const {
  return glfwWindowShouldClose(impl_->window);
}
const std::string& ViewerWindow::status() const {
  return impl_->status;
}
void ViewerWindow::set_scene_path(const std::string& path) {
  impl_->scene_path = path;
}

bool ViewerWindow::set_tool(const std::string& name) {
  for (int i = 0; i < 6; ++i)
    if (name == kToolNames[i]) {
      impl_->tool = static_cast<Tool>(i);
      return true;
    }
  return false;
}

void ViewerWindow::inject(const Pointer& pointer) {
  impl_->injected = pointer;
}

void ViewerWindow::set_hole_radius(double metres) {
  impl_->hole_radius = metres;
}

void ViewerWindow::frame(ViewerSession& session, ViewSettings& settings, bool simulate,
                         Image* capture) {
  Impl& r = *impl_;
  glfwPollEvents();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  const Pointer ptr = r.injected ? *r.injected : r.read_pointer();
  r.injected.reset();
  r.handle_mouse(session, settings, ptr);
  r.handle_keys(session, settings);
  if (simulate && settings.playing) {
    const SliceReport slice =
        session.advance(settings.iterations_per_frame, settings.seconds_per_frame);
    if (!slice.message.empty()) r.status = slice.message;
  }
  r.panel(session, settings);
  ImGui::Render();

  int w, h;
  r.sizes(w, h);
  glViewport(0, 0, w, h);
  glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  r.draw_scene(session, settings);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  Image button_shot;
  if (!capture && r.screenshot_pending) capture = &button_shot;
  if (capture) {
    // The back buffer, before it is shown.
    glReadBuffer(GL_BACK);
    *capture = read_pixels(w, h);
  }
  if (r.screenshot_pending) {
    r.screenshot_pending = false;
    r.guarded([&] {
      write_png(r.screenshot_path, *capture);
      r.status = "wrote " + r.screenshot_path;
    });
  }
  glfwSwapBuffers(r.window);
  const auto now = std::chrono::steady_clock::now();
  const double dt = std::chrono::duration<double>(now - r.last_frame).count();
  r.last_frame = now;
  if (dt > 0.0) r.fps = r.fps == 0.0 ? 1.0 / dt : 0.9 * r.fps + 0.1 / dt;
}

}  // namespace membra::viewer
