#pragma once
// report.html: one page per output directory (run, design; a sweep's is written by the Python
// module) that says what is in it — the scene's name and description, the key numbers with
// units, the pictures, the stencil inline, and an interactive 3-D view of final.glb built on
// three.js (Debian's libjs-three), copied beside the page so that it works offline from a
// file:// URL. The model is inlined as base64 because browsers refuse to fetch a file:// URL.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "membra/measure/colormap.hpp"
#include "membra/output/output_set.hpp"

namespace membra {

struct ColourScale {
  std::string title, unit;  // unit of lo and hi, e.g. "1/mm^2" (shown readable)
  double lo = 0.0, hi = 1.0;
};

struct ReportPage {
  std::string title, description;
  nlohmann::json report;              // the directory's report.json
  std::vector<std::string> pictures;  // PNG files beside the page, in display order
  std::string stencil_svg;            // pattern.svg's text, or empty
  std::vector<std::uint8_t> glb;      // final.glb's bytes, or empty: no 3-D view
  std::vector<ColourScale> scales;    // COLOR_0, COLOR_1 of the glb
  std::vector<std::string> files;     // every file of the directory, linked
  std::string note;  // shown at the top in red: why pictures are missing, a divergence
};

// Where the three.js files are read from: $MEMBRA_THREE_JS when set, else Debian's
// /usr/share/javascript/three (the compiled-in MEMBRA_THREE_JS_DIR).
std::filesystem::path three_js_dir();

// The page's HTML; `with_view` false leaves the 3-D view out with a note saying why.
std::string make_report_page(const ReportPage& page, bool with_view, const std::string& note = {});

// Stages report.html and, when three.js is found and the page has a model, its three scripts
// under report_files/.
void stage_report_page(const ReportPage& page, OutputSet& out);

// The page of an output set whose report.json, final.glb, pattern.svg and pictures are staged:
// reads them back from the staged files.
ReportPage page_from_staged(const OutputSet& out, const std::string& title,
                            const std::string& description, std::vector<ColourScale> scales,
                            const std::string& note = {});

std::string base64(const std::vector<std::uint8_t>& bytes);
std::string html_escape(const std::string& text);

}  // namespace membra
