// The viewer's control panel (Dear ImGui): one function per section, in the order shown.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "membra/core/units.hpp"
#include "membra/io/scene.hpp"
#include "membra/view/session_files.hpp"
#include "viewer_window_impl.hpp"

namespace membra::viewer {
namespace {

const char* kFamilyNames[] = {"stretch", "shear", "flex", "added"};

}  // namespace

void ViewerWindow::Impl::panel(ViewerSession& s, ViewSettings& v) {
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  int w, h;
  glfwGetWindowSize(window, &w, &h);
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, static_cast<float>(h)));
  ImGui::Begin("membra", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  panel_status(s);

  if (ImGui::CollapsingHeader("Process", ImGuiTreeNodeFlags_DefaultOpen)) panel_process(s, v);
  if (ImGui::CollapsingHeader("K, G, T, D", ImGuiTreeNodeFlags_DefaultOpen)) panel_parameters(s);
  if (ImGui::CollapsingHeader("Tools", ImGuiTreeNodeFlags_DefaultOpen)) panel_tools(s, v);
  if (ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) {
    panel_colors(s, v);
    panel_view(v);
  }
  if (ImGui::CollapsingHeader("Files", ImGuiTreeNodeFlags_DefaultOpen)) panel_files(s, v);
  ImGui::Separator();
  ImGui::TextWrapped("%s", status.c_str());
  ImGui::End();
}

// The scene's name, the stage, the frame rate and whether the sheet has settled.
void ViewerWindow::Impl::panel_status(const ViewerSession& s) {
  ImGui::Text("%s", s.scene().name.c_str());
  ImGui::Text("stage: %s   %.0f fps", stage_name(s.stage()), fps);
  if (s.settled())
    ImGui::Text("settled");
  else
    ImGui::Text("moving: residual %.2e", s.last_slice().residual_relative);
  if (!s.grid_warning().empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.2f, 1.0f));
    ImGui::TextWrapped("warning: %s", s.grid_warning().c_str());
    ImGui::PopStyleColor();
  }
  if (s.crossings().pairs > 0) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.2f, 1.0f));
    ImGui::TextWrapped(
        "the form passes through itself: %s (outlined in magenta); no real sheet takes it there",
        crossing_summary(s.crossings()).c_str());
    ImGui::PopStyleColor();
  }
}

// The protocol buttons, play/pause/step and the live mode.
void ViewerWindow::Impl::panel_process(ViewerSession& s, ViewSettings& v) {
  if (ImGui::Button("Stretch")) report(s.stretch(), "stretched");
  ImGui::SameLine();
  if (ImGui::Button("Impregnate")) report(s.impregnate(), "impregnated");
  ImGui::SameLine();
  if (ImGui::Button("Release")) report(s.release(), "releasing");
  if (ImGui::Button("Play scene")) {
    s.play_scene_protocol();
    status = "playing the scene's protocol";
  }
  ImGui::SameLine();
  if (ImGui::Button("Reset")) {
    s.reset();
    v.camera_fitted = false;
    status = "reset";
  }
  if (ImGui::Button(v.playing ? "Pause" : "Play")) v.playing = !v.playing;
  ImGui::SameLine();
  if (ImGui::Button("Step")) s.advance(v.iterations_per_frame);
  int mode = s.mode() == LiveMode::relax ? 0 : 1;
  ImGui::SameLine();
  if (ImGui::RadioButton("relax", &mode, 0)) s.set_mode(LiveMode::relax);
  ImGui::SameLine();
  if (ImGui::RadioButton("dynamics", &mode, 1)) s.set_mode(LiveMode::dynamics);
}

