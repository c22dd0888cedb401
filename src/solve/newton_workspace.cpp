#include "membra/solve/newton_workspace.hpp"

namespace membra {

NewtonWorkspace::NewtonWorkspace(const Model& model, const std::vector<int>& dof, int ndof)
    : exact(model, dof, ndof),
      projected(exact),  // the same pattern: built once
      dof_(dof),
      spring_a_(model.springs.a),
      spring_b_(model.springs.b),
      bending_(model.bending.v),
      hinges_(model.hinges.v) {
  llt.cholmod().print = 0;  // "not positive definite" is an expected answer in Newton
}

bool NewtonWorkspace::fits(const Model& model, const std::vector<int>& dof) const {
  return dof == dof_ && model.springs.a == spring_a_ && model.springs.b == spring_b_ &&
         model.bending.v == bending_ && model.hinges.v == hinges_;
}

void NewtonWorkspace::bind(const Model& model) {
  exact.bind(model);
  projected.bind(model);
}

}  // namespace membra
