#pragma once
// report.html: one page per output directory (run, design; a sweep's is written by the Python
// module) that says what is in it — the scene's name and description, the key numbers with
// units, the scene's inputs, the pictures, the stencil inline, and an interactive 3-D view of
// final.glb built on three.js (Debian's libjs-three). One self-contained file: the scripts, the
// model (base64: browsers refuse to fetch a file:// URL) and the pictures are all inlined.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "membra/measure/colormap.hpp"
#include "membra/output/output_set.hpp"

namespace membra {

struct ColourScale {
  std::string title, unit;  // unit of lo and hi, e.g. "1/m^2" (shown readable)
  double lo = 0.0, hi = 1.0;
  ColourMap map = ColourMap::diverging;
};

// A picture of the page: its file beside the page, and its bytes, embedded.
struct PagePicture {
  std::string name;
  std::vector<std::uint8_t> png;
};

struct ReportPage {
  std::string title, description;
  nlohmann::json report;              // the directory's report.json
  nlohmann::json scene;               // the scene as written (io/scene_writer), or null
  std::vector<PagePicture> pictures;  // in display order
  std::string stencil_svg;            // pattern.svg's text, or empty
  std::vector<std::uint8_t> glb;      // final.glb's bytes, or empty: no 3-D view
  std::vector<ColourScale> scales;    // COLOR_0, COLOR_1 of the glb
  std::vector<std::string> files;     // every file of the directory, linked
  std::string note;  // shown at the top in red: why pictures are missing, a divergence
};

// Where the three.js files are read from: $MEMBRA_THREE_JS when set, else Debian's
// /usr/share/javascript/three (the compiled-in MEMBRA_THREE_JS_DIR).
std::filesystem::path three_js_dir();

// The page's HTML, one self-contained file: the pictures as data URIs, the model as base64, and
// `scripts` (three.js and its loader and controls) inline. No scripts leave the 3-D view out,
// with `note` saying why.
std::string make_report_page(const ReportPage& page, const std::vector<std::string>& scripts,
                             const std::string& note = {});

// Stages report.html, with three.js inlined when it is found and the page has a model.
void stage_report_page(const ReportPage& page, OutputSet& out);

// The page of an output set whose report.json, final.glb, pattern.svg and pictures are staged:
// reads them back from the staged files.
ReportPage page_from_staged(const OutputSet& out, const std::string& title,
                            const std::string& description, std::vector<ColourScale> scales,
                            const std::string& note = {});

std::string base64(const std::vector<std::uint8_t>& bytes);
std::string html_escape(const std::string& text);

}  // namespace membra
