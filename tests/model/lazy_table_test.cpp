// The lazily built table the shell triangles keep their plans in, and the plans it keeps: equal
// to plan(i) built afresh after every change of the rest state.
#include "membra/model/elements/lazy_table.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <utility>
#include <vector>

#include "element_checks.hpp"
#include "membra/model/elements/shell_triangles.hpp"

namespace membra {
namespace lazy_table_test {

TEST(LazyTable, BuildsOnceUntilClearedAndCopiesCarryTheRows) {
  LazyTable<int> t;
  std::atomic<int> builds{0};
  const auto build = [&] {
    ++builds;
    return std::vector<int>{1, 2, 3};
  };
  // Two threads at once, as the force kernels' ranges: one build.
  std::thread a([&] { EXPECT_EQ(t.get(build).size(), 3u); });
  std::thread b([&] { EXPECT_EQ(t.get(build).size(), 3u); });
  a.join();
  b.join();
  EXPECT_EQ(builds.load(), 1);
  const LazyTable<int> copy = t;
  EXPECT_EQ(copy.get(build)[2], 3);
  EXPECT_EQ(builds.load(), 1);
  t.clear();
  EXPECT_EQ(t.get(build)[0], 1);
  EXPECT_EQ(builds.load(), 2);
  EXPECT_EQ(copy.get(build)[1], 2);  // the copy keeps the rows it had
  EXPECT_EQ(builds.load(), 2);
  LazyTable<int> moved = std::move(t);  // takes the rows along; t builds again if used
  EXPECT_EQ(moved.get(build)[0], 1);
  EXPECT_EQ(builds.load(), 2);
}

// Every kept plan equals the one built now from the members.
void expect_plans_current(const ShellTriangles& s, const char* when) {
  for (int i = 0; i < s.size(); ++i) {
    const ShellTriangles::Plan fresh = s.plan(i);
    const ShellTriangles::Plan& kept = s.planned(i);
    ASSERT_EQ(kept.edges, fresh.edges) << when << " " << i;
    ASSERT_EQ(kept.coef, fresh.coef) << when << " " << i;
    ASSERT_EQ(kept.map, fresh.map) << when << " " << i;
    ASSERT_EQ(kept.form, fresh.form) << when << " " << i;
    ASSERT_EQ(kept.shift, fresh.shift) << when << " " << i;
  }
}

TEST(ShellPlans, FollowTheReleaseTheMeshAndDirectWrites) {
  const TriPatch m = tri_patch(5, 0.002, 0.2);
  ShellTriangles s;
  s.add_mesh(m.triangles, m.x, 1e-3, 0.5);
  expect_plans_current(s, "meshed");
  for (auto& c : s.coat_curvature) c = Eigen::Vector3d(1e-3, 0.0, 2e-3);
  s.invalidate();
  Points stretched = m.x;
  stretched.row(0) *= 1.5;
  s.begin_release(stretched);
  s.update({true, 0.4});  // the latex's plate and the coat's share both move with the release
  expect_plans_current(s, "released to 0.4");
  const Eigen::Matrix3d before = s.planned(0).form;
  s.update({true, 0.9});
  expect_plans_current(s, "released to 0.9");
  EXPECT_NE(s.planned(0).form, before);
  std::vector<bool> keep(static_cast<size_t>(s.size()), true);
  keep[3] = keep[7] = false;
  s.filter(keep);  // new neighbours: free edges where the two went
  expect_plans_current(s, "filtered");
  s.resin[2] = {s.latex[2].metric_inverse, s.latex[2].area, 500.0 * s.latex[2].d, 1.0 / 3.0};
  s.invalidate();  // a stiff neighbour clamps and frees edges around triangle 2
  expect_plans_current(s, "a stiff triangle written directly");
}

}  // namespace lazy_table_test
}  // namespace membra
