#pragma once
// Debian's CHOLMOD opens OpenMP regions of a fixed 4 threads inside the supernodal
// factorization, whatever OMP_NUM_THREADS says; on 2 cores their sleeping and waking cost 5x the
// factorization itself (docs/performance.md). While one of these guards lives, no parallel level
// is active, so those regions run on the calling thread; the old setting comes back after.
namespace membra {

class SerialFactorization {
 public:
  SerialFactorization();
  ~SerialFactorization();
  SerialFactorization(const SerialFactorization&) = delete;
  SerialFactorization& operator=(const SerialFactorization&) = delete;

 private:
  int levels_;
};

}  // namespace membra
