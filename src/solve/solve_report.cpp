#include "membra/solve/solve_report.hpp"

#include <sstream>

namespace membra {

double sheet_extent(const Points& x) {
  if (x.cols() == 0) return 0.0;
  return (x.rowwise().maxCoeff() - x.rowwise().minCoeff()).norm();
}

std::string summary_message(const std::string& name, const SolveReport& r, double tolerance,
                            const char* unit) {
  std::ostringstream msg;
  msg << name << ": " << (r.converged ? "converged" : "not converged") << " after " << r.iterations
      << " " << unit << ", residual " << r.residual_relative << " (tolerance " << tolerance << ")";
  return msg.str();
}

}  // namespace membra
