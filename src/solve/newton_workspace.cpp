#include "membra/solve/newton_workspace.hpp"

#include "membra/solve/serial_factorization.hpp"

namespace membra {
namespace {

// Every element's particles, set by set (with each set's size, so that sets cannot trade).
std::vector<int> topology(const Model& model) {
  std::vector<int> ids;
  model.for_each_set([&](const auto& set) {
    ids.push_back(set.size());
    append_ids(set, ids);
  });
  return ids;
}

}  // namespace

NewtonWorkspace::NewtonWorkspace(const Model& model, const std::vector<int>& dof, int ndof)
    : exact(model, dof, ndof),
      projected(exact),  // the same pattern: built once
      dof_(dof),
      elements_(topology(model)) {
  llt.cholmod().print = 0;  // "not positive definite" is an expected answer in Newton
}

bool NewtonWorkspace::fits(const Model& model, const std::vector<int>& dof) const {
  if (dof != dof_) return false;
  // Set by set against the stored topology, without building it again (millions of ints on
  // large sheets).
  size_t at = 0;
  bool same = true;
  model.for_each_set([&](const auto& set) {
    if (!same || at >= elements_.size() || elements_[at++] != set.size()) {
      same = false;
      return;
    }
    for (int i = 0; i < set.size() && same; ++i)
      for (int p : set.ids(i)) {
        if (at >= elements_.size() || elements_[at++] != p) {
          same = false;
          break;
        }
      }
  });
  return same && at == elements_.size();
}

bool NewtonWorkspace::factorize(const Eigen::SparseMatrix<double>& a) {
  const SerialFactorization serial;
  if (!analysed) llt.analyzePattern(a), analysed = true;
  llt.factorize(a);
  return llt.info() == Eigen::Success;
}

void NewtonWorkspace::bind(const Model& model) {
  exact.bind(model);
  projected.bind(model);
}

}  // namespace membra
