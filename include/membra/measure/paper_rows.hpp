#pragma once
// Sums of per-particle values over every particle within a radius on the paper, for big sheets
// where PaperWindows thins its windows: the paper's grid rows (particles of one exact y), each
// with prefix sums along x, so a window costs two binary searches per row it crosses. Sums that
// must see every particle (a window's angle defects cancel only in full, Gauss-Bonnet) or moments
// that stand for a window's means and plane use it (global_curvature.cpp, shape.cpp).
#include <vector>

#include <Eigen/Core>

#include "membra/core/vec.hpp"

namespace membra {

class PaperRows {
 public:
  // paper: one column per particle, on a grid (each row's particles share one y exactly);
  // values: one column per particle, the quantities to sum.
  PaperRows(const Points& paper, const Eigen::MatrixXd& values);

  // The sums of the values of the particles q with |paper_q - centre| <= radius (in x and y).
  Eigen::VectorXd sum_within(const Vec2& centre, double radius) const;

 private:
  struct Row {
    std::vector<double> x;   // sorted
    Eigen::MatrixXd prefix;  // column k: the sum of the values of the first k particles
  };
  std::vector<double> y_;  // the rows' y, ascending
  std::vector<Row> rows_;
  Eigen::Index size_ = 0;  // values per particle
};

}  // namespace membra
