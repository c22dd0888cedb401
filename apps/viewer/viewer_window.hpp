#pragma once
// The viewer's window: GLFW + OpenGL 3.3 + Dear ImGui. It draws the session (3-D or 2-D view,
// colours, springs, particles, legend), turns mouse and keys into session edits and camera
// moves, and shows the control panel. The logic it calls lives in the view library.
#include <array>
#include <memory>
#include <string>

#include "membra/render/renderer.hpp"
#include "membra/view/view_settings.hpp"
#include "membra/view/viewer_session.hpp"

namespace membra::viewer {

// The mouse in one frame: position in framebuffer pixels (origin top-left), buttons (left,
// right, middle), wheel, Shift, and whether the panel has it.
struct Pointer {
  double x = 0.0, y = 0.0;
  std::array<bool, 3> down{false, false, false};
  double wheel = 0.0;
  bool shift = false;
  bool over_panel = false;
};

class ViewerWindow {
 public:
  // Opens a width x height window (hidden when !visible). Throws RenderError when no display or
  // no OpenGL 3.3 is available.
  ViewerWindow(int width, int height, bool visible);
  ~ViewerWindow();
  ViewerWindow(const ViewerWindow&) = delete;
  ViewerWindow& operator=(const ViewerWindow&) = delete;

  bool should_close() const;
  // Polls events, advances the live simulation when `simulate`, draws one frame (panel
  // included) and, when `capture`, reads it back before showing it.
  void frame(ViewerSession& session, ViewSettings& settings, bool simulate, Image* capture);
  // The last status line (messages from the session and the panel).
  const std::string& status() const;
  // Where the panel's Load/Save buttons point.
  void set_scene_path(const std::string& path);
  // The editing tool (orbit, paint, erase, cut, hole, pin); false for an unknown name.
  bool set_tool(const std::string& name);
  // The hole tool's radius, m.
  void set_hole_radius(double metres);
  // Uses `pointer` instead of the real mouse in the next frame (scripts drive the same code).
  void inject(const Pointer& pointer);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace membra::viewer
