#include "membra/model/pins.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace membra {
namespace {

// Corners and edges of a sheet without a grid (a mesh): the particles at the rectangle's corners
// and on its sides, by their paper positions.
std::vector<int> select_on_mesh(const PinSpec& pin, const GridSheet& g, const Model& m) {
  std::vector<int> out;
  const double eps = 1e-9 * std::max(g.width(), g.height());
  for (int p = 0; p < m.num_particles(); ++p) {
    const Vec2 q = m.reference.col(p).head<2>();
    const bool left = q.x()<eps, right = q.x()> g.width() - eps,
               bottom = q.y()<eps, top = q.y()> g.height() - eps;
    const bool take = pin.kind == PinSpec::Kind::corners
                          ? (left || right) && (bottom || top)
                          : (pin.edge == "left" && left) || (pin.edge == "right" && right) ||
                                (pin.edge == "bottom" && bottom) || (pin.edge == "top" && top);
    if (take) out.push_back(p);
  }
  return out;
}

std::vector<int> select(const PinSpec& pin, const GridSheet& g, const Model& m) {
  std::vector<int> out;
  const int nx = g.nx(), ny = g.ny();
  const bool mesh = g.num_particles() == 0 && m.num_particles() > 0;
  if (mesh && (pin.kind == PinSpec::Kind::corners || pin.kind == PinSpec::Kind::edge))
    return select_on_mesh(pin, g, m);
  switch (pin.kind) {
    case PinSpec::Kind::corners:
      for (auto [i, j] : {std::pair{0, 0}, {nx - 1, 0}, {0, ny - 1}, {nx - 1, ny - 1}})
        if (const int p = g.particle(i, j); p >= 0) out.push_back(p);
      break;
    case PinSpec::Kind::edge:
      for (int k = 0; k < (pin.edge == "left" || pin.edge == "right" ? ny : nx); ++k) {
        int i = k, j = k;
        if (pin.edge == "left") i = 0;
        if (pin.edge == "right") i = nx - 1;
        if (pin.edge == "bottom") j = 0;
        if (pin.edge == "top") j = ny - 1;
        if (const int p = g.particle(i, j); p >= 0) out.push_back(p);
      }
      break;
    case PinSpec::Kind::point: {
      int best = -1;
      double best_d = std::numeric_limits<double>::infinity();
      for (int p = 0; p < m.num_particles(); ++p) {
        const double d = (m.reference.col(p).head<2>() - pin.point).squaredNorm();
        if (d < best_d) best_d = d, best = p;
      }
      if (best >= 0) out.push_back(best);
      break;
    }
    case PinSpec::Kind::box: {
      const double eps = 1e-9 * std::max(g.width(), g.height());
      for (int p = 0; p < m.num_particles(); ++p) {
        const Vec2 q = m.reference.col(p).head<2>();
        if ((q.array() >= pin.box_min.array() - eps).all() &&
            (q.array() <= pin.box_max.array() + eps).all())
          out.push_back(p);
      }
      break;
    }
  }
  return out;
}

}  // namespace

int apply_pins(const std::vector<PinSpec>& pins, const GridSheet& grid, Model& model) {
  int count = 0;
  for (size_t k = 0; k < pins.size(); ++k) {
    const std::vector<int> ps = select(pins[k], grid, model);
    if (ps.empty())
      throw std::invalid_argument("pin " + std::to_string(k) + " selects no particle");
    for (int p : ps) {
      if (!model.pinned(p)) ++count;
      model.pin(p);
    }
  }
  return count;
}

}  // namespace membra
