#include "membra/model/forces.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <utility>
#include <vector>

namespace membra {
namespace {

// The particles that the elements [begin, end) of each kind touch, as [lo, hi) (empty: lo >= hi).
struct ParticleRange {
  int lo = std::numeric_limits<int>::max(), hi = 0;
  template <typename Ids>
  void add(const Ids& ids) {
    for (int p : ids) lo = std::min(lo, p), hi = std::max(hi, p + 1);
  }
};

// Chunk c of `chunks` of a set's elements.
template <typename S>
std::pair<int, int> chunk(const S& set, int c, int chunks) {
  return {set.size() * c / chunks, set.size() * (c + 1) / chunks};
}

ParticleRange touched(const Model& model, int c, int chunks) {
  ParticleRange r;
  model.for_each_set([&](const auto& set) {
    const auto [begin, end] = chunk(set, c, chunks);
    for (int i = begin; i < end; ++i) r.add(set.ids(i));
  });
  return r;
}

// Every element set's forces. Large sheets split each set's elements into a fixed number of
// chunks, each summed into its own buffer, the buffers added in chunk order: the result is the
// same bit for bit whatever the number of threads (and whichever thread takes which chunk).
// Elements are numbered along the sheet, so a chunk touches a band of particles: only that band
// of its buffer is cleared and added (the rest would add zeros), a quarter of the memory traffic.
void add_elastic_forces(const Model& model, const Points& x, const Points* v, Points& f) {
  constexpr int kParallelParticles = 2000;  // below this, threads cost more than they save
  constexpr int kChunks = 4;
  if (model.num_particles() >= kParallelParticles) {
    // Reused between passes; a reference, so every thread of the region sees the caller's.
    thread_local std::vector<Points> buffers;
    std::vector<Points>& partial = buffers;
    partial.resize(kChunks);
    std::array<ParticleRange, kChunks> band;
#pragma omp parallel for schedule(static)
    for (int c = 0; c < kChunks; ++c) {
      Points& fc = partial[static_cast<size_t>(c)];
      if (fc.cols() != x.cols()) fc.resize(3, x.cols());
      const ParticleRange r = touched(model, c, kChunks);
      band[static_cast<size_t>(c)] = r;
      if (r.lo >= r.hi) continue;
      fc.middleCols(r.lo, r.hi - r.lo).setZero();
      model.for_each_set([&](const auto& set) {
        const auto [begin, end] = chunk(set, c, kChunks);
        set.add_forces(x, v, begin, end, fc);
      });
    }
    for (int c = 0; c < kChunks; ++c) {
      const ParticleRange& r = band[static_cast<size_t>(c)];
      if (r.lo < r.hi)
        f.middleCols(r.lo, r.hi - r.lo) +=
            partial[static_cast<size_t>(c)].middleCols(r.lo, r.hi - r.lo);
    }
    return;
  }
  model.for_each_set([&](const auto& set) { set.add_forces(x, v, 0, set.size(), f); });
}

void add_gravity(const Model& model, Points& f) {
  for (int p = 0; p < model.num_particles(); ++p) f.col(p) += model.mass[p] * model.gravity;
}

}  // namespace

void compute_forces(const Model& model, const Points& x, const Points& v, Points& f) {
  f.setZero(3, x.cols());
  const bool dynamic = v.cols() == x.cols();
  add_elastic_forces(model, x, dynamic ? &v : nullptr, f);
  add_gravity(model, f);
  if (dynamic && model.velocity_damping != 0.0) {
    for (int p = 0; p < model.num_particles(); ++p)
      f.col(p) -= model.velocity_damping * model.mass[p] * v.col(p);
  }
}

void compute_static_forces(const Model& model, const Points& x, Points& f) {
  f.setZero(3, x.cols());
  add_elastic_forces(model, x, nullptr, f);
  add_gravity(model, f);
}

double energy_of_kind(const Model& model, const Points& x, EnergyKind kind) {
  double e = 0.0;
  model.for_each_set([&](const auto& set) {
    if (set.kEnergy == kind) e += set_energy(set, x);
  });
  return e;
}

double elastic_energy(const Model& model, const Points& x) {
  return energy_of_kind(model, x, EnergyKind::stretching);
}

double bending_energy(const Model& model, const Points& x) {
  return energy_of_kind(model, x, EnergyKind::bending);
}

double gravity_energy(const Model& model, const Points& x) {
  double e = 0.0;
  for (int p = 0; p < model.num_particles(); ++p) e -= model.mass[p] * model.gravity.dot(x.col(p));
  return e;
}

double potential_energy(const Model& model, const Points& x) {
  double e = 0.0;  // set by set, in their order (so the sum is the same bit for bit)
  model.for_each_set([&](const auto& set) { e += set_energy(set, x); });
  return e + gravity_energy(model, x);
}

double kinetic_energy(const Model& model, const Points& v) {
  double e = 0.0;
  for (int p = 0; p < model.num_particles(); ++p)
    if (!model.pinned(p)) e += 0.5 * model.mass[p] * v.col(p).squaredNorm();
  return e;
}

double max_free_force(const Model& model, const Points& f) {
  double r = 0.0;
  for (int p = 0; p < model.num_particles(); ++p)
    if (!model.pinned(p)) r = std::max(r, f.col(p).norm());
  return r;
}

double max_residual_force(const Model& model, const Points& x) {
  Points f;
  compute_static_forces(model, x, f);
  return max_free_force(model, f);
}

}  // namespace membra
