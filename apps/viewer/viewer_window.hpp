#pragma once
// The viewer's window: GLFW + OpenGL 3.3 + Dear ImGui. It draws the session (3-D or 2-D view,
// colours, springs, particles, legend), turns mouse and keys into session edits and camera
// moves, and shows the control panel. The logic it calls lives in the view library.
#include <memory>
#include <string>

#include "membra/render/renderer.hpp"
#include "membra/view/view_settings.hpp"
#include "membra/view/viewer_session.hpp"

namespace membra::viewer {

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

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace membra::viewer
