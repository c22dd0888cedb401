#include "membra/solve/tangent_correction.hpp"

#include <Eigen/CholmodSupport>

#include "membra/geometry/triangulation.hpp"
#include "membra/solve/serial_factorization.hpp"

namespace membra {

struct TangentCorrection::Factor {
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>> llt;
  Eigen::Index analysed_nonzeros = -1;  // the pattern llt was analysed on
};

TangentCorrection::~TangentCorrection() = default;

TangentCorrection::TangentCorrection(const Model& model, const std::vector<int>& dof, int ndof)
    : dof_(dof),
      ndof_(ndof),
      applies_(model.membrane_triangles.size() > 0),
      factor_(std::make_unique<Factor>()) {
  for (int i = 0; i < model.membrane_triangles.size(); ++i) {
    const auto [a, b, c] = model.membrane_triangles.ids(i);
    triangles_.emplace_back(a, b, c);
  }
  for (int p = 0; p < model.num_particles(); ++p)
    if (dof[3 * p] >= 0 || dof[3 * p + 1] >= 0 || dof[3 * p + 2] >= 0) movable_.push_back(p);
  factor_->llt.cholmod().print = 0;
}

void TangentCorrection::forget_pattern() {
  factor_->analysed_nonzeros = -1;
}

// ndof x 2m: columns 2k and 2k + 1 are two orthonormal tangents at movable particle k, on its
// free coordinates (every coordinate entered, zeros too, so the pattern does not change).
Eigen::SparseMatrix<double> TangentCorrection::basis(const Points& x) const {
  const Points n = vertex_normals(x, triangles_);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(6 * movable_.size());
  for (size_t k = 0; k < movable_.size(); ++k) {
    const int p = movable_[k];
    const Vec3 normal = n.col(p);
    Eigen::Index axis = 0;
    normal.cwiseAbs().minCoeff(&axis);
    const Vec3 t1 = normal.cross(Vec3::Unit(axis)).normalized();
    const Vec3 t2 = normal.cross(t1);
    for (int c = 0; c < 3; ++c) {
      const int d = dof_[static_cast<size_t>(3 * p + c)];
      if (d < 0) continue;
      entries.emplace_back(d, static_cast<int>(2 * k), t1[c]);
      entries.emplace_back(d, static_cast<int>(2 * k + 1), t2[c]);
    }
  }
  Eigen::SparseMatrix<double> b(ndof_, static_cast<Eigen::Index>(2 * movable_.size()));
  b.setFromTriplets(entries.begin(), entries.end());
  return b;
}

bool TangentCorrection::correction(const Points& x, const Eigen::SparseMatrix<double>& lower,
                                   const Eigen::VectorXd& g_trial, Eigen::VectorXd& e) {
  const Eigen::SparseMatrix<double> b = basis(x);
  const Eigen::SparseMatrix<double> h = lower.selfadjointView<Eigen::Lower>();
  Eigen::SparseMatrix<double> a =
      Eigen::SparseMatrix<double>(b.transpose() * h * b).triangularView<Eigen::Lower>();
  // In-plane rigid motions of a free sheet, and tangents on held coordinates, are not stiffened:
  // a small shift in the diagonal's metric keeps them factorizable (and unmoved).
  const Eigen::VectorXd diag = a.diagonal().cwiseAbs();
  const double floor = 1e-12 * (diag.size() ? diag.maxCoeff() : 1.0);
  for (Eigen::Index k = 0; k < a.outerSize(); ++k) a.coeffRef(k, k) += 1e-8 * diag[k] + floor;
  auto& [llt, analysed] = *factor_;
  {
    const SerialFactorization serial;
    if (a.nonZeros() != analysed) llt.analyzePattern(a), analysed = a.nonZeros(), ++analyses_;
    llt.factorize(a);
  }
  ++factorizations_;
  if (llt.info() != Eigen::Success) return false;
  e = -(b * llt.solve(b.transpose() * g_trial));
  return e.allFinite();
}

}  // namespace membra
