#pragma once
// Whether a run's warnings say that its form passes through itself (process/run.hpp,
// run_warnings), for the tests of the warning and of the pictures that mark the crossings.
#include <string>
#include <vector>

namespace membra::test_support {

inline bool says_it_passes_through_itself(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings)
    if (w.find("passes through itself") != std::string::npos) return true;
  return false;
}

}  // namespace membra::test_support
