#pragma once
// The viewer window's private state and helpers, shared by viewer_window.cpp (window, GL, frame
// loop, mouse and keys, drawing) and viewer_panel.cpp (the ImGui control panel). Not for use
// outside the viewer.
#include <algorithm>
#include <chrono>
#include <exception>
#include <memory>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "membra/render/gl_painter.hpp"
#include "membra/view/flat_view.hpp"
#include "viewer_window.hpp"

struct GLFWwindow;

namespace membra::viewer {

inline constexpr int kPanelWidth = 330;  // pixels of the control panel on the left

enum class Tool { orbit, paint, erase, cut, hole, pin };
inline constexpr const char* kToolNames[] = {"orbit", "paint", "erase", "cut", "hole", "pin"};

struct ViewerWindow::Impl {
  GLFWwindow* window = nullptr;
  std::unique_ptr<GlPainter> painter;
  std::string status = "ready";
  std::string scene_path = "session.json";
  std::string export_path = "form.obj";
  std::string screenshot_path = "screenshot.png";
  bool screenshot_pending = false;  // the Screenshot button: capture this frame
  Tool tool = Tool::orbit;
  double hole_radius = 0.01;  // m
  // Mouse drag state.
  bool dragging = false;
  int drag_button = -1;
  double last_x = 0, last_y = 0;
  std::optional<Vec2> cut_start, cut_end;  // frame coordinates of a cut being dragged
  // Frame timing, for the panel's frames per second.
  std::chrono::steady_clock::time_point last_frame = std::chrono::steady_clock::now();
  double fps = 0.0;
  std::optional<Stage> drawn_stage;  // the camera is refitted when the stage changes
  std::optional<Pointer> injected;   // a scripted mouse for the next frame

  int scene_x() const { return kPanelWidth; }
  // The framebuffer's size in pixels.
  void sizes(int& w, int& h) const;
  // The sheet is drawn in the left part of the scene area; the legend takes the rest.
  static int mesh_width(int scene_width) { return std::max(1, scene_width * 4 / 5); }

  // Frame coordinates under the mouse at window pixel (px, py), if it is over the sheet.
  std::optional<Vec2> frame_point(const ViewerSession& s, const ViewSettings& v, double px,
                                  double py) const;
  // The 2-D view of the whole sheet and its frame in a w x h viewport.
  static FlatView flat_view(const ViewerSession& s, int w, int h);
  // Points the camera at the sheet's bounding sphere.
  void fit_camera(const ViewerSession& s, ViewSettings& v) const;

  void report(const std::string& why, const std::string& done) {
    status = why.empty() ? done : why;
  }

  // The editing tool's action at frame point `at` (`first`: the press that starts a drag).
  void apply_tool(ViewerSession& s, const ViewSettings& v, const Vec2& at, bool first);
  // The mouse as GLFW and ImGui see it, in framebuffer pixels.
  Pointer read_pointer() const;
  // Turns the mouse into tool edits and camera moves.
  void handle_mouse(ViewerSession& s, ViewSettings& v, const Pointer& ptr);
  // Undo/redo, play/pause and camera refit from the keyboard.
  void handle_keys(ViewerSession& s, ViewSettings& v);

  // The control panel (viewer_panel.cpp), one function per section.
  void panel(ViewerSession& s, ViewSettings& v);
  // The scene's name, the stage, the frame rate and whether the sheet has settled.
  void panel_status(const ViewerSession& s);
  // The protocol buttons, play/pause/step and the live mode.
  void panel_process(ViewerSession& s, ViewSettings& v);
  // The live parameters K, G, T, D and the stretch.
  void panel_parameters(ViewerSession& s);
  // The editing tool, brush and hole sizes, undo/redo.
  void panel_tools(ViewerSession& s, ViewSettings& v);
  // The colour map and its range (the first part of the Display section).
  void panel_colors(const ViewerSession& s, ViewSettings& v);
  // 2-D or 3-D, camera fit and what is drawn (the rest of the Display section).
  void panel_view(ViewSettings& v);
  // Scene save/load, export and screenshot, each with its path.
  void panel_files(ViewerSession& s, ViewSettings& v);

  template <class F>
  void guarded(F&& f) {
    try {
      f();
    } catch (const std::exception& e) {
      status = e.what();
    }
  }

  // The sheet, springs, particles, outlines and legend in the scene area.
  void draw_scene(const ViewerSession& s, ViewSettings& v);
  // The springs of the shown families, the pinned particles and (when shown) all particles.
  void draw_springs_and_particles(const Membrane& m, const ViewSettings& v,
                                  const Eigen::Matrix4f& vp);
  // The frame's outline in the 2-D view and the cut being dragged.
  void draw_frame_and_cut(const Membrane& m, const ViewSettings& v, const Eigen::Matrix4f& vp);
  void draw_crossings(const ViewerSession& s, const Eigen::Matrix4f& vp);
};

}  // namespace membra::viewer
