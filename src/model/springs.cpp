#include "membra/model/springs.hpp"

namespace membra {

std::string_view to_string(SpringFamily f) {
  switch (f) {
    case SpringFamily::stretch:
      return "stretch";
    case SpringFamily::shear:
      return "shear";
    case SpringFamily::flex:
      return "flex";
    case SpringFamily::added:
      return "added";
  }
  return "unknown";
}

int Springs::add(int pa, int pb, double l0, double k, double c, SpringFamily f, double w) {
  a.push_back(pa);
  b.push_back(pb);
  rest_length.push_back(l0);
  stiffness.push_back(k);
  damping.push_back(c);
  family.push_back(f);
  width.push_back(w);
  return size() - 1;
}

void Springs::filter(const std::vector<bool>& keep) {
  size_t out = 0;
  for (size_t s = 0; s < a.size(); ++s) {
    if (!keep[s]) continue;
    a[out] = a[s];
    b[out] = b[s];
    rest_length[out] = rest_length[s];
    stiffness[out] = stiffness[s];
    damping[out] = damping[s];
    family[out] = family[s];
    width[out] = width[s];
    ++out;
  }
  a.resize(out);
  b.resize(out);
  rest_length.resize(out);
  stiffness.resize(out);
  damping.resize(out);
  family.resize(out);
  width.resize(out);
}

}  // namespace membra
