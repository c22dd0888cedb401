#include "membra/output/report_page.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "membra/core/readable_units.hpp"
#include "membra/version.hpp"

#ifndef MEMBRA_THREE_JS_DIR
#define MEMBRA_THREE_JS_DIR "/usr/share/javascript/three"
#endif

namespace membra {
namespace fs = std::filesystem;
namespace {

// The three.js files the page inlines, as found in Debian's libjs-three.
constexpr const char* kScripts[] = {"three.min.js", "examples/js/loaders/GLTFLoader.js",
                                    "examples/js/controls/OrbitControls.js"};

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A value of report.json at `pointer`, or null.
const nlohmann::json* at(const nlohmann::json& j, const std::string& pointer) {
  const nlohmann::json::json_pointer p(pointer);
  return j.contains(p) ? &j.at(p) : nullptr;
}

std::string number(double v, const std::string& unit) {
  if (unit.empty() && v == std::round(v) && std::abs(v) < 1e15) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.0f", v);  // counts as counts
    return buf;
  }
  const DisplayUnit d = readable_unit(unit, std::abs(v));
  // A step of a tenth of the value: three significant digits.
  const std::string text = format_number(v * d.factor, std::abs(v * d.factor) * 0.1);
  return d.unit.empty() ? text : text + " " + d.unit;
}

// One row of the key numbers: label, value (formatted, with unit), what it means.
struct Row {
  const char* label;
  const char* pointer;
  const char* unit;  // "" for a dimensionless number, "text" for a string or flag
  const char* meaning;
};
constexpr Row kRows[] = {
    {"Status", "/status", "text", "converged, not_converged or diverged"},
    {"Stable", "/stability/stable", "text", "a minimum of the energy (false: a saddle)"},
    {"Passes through itself", "/self_intersection/pairs", "",
     "triangle pairs that cross: no self-contact in the model, so 0 for a physical form"},
    {"Form", "/curvature/global/classification", "text",
     "of the global form, wrinkles averaged out"},
    {"Quadric", "/shape/quadric/classification", "text",
     "of the whole sheet's best-fit quadric (bowl: synclastic)"},
    {"Size x", "/shape/size/0", "mm", "overall, in the reading pose (docs/outputs.md)"},
    {"Size y", "/shape/size/1", "mm", "overall"},
    {"Size z", "/shape/size/2", "mm", "overall: the piece's height on a table"},
    {"Quadric radius 1", "/shape/quadric/radii_mm/0", "mm", "its more curved principal radius"},
    {"Quadric radius 2", "/shape/quadric/radii_mm/1", "mm",
     "negative: curving the other way, a saddle"},
    {"Quadric k1", "/shape/quadric/k1", "1/m", "its larger principal curvature"},
    {"Quadric k2", "/shape/quadric/k2", "1/m", "1/radius 2"},
    {"Height", "/shape/height", "mm", "rise of the sheet above its lowest point"},
    {"Global height", "/shape/global_height", "mm", "of the window-averaged form"},
    {"Total Gaussian curvature", "/curvature/total", "", "∫K dA (rad); 2π is a closed cap"},
    {"Global total curvature", "/curvature/global/total", "", "of the window-averaged form (rad)"},
    {"Stress, min", "/stress/min", "MPa", "compression < 0"},
    {"Stress, max", "/stress/max", "MPa", "tension > 0"},
    {"Energy", "/energy", "J", "elastic + bending + gravitational"},
    {"Design error (rms)", "/design/rms_error", "%", "of the target's diameter"},
    {"Design verdict", "/design/verdict", "text", "against the goal and a flat sheet"},
    {"Curvature map correlation", "/curvature_map/correlation", "", "target against measured"},
    {"Stable forms found", "/explore/distinct_forms", "", "distinct forms of simulation.explore"},
    {"Solver", "/solver", "text", ""},
    {"Particles", "/particles", "", ""},
    {"Iterations", "/iterations", "", ""},
    {"Wall time", "/wall_seconds", "s", ""},
};

std::string key_numbers(const nlohmann::json& report) {
  std::ostringstream h;
  h << "<table class=\"numbers\">\n";
  for (const Row& row : kRows) {
    const nlohmann::json* v = at(report, row.pointer);
    if (!v || v->is_null()) continue;
    std::string value;
    if (std::string(row.pointer) == "/stability/stable" &&
        !report.value(nlohmann::json::json_pointer("/stability/checked"), true))
      value = "not checked";
    else if (v->is_number() && std::string(row.unit) != "text")
      value = number(v->get<double>(), row.unit);
    else
      value = v->is_string() ? v->get<std::string>() : v->dump();
    h << "<tr><th>" << row.label << "</th><td>" << html_escape(value) << "</td><td class=\"note\">"
      << html_escape(row.meaning) << "</td></tr>\n";
  }
  h << "</table>\n";
  return h.str();
}

// A colour bar as a CSS gradient with five readable labels under it.
std::string scale_html(const ColourScale& s, size_t index) {
  std::ostringstream h;
  h << "<div class=\"scale\" data-scale=\"" << index << "\"" << (index ? " hidden" : "") << ">"
    << "<div class=\"scale-title\">" << html_escape(s.title) << "</div><div class=\"bar\" "
    << "style=\"background: linear-gradient(to right";
  for (int i = 0; i <= 10; ++i) {
    const Rgb c = colormap(s.lo + (s.hi - s.lo) * i / 10.0, s.lo, s.hi, s.map);
    const auto byte = [](float v) { return static_cast<int>(std::lround(v * 255.0f)); };
    h << ", rgb(" << byte(c.x()) << "," << byte(c.y()) << "," << byte(c.z()) << ")";
  }
  h << ")\"></div><div class=\"ticks\">";
  const Ticks t = readable_ticks(s.lo, s.hi, s.unit, 5);
  for (const auto& l : t.labels) h << "<span>" << html_escape(l) << "</span>";
  h << "</div><div class=\"scale-unit\">" << html_escape(t.unit) << "</div></div>";
  return h.str();
}

const char* kStyle = R"(
body { font-family: "DejaVu Sans", system-ui, sans-serif; margin: 1.5em auto; max-width: 1200px;
       padding: 0 1em; color: #1a1a1a; }
h1 { margin-bottom: 0.2em; } .sub { color: #555; margin-top: 0; }
.top { display: flex; gap: 1.5em; flex-wrap: wrap; align-items: flex-start; }
#view { flex: 1 1 560px; min-width: 320px; } #view canvas { width: 100%; height: 480px;
  border: 1px solid #ddd; border-radius: 4px; display: block; cursor: grab; }
.controls { margin: 0.4em 0; } .numbers { border-collapse: collapse; flex: 1 1 360px; }
.numbers th { text-align: left; padding: 0.25em 0.8em 0.25em 0; font-weight: 600; }
.numbers td { padding: 0.25em 0.8em 0.25em 0; } .note { color: #777; font-size: 0.85em; }
.scale { max-width: 420px; } .bar { height: 14px; border: 1px solid #bbb; }
.ticks { display: flex; justify-content: space-between; font-size: 0.85em; }
.scale-title, .scale-unit { font-size: 0.9em; color: #333; }
.pictures { display: grid; grid-template-columns: repeat(auto-fill, minmax(360px, 1fr)); gap: 1em; }
.pictures figure { margin: 0; } .pictures img { width: 100%; border: 1px solid #eee; }
.stencil svg { max-width: 100%; height: auto; border: 1px solid #eee; }
#errors, .warning { color: #a00; white-space: pre-wrap; } .files li { font-family: monospace; }
.inputs th { text-align: left; padding: 0.2em 0.8em 0.2em 0; vertical-align: top; }
.inputs code { white-space: pre-wrap; word-break: break-all; font-size: 0.85em; }
details pre { font-size: 0.8em; max-height: 24em; overflow: auto; background: #f7f7f7; }
)";

// The 3-D view: parses the inlined final.glb with three.js's GLTFLoader, turns membra's z-up
// into three.js's y-up, frames the form from membra's default camera direction, and switches the
// vertex colours between COLOR_0 (curvature) and COLOR_1 (stress). Sets data-view="ready" and
// data-view-rect (the canvas on the page, CSS pixels) on <body> after the first frame, and lists
// any error on the page (the browser test reads them).
const char* kViewScript = R"(
(function () {
  const errors = [];
  function fail(message) {
    errors.push(String(message));
    const box = document.getElementById('errors');
    box.textContent = errors.join('\n');
    box.hidden = false;
    document.body.dataset.errors = String(errors.length);
  }
  window.addEventListener('error', function (e) { fail(e.message); });
  window.addEventListener('unhandledrejection', function (e) { fail(e.reason); });
  if (typeof THREE === 'undefined' || !THREE.GLTFLoader || !THREE.OrbitControls) {
    fail('3-D view: the inlined three.js did not load');
    return;
  }
  const canvas = document.getElementById('view-canvas');
  let renderer;
  try {
    renderer = new THREE.WebGLRenderer({canvas: canvas, antialias: true, preserveDrawingBuffer: true});
  } catch (e) { fail('3-D view: WebGL is not available in this browser (' + e.message + ')'); return; }
  renderer.gammaOutput = true;
  renderer.gammaFactor = 2.2;
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xffffff);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x80858f, 0.85));
  const sun = new THREE.DirectionalLight(0xffffff, 0.55);
  sun.position.set(-1, 3, 2);
  scene.add(sun);
  const camera = new THREE.PerspectiveCamera(25, 1, 1, 1e6);
  const controls = new THREE.OrbitControls(camera, canvas);
  function draw() { renderer.render(scene, camera); }
  function resize() {
    const w = canvas.clientWidth, h = canvas.clientHeight;
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setSize(w, h, false);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    draw();
  }
  controls.addEventListener('change', function () {
    // Clipping planes that follow the zoom, so that the form is never cut off.
    const d = camera.position.distanceTo(controls.target);
    camera.near = d / 100;
    camera.far = d * 100;
    camera.updateProjectionMatrix();
    draw();
  });
  window.addEventListener('resize', resize);
  const bytes = Uint8Array.from(atob(MEMBRA_GLB), function (c) { return c.charCodeAt(0); });
  new THREE.GLTFLoader().parse(bytes.buffer, '', function (gltf) {
    const root = gltf.scene;
    scene.add(root);
    // One mesh per material (latex, resin), each with both colourings.
    const meshes = [];
    root.traverse(function (o) { if (o.isMesh) meshes.push(o); });
    if (!meshes.length) { fail('final.glb holds no mesh'); return; }
    const colours = meshes.map(function (m) {
      m.material.side = THREE.DoubleSide;
      return [m.geometry.getAttribute('color'), m.geometry.getAttribute('color_1')];
    });
    root.updateMatrixWorld(true);
    const sphere = new THREE.Box3().setFromObject(root).getBoundingSphere(new THREE.Sphere());
    function home() {
      // membra's default camera: azimuth -60 deg, elevation 35 deg, in three.js's axes.
      const az = -60 * Math.PI / 180, el = 35 * Math.PI / 180;
      const dir = new THREE.Vector3(Math.cos(el) * Math.cos(az), Math.sin(el),
                                    -Math.cos(el) * Math.sin(az));
      const d = sphere.radius / Math.sin(camera.fov * Math.PI / 360) * 0.7;
      camera.position.copy(sphere.center).addScaledVector(dir, d);
      camera.near = d / 100;  // final.glb is in metres: clip planes at the form's own scale
      camera.far = d * 100;
      camera.updateProjectionMatrix();
      controls.target.copy(sphere.center);
      controls.update();
    }
    document.getElementById('home').onclick = function () { home(); draw(); };
    document.querySelectorAll('input[name=colour]').forEach(function (input) {
      input.onchange = function () {
        const i = Number(input.value);
        meshes.forEach(function (m, k) {
          if (colours[k][i]) m.geometry.setAttribute('color', colours[k][i]);
        });
        document.querySelectorAll('.scale').forEach(function (s) {
          s.hidden = s.dataset.scale !== input.value;
        });
        draw();
      };
    });
    home();
    resize();
    requestAnimationFrame(function () {
      draw();
      const r = canvas.getBoundingClientRect();
      document.body.dataset.viewRect =
          [r.left + window.scrollX, r.top + window.scrollY, r.width, r.height].join(',');
      document.body.dataset.view = 'ready';
    });
  }, function (e) { fail('final.glb: ' + (e && e.message ? e.message : e)); });
})();
)";

// A pattern in a few words: "union of 25: 1 ellipse, 24 polygon".
std::string pattern_summary(const nlohmann::json& p) {
  if (!p.is_object() || p.empty()) return p.dump();
  const std::string kind = p.begin().key();
  const nlohmann::json& body = p.begin().value();
  if ((kind != "union" && kind != "difference") || !body.is_array()) {
    if (kind == "image" && body.is_object() && body.contains("file"))
      return "image " + body["file"].get<std::string>();
    return kind;
  }
  std::map<std::string, int> kinds;
  for (const auto& part : body)
    if (part.is_object() && !part.empty()) ++kinds[part.begin().key()];
  std::string out = kind + " of " + std::to_string(body.size()) + ":";
  for (const auto& [k, n] : kinds) out += " " + std::to_string(n) + " " + k + ",";
  out.pop_back();
  return out;
}

// The scene's inputs beside the results: the sheet, the model and its grid or mesh, the
// simulation, each protocol step's settings (a pattern in a few words: the stencil below draws
// it), and the whole scene as written.
std::string inputs_html(const nlohmann::json& scene) {
  if (!scene.is_object()) return "";
  std::ostringstream h;
  h << "<h2>Inputs</h2>\n<table class=\"inputs\">\n";
  const auto row = [&](const std::string& label, const std::string& value) {
    h << "<tr><th>" << html_escape(label) << "</th><td><code>" << html_escape(value)
      << "</code></td></tr>\n";
  };
  row("model", scene.value("model", "lattice"));
  for (const char* key : {"sheet", "mesh", "simulation"})
    if (scene.contains(key)) row(key, scene[key].dump());
  if (scene.contains("protocol"))
    for (size_t i = 0; i < scene["protocol"].size(); ++i) {
      nlohmann::json step = scene["protocol"][i];
      const std::string kind = step.value("step", "?");
      step.erase("step");
      std::string pattern;
      if (step.contains("pattern")) {
        pattern = "; pattern: " + pattern_summary(step["pattern"]);
        step.erase("pattern");
      }
      row(std::to_string(i + 1) + ". " + kind, step.dump() + pattern);
    }
  h << "</table>\n<details><summary>The whole scene (run it again with <code>membra run</code>)"
    << "</summary><pre>" << html_escape(scene.dump(2)) << "</pre></details>\n";
  return h.str();
}

std::string view_html(const ReportPage& page) {
  std::ostringstream h;
  h << "<div id=\"view\"><canvas id=\"view-canvas\"></canvas>\n<div class=\"controls\">Colour: ";
  for (size_t i = 0; i < page.scales.size(); ++i)
    h << "<label><input type=\"radio\" name=\"colour\" value=\"" << i << "\""
      << (i ? "" : " checked") << "> " << html_escape(page.scales[i].title) << "</label> ";
  h << "<button id=\"home\">Reset view</button> <span class=\"note\">drag to turn, wheel to "
       "zoom, right-drag to move</span></div>\n";
  for (size_t i = 0; i < page.scales.size(); ++i) h << scale_html(page.scales[i], i) << "\n";
  h << "</div>\n";
  return h.str();
}

}  // namespace

fs::path three_js_dir() {
  const char* env = std::getenv("MEMBRA_THREE_JS");
  return env && *env ? fs::path(env) : fs::path(MEMBRA_THREE_JS_DIR);
}

std::string html_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string base64(const std::vector<std::uint8_t>& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const unsigned b0 = bytes[i], b1 = i + 1 < bytes.size() ? bytes[i + 1] : 0,
                   b2 = i + 2 < bytes.size() ? bytes[i + 2] : 0;
    const unsigned v = (b0 << 16) | (b1 << 8) | b2;
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? digits[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? digits[v & 63] : '=';
  }
  return out;
}

std::string make_report_page(const ReportPage& page, const std::vector<std::string>& scripts,
                             const std::string& note) {
  const bool with_view = !scripts.empty() && !page.glb.empty();
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>"
    << html_escape(page.title) << " — membra</title>\n<style>" << kStyle << "</style>\n</head>\n"
    << "<body>\n<h1>" << html_escape(page.title) << "</h1>\n";
  if (!page.description.empty())
    h << "<p class=\"sub\">" << html_escape(page.description) << "</p>\n";
  h << "<p class=\"note\">membra " << kVersion << ". Lengths in mm; every number is also in "
    << "<a href=\"report.json\">report.json</a>.</p>\n<pre id=\"errors\" hidden></pre>\n";
  if (!page.note.empty()) h << "<p class=\"warning\">" << html_escape(page.note) << "</p>\n";
  h << "<div class=\"top\">\n";
  if (with_view)
    h << view_html(page);
  else if (!note.empty())
    h << "<p class=\"note\">" << html_escape(note) << "</p>\n";
  h << key_numbers(page.report) << "</div>\n" << inputs_html(page.scene);
  if (!page.pictures.empty()) {
    h << "<h2>Pictures</h2>\n<div class=\"pictures\">\n";
    for (const auto& p : page.pictures) {
      const std::string e = html_escape(p.name);
      h << "<figure><img src=\"data:image/png;base64," << base64(p.png) << "\" alt=\"" << e
        << "\"><figcaption>" << e << "</figcaption></figure>\n";
    }
    h << "</div>\n";
  }
  if (!page.stencil_svg.empty()) {
    const size_t at = page.stencil_svg.find("<svg");
    h << "<h2>Stencil</h2>\n<p class=\"note\">At true scale in <a href=\"pattern.svg\">pattern.svg"
      << "</a> and <a href=\"pattern.dxf\">pattern.dxf</a> (mm), for the laser cutter.</p>\n"
      << "<div class=\"stencil\">" << (at == std::string::npos ? "" : page.stencil_svg.substr(at))
      << "</div>\n";
  }
  if (!page.files.empty()) {
    h << "<h2>Files</h2>\n<ul class=\"files\">\n";
    for (const auto& f : page.files)
      h << "<li><a href=\"" << html_escape(f) << "\">" << html_escape(f) << "</a></li>\n";
    h << "</ul>\n";
  }
  if (with_view) {
    // Inlined: "</script" inside a script would end it early.
    for (std::string js : scripts) {
      for (size_t at = js.find("</script"); at != std::string::npos; at = js.find("</script", at))
        js.replace(at, 2, "<\\/");
      h << "<script>\n" << js << "\n</script>\n";
    }
    h << "<script>const MEMBRA_GLB = \"" << base64(page.glb) << "\";\n"
      << kViewScript << "</script>\n";
  }
  h << "</body>\n</html>\n";
  return h.str();
}

void stage_report_page(const ReportPage& page, OutputSet& out) {
  std::string note = page.glb.empty() ? "No 3-D view: the run wrote no final.glb." : "";
  std::vector<std::string> scripts;
  const fs::path dir = three_js_dir();
  for (const char* s : kScripts) {
    if (page.glb.empty()) break;
    if (!fs::is_regular_file(dir / s)) {
      scripts.clear();
      note = "No 3-D view: three.js was not found at " + (dir / s).string() +
             " (install Debian's libjs-three, or set MEMBRA_THREE_JS to its folder).";
      break;
    }
    scripts.push_back(read_text(dir / s));
  }
  const std::string html = make_report_page(page, scripts, note);
  out.add("report.html", [&](std::ostream& os) { os << html; });
}

ReportPage page_from_staged(const OutputSet& out, const std::string& title,
                            const std::string& description, std::vector<ColourScale> scales,
                            const std::string& note) {
  ReportPage page;
  page.note = note;
  page.title = title;
  page.description = description;
  page.scales = std::move(scales);
  if (const fs::path f = out.staged("report.json"); !f.empty())
    page.report = nlohmann::json::parse(read_text(f), nullptr, false);
  if (const fs::path f = out.staged("final.glb"); !f.empty()) {
    const std::string bytes = read_text(f);
    page.glb.assign(bytes.begin(), bytes.end());
  }
  if (const fs::path f = out.staged("pattern.svg"); !f.empty()) page.stencil_svg = read_text(f);
  // The pictures in the order a reader wants them: the form first, then the rest as staged
  // (branches/N/curvature.png among them); the frames are in the contact sheet.
  for (const char* p : {"curvature.png", "views.png", "curvature_global.png", "stress.png",
                        "comparison.png", "comparison_density.png", "density.png",
                        "curvature_map.png", "contact_sheet.png", "pattern.png"})
    if (!out.staged(p).empty()) page.pictures.push_back({p, {}});
  for (const auto& name : out.names())
    if (name.starts_with("branches/") && name.ends_with(".png"))
      page.pictures.push_back({name, {}});
  for (PagePicture& p : page.pictures) {
    const std::string bytes = read_text(out.staged(p.name));
    p.png.assign(bytes.begin(), bytes.end());
  }
  page.files = out.names();
  page.files.push_back("report.html");
  return page;
}

}  // namespace membra
