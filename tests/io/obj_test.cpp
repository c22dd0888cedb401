// OBJ targets: what is read, and every malformed line named.
#include <gtest/gtest.h>

#include <sstream>

#include "membra/core/input_error.hpp"
#include "membra/io/obj.hpp"

namespace membra {
namespace {

TEST(ObjReader, ReadsVerticesInMmAndSplitsPolygonsIntoFans) {
  std::istringstream in(
      "# a quad and a triangle\nv 0 0 0\nv 10 0 0\nv 10 10 0\nv 0 10 5\nvn 0 0 1\n"
      "f 1/1/1 2/2/1 3/3/1 4/4/1\nf -1 -3 -2\n");
  const ObjMesh m = read_obj(in, "t.obj");
  ASSERT_EQ(m.x.cols(), 4);
  EXPECT_DOUBLE_EQ(m.x(2, 3), 0.005);
  ASSERT_EQ(m.triangles.size(), 3u);
  EXPECT_EQ(m.triangles[1], Triangle(0, 2, 3));
  EXPECT_EQ(m.triangles[2], Triangle(3, 1, 2));
}

// The form's OBJ: normals, the flat sheet's texture coordinates, latex and resin groups; it
// reads back as the same mesh.
TEST(ObjWriter, WritesNormalsTextureCoordinatesAndMaterialGroups) {
  Points x(3, 4);
  x << 0, 0.01, 0.01, 0, 0, 0, 0.01, 0.01, 0, 0, 0, 0;
  const std::vector<Triangle> tris{Triangle(0, 1, 2), Triangle(0, 2, 3)};
  std::ostringstream out;
  write_obj(out, x, tris, ObjLayers{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {false, true}, "final.mtl"});
  const std::string text = out.str();
  EXPECT_NE(text.find("mtllib final.mtl\n"), std::string::npos);
  EXPECT_NE(text.find("vn 0.000000 0.000000 1.000000\n"), std::string::npos);  // flat, +z
  EXPECT_NE(text.find("vt 1.00000000 1.00000000\n"), std::string::npos);
  EXPECT_NE(text.find("g latex\nusemtl latex\nf 1/1/1 2/2/2 3/3/3\n"), std::string::npos);
  EXPECT_NE(text.find("g resin\nusemtl resin\nf 1/1/1 3/3/3 4/4/4\n"), std::string::npos);
  std::istringstream in(text);
  const ObjMesh m = read_obj(in, "final.obj");
  EXPECT_LT((m.x - x).cwiseAbs().maxCoeff(), 1e-15);
  ASSERT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.triangles[1], tris[1]);
  std::ostringstream mtl;
  write_mtl(mtl);
  EXPECT_NE(mtl.str().find("newmtl latex"), std::string::npos);
  EXPECT_NE(mtl.str().find("newmtl resin"), std::string::npos);
  EXPECT_THROW(write_obj(out, x, tris, ObjLayers{{}, {false, true}, ""}), std::invalid_argument);
}

TEST(ObjReader, NamesTheLineOfEachProblem) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"v 0 0\nf 1 1 1\n", "line 1: a vertex needs x y z"},
      {"v 0 0 nan\n", "line 1: 'nan' is not a finite number"},
      {"v 0 0 1e999\n", "is not a finite number"},
      {"v 0 0 0\nf 1 2 3\n", "line 2: vertex index 2 is out of range"},
      {"v 0 0 0\nv 1 0 0\nf 1 2\n", "line 3: a face needs at least 3 corners"},
      {"v 0 0 0\nf 1 x 1\n", "'x' is not a vertex index"},
      {"v 0 0 0\nf 0 1 1\n", "'0' is not a vertex index"},
      {"v 0 0 0\n", "no faces"}};
  for (const auto& [text, message] : bad) {
    std::istringstream in(text);
    try {
      read_obj(in, "t.obj");
      FAIL() << text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), "t.obj");
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace membra
