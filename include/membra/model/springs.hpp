#pragma once
// The springs of a model, stored as parallel arrays (structure of arrays) so force passes stream
// through memory.
#include <cstdint>
#include <string_view>
#include <vector>

namespace membra {

// Which lattice family a spring belongs to (the paper's three, plus springs added later).
enum class SpringFamily : std::uint8_t { stretch, shear, flex, added };

std::string_view to_string(SpringFamily f);

struct Springs {
  std::vector<int> a, b;            // particle indices
  std::vector<double> rest_length;  // l0, m
  std::vector<double> stiffness;    // k, N/m
  std::vector<double> damping;      // c, N*s/m, acts on the relative velocity along the spring
  std::vector<SpringFamily> family;
  std::vector<double> width;  // tributary width of sheet it stands for, m (0: unknown)

  int size() const { return static_cast<int>(a.size()); }
  // Appends a spring and returns its index.
  int add(int pa, int pb, double l0, double k, double c, SpringFamily f, double w = 0.0);
  // Removes the springs for which keep[s] is false, preserving order.
  void filter(const std::vector<bool>& keep);
};

}  // namespace membra
