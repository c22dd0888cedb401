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

}  // namespace membra
