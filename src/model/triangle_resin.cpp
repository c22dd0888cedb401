#include "membra/model/triangle_resin.hpp"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

#include "membra/geometry/triangulation.hpp"

namespace membra {
namespace {

std::vector<bool> lattice_resin(const Sheet& sheet) {
  const Springs& s = sheet.model.springs;
  std::unordered_map<std::uint64_t, double> fraction;
  fraction.reserve(static_cast<size_t>(s.size()));
  for (int i = 0; i < s.size(); ++i) {
    const auto k = static_cast<size_t>(i);
    fraction[edge_key(s.a[k], s.b[k])] = s.resin_fraction[k];
  }
  std::vector<bool> out;
  out.reserve(sheet.triangles.size());
  for (const Triangle& t : sheet.triangles) {
    double sum = 0.0;
    int edges = 0;
    for (int c = 0; c < 3; ++c) {
      const auto it = fraction.find(edge_key(t[c], t[(c + 1) % 3]));
      if (it == fraction.end()) continue;
      sum += it->second;
      ++edges;
    }
    out.push_back(edges > 0 && sum >= 0.5 * edges);
  }
  return out;
}

}  // namespace

std::vector<bool> triangle_resin(const Sheet& sheet) {
  if (!sheet.continuum()) return lattice_resin(sheet);
  const MembraneTriangles& mt = sheet.model.membrane_triangles;
  std::vector<bool> out(sheet.triangles.size(), false);
  for (size_t i = 0; i < out.size() && i < static_cast<size_t>(mt.size()); ++i)
    out[i] = mt.resin[i].volume > 0.0;
  return out;
}

}  // namespace membra
