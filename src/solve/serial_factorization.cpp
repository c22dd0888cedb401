#include "membra/solve/serial_factorization.hpp"

#include <omp.h>

namespace membra {

SerialFactorization::SerialFactorization() : levels_(omp_get_max_active_levels()) {
  omp_set_max_active_levels(0);
}

SerialFactorization::~SerialFactorization() {
  omp_set_max_active_levels(levels_);
}

}  // namespace membra
