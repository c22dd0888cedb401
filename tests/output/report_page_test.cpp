// report.html: what the page holds (the browser test, tests/browser/, opens it for real).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "membra/output/report_page.hpp"

namespace membra {
namespace {

namespace fs = std::filesystem;

ReportPage test_page() {
  ReportPage p;
  p.title = "bowl <test>";
  p.description = "An ellipse & its ring";
  p.report = {{"status", "converged"},
              {"stability", {{"stable", true}}},
              {"shape", {{"height", 81.75}}},
              {"stress", {{"min", -0.00042}, {"max", 1.2}}},
              {"particles", 441}};
  p.pictures = {{"curvature.png", {'P', 'N', 'G'}}};
  p.scene = {
      {"model", "lattice"},
      {"sheet", {{"size", {200, 200}}, {"material", "latex"}}},
      {"protocol",
       {{{"step", "stretch"}, {"lambda", {1.5, 1.0}}},
        {{"step", "impregnate"},
         {"material", "epoxy"},
         {"pattern", {{"union", {{{"ellipse", {}}}, {{"polygon", {}}}, {{"polygon", {}}}}}}}}}}};
  p.stencil_svg = "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"></svg>";
  p.glb = {'g', 'l', 'T', 'F'};
  p.scales = {{"Gaussian curvature", "1/m^2", -600, 600}, {"Stress", "MPa", -1.2, 1.2}};
  p.files = {"report.json", "final.glb"};
  return p;
}

TEST(ReportPage, HoldsTheNumbersWithUnitsThePicturesTheStencilAndTheModel) {
  const std::string html = make_report_page(test_page(), {"var THREE_STUB = '</script>';"});
  EXPECT_NE(html.find("<h1>bowl &lt;test&gt;</h1>"), std::string::npos);  // escaped
  EXPECT_NE(html.find("An ellipse &amp; its ring"), std::string::npos);
  EXPECT_NE(html.find("81.8 mm"), std::string::npos);             // three significant digits
  EXPECT_NE(html.find("\u22120.000420 MPa"), std::string::npos);  // a small stress still in MPa
  EXPECT_NE(html.find("<td>441</td>"), std::string::npos);        // a count as a count
  EXPECT_NE(html.find("<img src=\"data:image/png;base64,UE5H\""), std::string::npos);  // embedded
  EXPECT_NE(html.find("<div class=\"stencil\"><svg"), std::string::npos);  // inline, no XML prolog
  EXPECT_NE(html.find("const MEMBRA_GLB = \"Z2xURg==\""), std::string::npos);  // base64 "glTF"
  // The scripts inline, a "</script" inside them escaped so that it does not end the element.
  EXPECT_NE(html.find("var THREE_STUB = '<\\/script>';"), std::string::npos);
  EXPECT_EQ(html.find("report_files"), std::string::npos);
  EXPECT_EQ(html.find("<script src="), std::string::npos);
  // The inputs beside the results: each step's settings, the pattern in a few words.
  EXPECT_NE(html.find("<th>1. stretch</th><td><code>{&quot;lambda&quot;:[1.5,1.0]}"),
            std::string::npos);
  EXPECT_NE(html.find("pattern: union of 3: 1 ellipse, 2 polygon"), std::string::npos);
  EXPECT_NE(html.find("<details><summary>The whole scene"), std::string::npos);
  EXPECT_NE(html.find("1/m²"), std::string::npos);                // the legend's readable unit
  EXPECT_EQ(html.find("Stable forms found"), std::string::npos);  // absent keys give no row
}

TEST(ReportPage, WithoutThreeJsTheViewIsLeftOutWithANote) {
  const std::string html = make_report_page(test_page(), {}, "No 3-D view: test");
  EXPECT_EQ(html.find("MEMBRA_GLB"), std::string::npos);
  EXPECT_NE(html.find("No 3-D view: test"), std::string::npos);
}

TEST(ReportPage, IsOneFileWithThreeJsInside) {
  const fs::path dir = fs::temp_directory_path() / "membra_report_page_test";
  fs::remove_all(dir);
  {
    OutputSet out(dir);
    stage_report_page(test_page(), out);
    out.commit();
  }
  EXPECT_TRUE(fs::exists(dir / "report.html"));
  EXPECT_FALSE(fs::exists(dir / "report_files"));
  if (fs::exists(three_js_dir() / "three.min.js")) {  // three.js (some 600 kB) is in the page
    EXPECT_GT(fs::file_size(dir / "report.html"), fs::file_size(three_js_dir() / "three.min.js"));
  }
  fs::remove_all(dir);
}

TEST(ReportPage, Base64OfEveryTailLength) {
  EXPECT_EQ(base64({}), "");
  EXPECT_EQ(base64({'f'}), "Zg==");
  EXPECT_EQ(base64({'f', 'o'}), "Zm8=");
  EXPECT_EQ(base64({'f', 'o', 'o'}), "Zm9v");
}

}  // namespace
}  // namespace membra
