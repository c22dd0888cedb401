#pragma once
// Helpers shared by the tests.
#include <filesystem>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

namespace membra {

// A temporary directory path unique to the running test and process (CTest runs tests in
// parallel processes), not yet created.
inline std::filesystem::path unique_temp_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = std::string("membra_") + info->test_suite_name() + "_" + info->name() + "_" +
                     std::to_string(::getpid());
  for (char& c : name)
    if (c == '/') c = '_';
  return std::filesystem::temp_directory_path() / name;
}

// Curvature (1/m) of the circle through three points: 2 |(p1 - p0) x (p2 - p0)| / (a b c).
// (Any vector type with norm() and cross(): this header serves tests that do not link membra.)
template <class V>
double circle_curvature(const V& p0, const V& p1, const V& p2) {
  const double a = (p1 - p0).norm(), b = (p2 - p1).norm(), c = (p2 - p0).norm();
  return 2.0 * (p1 - p0).cross(p2 - p0).norm() / (a * b * c);
}

}  // namespace membra
