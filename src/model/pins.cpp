#include "membra/model/pins.hpp"

#include <limits>
#include <stdexcept>

namespace membra {
namespace {

std::vector<int> select(const PinSpec& pin, const GridSheet& g, const Model& m) {
  std::vector<int> out;
  const int nx = g.nx(), ny = g.ny();
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