// The live parameters K, G, T, D and the stretch.
void ViewerWindow::Impl::panel_parameters(ViewerSession& s) {
  LiveParameters p = s.parameters();
  float k = static_cast<float>(p.K / units::N_per_mm), g = static_cast<float>(p.G),
        t = static_cast<float>(p.T), d = static_cast<float>(p.D),
        lx = static_cast<float>(p.lambda.x()), ly = static_cast<float>(p.lambda.y());
  bool changed =
      ImGui::SliderFloat("K N/mm", &k, 0.01f, 10.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
  changed |= ImGui::SliderFloat("G m/s2", &g, 0.0f, 20.0f, "%.2f");
  changed |= ImGui::SliderFloat("T s", &t, 1e-6f, 1e-3f, "%.1e", ImGuiSliderFlags_Logarithmic);
  changed |= ImGui::SliderFloat("D 1/s", &d, 0.0f, 200.0f, "%.1f");
  changed |= ImGui::SliderFloat("lambda x", &lx, 0.5f, 3.0f, "%.2f");
  changed |= ImGui::SliderFloat("lambda y", &ly, 0.5f, 3.0f, "%.2f");
  if (changed) {
    p.K = k * units::N_per_mm;
    p.G = g;
    p.T = t;
    p.D = d;
    p.lambda = Vec2(lx, ly);
    report(s.set_parameters(p), status);
  }
}

// The editing tool, brush and hole sizes, undo/redo.
void ViewerWindow::Impl::panel_tools(ViewerSession& s, ViewSettings& v) {
  int t = static_cast<int>(tool);
  for (int i = 0; i < 6; ++i) {
    if (i % 3) ImGui::SameLine();
    ImGui::RadioButton(kToolNames[i], &t, i);
  }
  tool = static_cast<Tool>(t);
  float brush = static_cast<float>(v.brush_radius / units::mm);
  if (ImGui::SliderFloat("brush mm", &brush, 1.0f, 50.0f, "%.1f"))
    v.brush_radius = brush * units::mm;
  float hole = static_cast<float>(hole_radius / units::mm);
  if (ImGui::SliderFloat("hole mm", &hole, 1.0f, 50.0f, "%.1f")) hole_radius = hole * units::mm;
  if (ImGui::Button("Undo")) report(s.undo() ? "" : "nothing to undo", "undone");
  ImGui::SameLine();
  if (ImGui::Button("Redo")) report(s.redo() ? "" : "nothing to redo", "redone");
}

// The colour map and its range (the first part of the Display section).
void ViewerWindow::Impl::panel_colors(const ViewerSession& s, ViewSettings& v) {
  int c = static_cast<int>(v.color);
  ImGui::RadioButton("stress", &c, 0);
  ImGui::SameLine();
  ImGui::RadioButton("curvature", &c, 1);
  ImGui::SameLine();
  ImGui::RadioButton("pattern", &c, 2);
  if (c != static_cast<int>(v.color)) {
    v.color = static_cast<ColorMode>(c);
    v.range.reset();
  }
  bool manual = v.range.has_value();
  if (ImGui::Checkbox("manual range", &manual)) {
    if (manual) {
      const ColorField f = color_field(s, v.color);
      v.range = std::pair{f.lo, f.hi};
    } else {
      v.range.reset();
    }
  }
  if (v.range) {
    float lo = static_cast<float>(v.range->first), hi = static_cast<float>(v.range->second);
    const float span = std::max(std::abs(lo), std::abs(hi)) * 2.0f + 1e-30f;
    ImGui::DragFloat("lo", &lo, span / 200, 0, 0, "%.3g");
    ImGui::DragFloat("hi", &hi, span / 200, 0, 0, "%.3g");
    if (lo < hi) v.range = std::pair{lo, hi};
  }
}

// 2-D or 3-D, camera fit and what is drawn (the rest of the Display section).
void ViewerWindow::Impl::panel_view(ViewSettings& v) {
  int view = v.flat ? 1 : 0;
  ImGui::RadioButton("3-D", &view, 0);
  ImGui::SameLine();
  ImGui::RadioButton("2-D", &view, 1);
  v.flat = view == 1;
  ImGui::SameLine();
  if (ImGui::Button("Fit camera")) v.camera_fitted = false;
  ImGui::Checkbox("surface", &v.show_surface);
  ImGui::SameLine();
  ImGui::Checkbox("particles", &v.show_particles);
  for (int f = 0; f < 4; ++f) {
    if (f) ImGui::SameLine();
    ImGui::Checkbox(kFamilyNames[f], &v.show_springs[static_cast<size_t>(f)]);
  }
}

// Scene save/load, export and screenshot, each with its path.
void ViewerWindow::Impl::panel_files(ViewerSession& s, ViewSettings& v) {
  char buf[512];
  std::snprintf(buf, sizeof buf, "%s", scene_path.c_str());
  if (ImGui::InputText("scene", buf, sizeof buf)) scene_path = buf;
  if (ImGui::Button("Save scene"))
    guarded([&] {
      save_session_scene(s, scene_path);
      status = "saved " + scene_path;
    });
  ImGui::SameLine();
  if (ImGui::Button("Load scene"))
    guarded([&] {
      s = ViewerSession(load_scene(scene_path));
      v.camera_fitted = false;
      status = "loaded " + scene_path;
    });
  std::snprintf(buf, sizeof buf, "%s", export_path.c_str());
  if (ImGui::InputText("export", buf, sizeof buf)) export_path = buf;
  if (ImGui::Button("Export (.obj .ply .svg .dxf)"))
    guarded([&] {
      export_session(s, export_path);
      status = "wrote " + export_path;
    });
  std::snprintf(buf, sizeof buf, "%s", screenshot_path.c_str());
  if (ImGui::InputText("png", buf, sizeof buf)) screenshot_path = buf;
  if (ImGui::Button("Screenshot")) screenshot_pending = true;
}

}  // namespace membra::viewer
