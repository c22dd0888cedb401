#include "membra/design/density_field.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace membra {

Vec2 DensityField::cell_size() const {
  return Vec2((frame.max.x() - frame.min.x()) / nx, (frame.max.y() - frame.min.y()) / ny);
}

Vec2 DensityField::centre(int cell) const {
  const Vec2 h = cell_size();
  return frame.min + Vec2((cell % nx + 0.5) * h.x(), (cell / nx + 0.5) * h.y());
}

DensityField::Weights DensityField::weights(const Vec2& p) const {
  const Vec2 h = cell_size();
  // Position in cell-centre units, clamped to the outer centres.
  auto axis = [](double u, int n, int& i0, double& t) {
    u = std::clamp(u - 0.5, 0.0, static_cast<double>(n - 1));
    i0 = std::min(static_cast<int>(std::floor(u)), std::max(n - 2, 0));
    t = n > 1 ? u - i0 : 0.0;
  };
  int i = 0, j = 0;
  double s = 0.0, t = 0.0;
  axis((p.x() - frame.min.x()) / h.x(), nx, i, s);
  axis((p.y() - frame.min.y()) / h.y(), ny, j, t);
  const int i1 = std::min(i + 1, nx - 1), j1 = std::min(j + 1, ny - 1);
  return {{i + nx * j, i1 + nx * j, i + nx * j1, i1 + nx * j1},
          {(1 - s) * (1 - t), s * (1 - t), (1 - s) * t, s * t}};
}

double DensityField::at(const Vec2& p) const {
  const Weights w = weights(p);
  double v = 0.0;
  for (int k = 0; k < 4; ++k) v += w.weight[k] * value[w.cell[k]];
  return v;
}

DensityField make_density_field(const Box2& frame, double cell, double value) {
  if (frame.empty()) throw std::invalid_argument("the density field needs a frame");
  if (!(cell > 0.0)) throw std::invalid_argument("the density cell must be > 0");
  DensityField d;
  d.frame = frame;
  const Vec2 size = frame.max - frame.min;
  d.nx = std::max(1, static_cast<int>(std::lround(size.x() / cell)));
  d.ny = std::max(1, static_cast<int>(std::lround(size.y() / cell)));
  d.value = Eigen::VectorXd::Constant(d.nx * d.ny, value);
  return d;
}

}  // namespace membra
