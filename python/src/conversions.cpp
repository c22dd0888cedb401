#include "conversions.hpp"

namespace membra::python {

py::array_t<double> positions_mm(const Points& x) {
  py::array_t<double> a({static_cast<py::ssize_t>(x.cols()), py::ssize_t{3}});
  auto v = a.mutable_unchecked<2>();
  for (Eigen::Index p = 0; p < x.cols(); ++p)
    for (int c = 0; c < 3; ++c) v(p, c) = x(c, p) * 1e3;
  return a;
}

py::array_t<double> paper_positions_mm(const Sheet& sheet) {
  const int n = sheet.grid.num_particles();
  py::array_t<double> a({static_cast<py::ssize_t>(n), py::ssize_t{2}});
  auto v = a.mutable_unchecked<2>();
  for (int p = 0; p < n; ++p) {
    const auto [i, j] = sheet.grid.node(p);
    const Vec2 q = sheet.grid.position(i, j);
    v(p, 0) = q.x() * 1e3;
    v(p, 1) = q.y() * 1e3;
  }
  return a;
}

py::array_t<int> triangles(const Sheet& sheet) {
  py::array_t<int> a({static_cast<py::ssize_t>(sheet.triangles.size()), py::ssize_t{3}});
  auto v = a.mutable_unchecked<2>();
  for (std::size_t t = 0; t < sheet.triangles.size(); ++t)
    for (int c = 0; c < 3; ++c) v(static_cast<py::ssize_t>(t), c) = sheet.triangles[t](c);
  return a;
}

py::array_t<double> per_particle(const std::vector<double>& values, double scale) {
  py::array_t<double> a(static_cast<py::ssize_t>(values.size()));
  auto v = a.mutable_unchecked<1>();
  for (std::size_t p = 0; p < values.size(); ++p)
    v(static_cast<py::ssize_t>(p)) = values[p] * scale;
  return a;
}

py::object json_to_python(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

}  // namespace membra::python
