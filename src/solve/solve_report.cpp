#include "membra/solve/solve_report.hpp"

#include <sstream>

namespace membra {

std::string summary_message(const std::string& name, const SolveReport& r, double tolerance,
                            const char* unit) {
  std::ostringstream msg;
  msg << name << ": " << (r.converged ? "converged" : "not converged") << " after " << r.iterations
      << " " << unit << ", residual " << r.residual_relative << " (tolerance " << tolerance << ")";
  return msg.str();
}

}  // namespace membra
