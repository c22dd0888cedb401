#pragma once
// Sums of per-particle values over every particle within a radius on the paper, for big sheets
// where PaperWindows thins its windows: the paper's grid rows (particles of one exact y), each
// with prefix sums along x, so a window costs two binary searches per row it crosses. Sums that
// must see every particle (a window's angle defects cancel only in full, Gauss-Bonnet) or moments
// that stand for a window's means and plane use it (global_curvature.cpp, shape.cpp).
// Scattered particles (a continuum mesh: far more distinct y than a grid's rows) go in bands of
// about sqrt(N) particles instead; a window takes a band's particles surely inside it from the
// prefix sums and tests the rest one by one, so its sum is over exactly the same particles.
#include <vector>

#include <Eigen/Core>

#include "membra/core/vec.hpp"

namespace membra {

class PaperRows {
 public:
  // paper: one column per particle; values: one column per particle, the quantities to sum.
  PaperRows(const Points& paper, const Eigen::MatrixXd& values);

  // The sums of the values of the particles q with |paper_q - centre| <= radius (in x and y).
  Eigen::VectorXd sum_within(const Vec2& centre, double radius) const;

 private:
  struct Row {
    double y_lo = 0.0, y_hi = 0.0;  // its particles' y (equal in a grid's row)
    std::vector<double> x;          // sorted
    std::vector<double> y;          // in the same order (banded rows)
    Eigen::MatrixXd value;          // in the same order (banded rows)
    Eigen::MatrixXd prefix;         // column k: the sum of the values of the first k particles
  };
  void add_banded(const Row& r, const Vec2& centre, double radius, Eigen::VectorXd& sum) const;

  std::vector<double> y_;  // the rows' lowest y, ascending
  std::vector<Row> rows_;
  Eigen::Index size_ = 0;  // values per particle
  bool banded_ = false;
  double band_ = 0.0;  // the bands' height (banded rows)
};

}  // namespace membra
