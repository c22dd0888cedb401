// final.glb: written with tinygltf, read back with tinygltf.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "membra/core/input_error.hpp"
#include "membra/geometry/grid_sheet.hpp"
#include "membra/geometry/triangulation.hpp"
#include "membra/io/gltf.hpp"

namespace membra {
namespace {

TEST(Gltf, WritesAndReadsBackVerticesColoursAndValues) {
  const GridSheet g({0.03, 0.02, 7, 5});
  GlbSheet s{
      Points(3, g.num_particles()), triangulate(g), {}, {}, {}, {}, {{"name", "test"}}, {}, {}};
  Points flat(3, g.num_particles());
  for (int p = 0; p < g.num_particles(); ++p) {
    const auto [i, j] = g.node(p);
    const Vec2 q = g.position(i, j);
    s.x.col(p) = Vec3(q.x(), q.y(), 0.01 * q.x() * q.y() / 0.0006);
    flat.col(p) = Vec3(q.x(), q.y(), 0.0);
    s.curvature.push_back(1e-5 * (p - 17));
    s.stress.push_back(0.01 * p);
    s.curvature_colors.push_back(colormap(s.curvature.back(), -2e-4, 2e-4));
    s.stress_colors.push_back(colormap(s.stress.back(), -0.35, 0.35));
  }
  s.uv = flat_uv(flat);
  for (size_t t = 0; t < s.triangles.size(); ++t) s.resin.push_back(t % 3 == 0);
  const auto file = std::filesystem::temp_directory_path() / "membra_gltf_test.glb";
  {
    std::ofstream out(file, std::ios::binary);
    write_glb(out, s);
  }
  std::ifstream in(file, std::ios::binary);
  char magic[4];
  in.read(magic, 4);
  EXPECT_EQ(std::string(magic, 4), "glTF");  // binary glTF, not JSON glTF

  const GlbSheet r = read_glb(file);
  ASSERT_EQ(r.x.cols(), s.x.cols());
  EXPECT_LT((r.x - s.x).cwiseAbs().maxCoeff(), 1e-8);  // float metres: 1e-5 mm of 30 mm
  // Two primitives, the latex's triangles first, then the resin's, each in their order.
  std::vector<Triangle> expected;
  std::vector<bool> expected_resin;
  for (const bool resin : {false, true})
    for (size_t t = 0; t < s.triangles.size(); ++t)
      if (s.resin[t] == resin) expected.push_back(s.triangles[t]), expected_resin.push_back(resin);
  ASSERT_EQ(r.triangles.size(), expected.size());
  for (size_t t = 0; t < expected.size(); ++t) EXPECT_EQ(r.triangles[t], expected[t]);
  EXPECT_EQ(r.resin, expected_resin);
  ASSERT_EQ(r.uv.size(), s.uv.size());
  for (size_t p = 0; p < s.uv.size(); ++p) EXPECT_LT((r.uv[p] - s.uv[p]).norm(), 1e-6);
  EXPECT_NEAR(s.uv.back().x(), 1.0, 1e-12);  // the larger side spans 0..1, the other 2/3 of it
  EXPECT_NEAR(s.uv.back().y(), 2.0 / 3.0, 1e-12);
  ASSERT_EQ(r.curvature_colors.size(), s.curvature_colors.size());
  for (size_t p = 0; p < s.curvature_colors.size(); ++p) {
    EXPECT_LT((r.curvature_colors[p] - s.curvature_colors[p]).cwiseAbs().maxCoeff(), 1e-5f);
    EXPECT_LT((r.stress_colors[p] - s.stress_colors[p]).cwiseAbs().maxCoeff(), 1e-5f);
    EXPECT_NEAR(r.curvature[p], s.curvature[p], 1e-6 * std::abs(s.curvature[p]) + 1e-12);
    EXPECT_NEAR(r.stress[p], s.stress[p], 1e-6);
  }
  EXPECT_EQ(r.extras.value("unit", ""), "m");
  EXPECT_EQ(r.extras.value("name", ""), "test");
  std::filesystem::remove(file);
}

TEST(Gltf, ColoursAreLinearInTheFile) {
  // glTF's vertex colours are linear: sRGB 0.5 is stored as 0.214.
  EXPECT_NEAR(srgb_to_linear(0.5f), 0.214f, 1e-3f);
  for (float c : {0.0f, 0.01f, 0.3f, 0.7f, 1.0f})
    EXPECT_NEAR(linear_to_srgb(srgb_to_linear(c)), c, 1e-5f);
}

TEST(Gltf, RefusesMismatchedArraysAndUnreadableFiles) {
  GlbSheet s{Points::Zero(3, 3), {Triangle(0, 1, 2)}, {}, {}, {}, {}, {}, {}, {}};
  std::ostringstream out;
  EXPECT_THROW(write_glb(out, s), InputError);
  s.curvature_colors = s.stress_colors = std::vector<Rgb>(3, Rgb(0.5f, 0.5f, 0.5f));
  s.curvature = s.stress = std::vector<double>(3, 0.0);
  s.resin = {true, false};  // two flags for one triangle
  EXPECT_THROW(write_glb(out, s), InputError);
  const auto file = std::filesystem::temp_directory_path() / "membra_not_a.glb";
  std::ofstream(file) << "not glTF";
  try {
    read_glb(file);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos);
  }
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace membra

namespace membra {
namespace {

// The file itself, read without tinygltf: glTF's y is up, so membra's height z is the second
// coordinate of POSITION, and the accessor carries the min and max glTF requires.
TEST(Gltf, TheFormStandsUprightInGltfAxes) {
  const GridSheet g({0.02, 0.02, 3, 3});
  GlbSheet s{Points(3, g.num_particles()), triangulate(g), {}, {}, {}, {}, {}, {}, {}};
  for (int p = 0; p < g.num_particles(); ++p) {
    const auto [i, j] = g.node(p);
    s.x.col(p) = Vec3(g.position(i, j).x(), g.position(i, j).y(), p == 4 ? 0.005 : 0.0);
  }
  s.curvature_colors = s.stress_colors = std::vector<Rgb>(9, Rgb(0.5f, 0.5f, 0.5f));
  s.curvature = s.stress = std::vector<double>(9, 0.0);
  std::ostringstream out;
  write_glb(out, s);
  const std::string b = out.str();
  const auto u32 = [&](size_t at) {
    std::uint32_t v;
    std::memcpy(&v, b.data() + at, 4);
    return v;
  };
  const nlohmann::json doc = nlohmann::json::parse(b.substr(20, u32(12)));
  const size_t bin = 20 + u32(12) + 8;
  const auto& acc =
      doc["accessors"][doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"].get<int>()];
  const auto& view = doc["bufferViews"][acc["bufferView"].get<int>()];
  float centre[3];
  std::memcpy(centre, b.data() + bin + view.value("byteOffset", 0) + 4 * 3 * 4, sizeof centre);
  EXPECT_FLOAT_EQ(centre[1], 0.005f);   // the raised middle: up is y, in metres (glTF's unit)
  EXPECT_FLOAT_EQ(centre[2], -0.010f);  // membra's y = 10 mm is glTF's z = -0.01 m
  EXPECT_FLOAT_EQ(acc["max"][1].get<float>(), 0.005f);
  EXPECT_FLOAT_EQ(acc["min"][2].get<float>(), -0.020f);
  EXPECT_EQ(doc["asset"]["extras"]["unit"], "m");
}

}  // namespace
}  // namespace membra
