#include "membra/design/resin_map.hpp"

namespace membra {
ElementRates element_force_sensitivity(const Membrane& m, const Points& x, const Points& w) {
  ElementRates out;
  m.sheet.model.for_each_set([&](const auto& set) {
    Eigen::VectorXd& r = out.set.emplace_back(Eigen::VectorXd::Zero(set.size()));
    for (int i = 0; i < set.size(); ++i) r[i] = set.resin_rate(i, x, w, m.release());
  });
  return out;
}

}  // namespace membra
