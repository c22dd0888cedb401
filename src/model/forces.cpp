#include "membra/model/forces.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

#include "membra/model/bend_kernel.hpp"
#include "membra/model/hinge_kernel.hpp"
#include "membra/model/spring_kernel.hpp"

namespace membra {
namespace {

void add_spring_forces(const Model& model, const Points& x, const Points* v, int begin, int end,
                       Points& f) {
  const Springs& s = model.springs;
  if (!v) {  // static: no damping, the lean kernel (2x faster)
    for (int i = begin; i < end; ++i) {
      const int a = s.a[i], b = s.b[i];
      const Vec3 fa =
          spring_static_force_on_a(x.col(a), x.col(b), s.rest_length[i], s.stiffness[i]);
      f.col(a) += fa;
      f.col(b) -= fa;
    }
    return;
  }
  for (int i = begin; i < end; ++i) {
    const int a = s.a[i], b = s.b[i];
    const Vec3 fa = spring_force_on_a(x.col(a), x.col(b), v->col(a), v->col(b), s.rest_length[i],
                                      s.stiffness[i], s.damping[i]);
    f.col(a) += fa;
    f.col(b) -= fa;
  }
}

void add_bending_forces(const Model& model, const Points& x, int begin, int end, Points& f) {
  const Bending& b = model.bending;
  for (int i = begin; i < end; ++i) {
    const auto& v = b.v[i];
    const BendEval e = bend_eval(x.col(v[0]), x.col(v[1]), x.col(v[2]), b.stiffness[i]);
    for (int k = 0; k < 3; ++k) f.col(v[k]) -= e.grad[k];
  }
}

void add_hinge_forces(const Model& model, const Points& x, int begin, int end, Points& f) {
  const Hinges& h = model.hinges;
  for (int i = begin; i < end; ++i) {
    const double m = h.moment[i];
    if (m == 0.0) continue;
    const auto& v = h.v[i];
    const HingeEval e = hinge_eval(x.col(v[0]), x.col(v[1]), x.col(v[2]), x.col(v[3]));
    for (int k = 0; k < 4; ++k) f.col(v[k]) -= m * e.grad[k];
  }
}

// The particles that the elements [begin, end) of each kind touch, as [lo, hi) (empty: lo >= hi).
struct ParticleRange {
  int lo = std::numeric_limits<int>::max(), hi = 0;
  template <typename Ids>
  void add(const Ids& ids) {
    for (int p : ids) lo = std::min(lo, p), hi = std::max(hi, p + 1);
  }
};

ParticleRange touched(const Model& model, int c, int chunks) {
  ParticleRange r;
  const Springs& s = model.springs;
  const int ns = s.size(), nb = model.bending.size(), nh = model.hinges.size();
  for (int i = ns * c / chunks; i < ns * (c + 1) / chunks; ++i)
    r.add(std::array<int, 2>{s.a[i], s.b[i]});
  for (int i = nb * c / chunks; i < nb * (c + 1) / chunks; ++i) r.add(model.bending.v[i]);
  for (int i = nh * c / chunks; i < nh * (c + 1) / chunks; ++i) r.add(model.hinges.v[i]);
  return r;
}

// Springs, bending and hinges. Large sheets split the elements into a fixed number of chunks, each
// summed into its own buffer, the buffers added in chunk order: the result is the same bit for
// bit whatever the number of threads (and whichever thread takes which chunk). Elements are
// numbered along the sheet, so a chunk touches a band of particles: only that band of its buffer
// is cleared and added (the rest would add zeros), a quarter of the memory traffic.
void add_elastic_forces(const Model& model, const Points& x, const Points* v, Points& f) {
  const int ns = model.springs.size(), nb = model.bending.size(), nh = model.hinges.size();
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
      add_spring_forces(model, x, v, ns * c / kChunks, ns * (c + 1) / kChunks, fc);
      add_bending_forces(model, x, nb * c / kChunks, nb * (c + 1) / kChunks, fc);
      add_hinge_forces(model, x, nh * c / kChunks, nh * (c + 1) / kChunks, fc);
    }
    for (int c = 0; c < kChunks; ++c) {
      const ParticleRange& r = band[static_cast<size_t>(c)];
      if (r.lo < r.hi)
        f.middleCols(r.lo, r.hi - r.lo) +=
            partial[static_cast<size_t>(c)].middleCols(r.lo, r.hi - r.lo);
    }
    return;
  }
  add_spring_forces(model, x, v, 0, ns, f);
  add_bending_forces(model, x, 0, nb, f);
  add_hinge_forces(model, x, 0, nh, f);
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

double elastic_energy(const Model& model, const Points& x) {
  const Springs& s = model.springs;
  double e = 0.0;
  for (int i = 0; i < s.size(); ++i)
    e += spring_energy(x.col(s.a[i]), x.col(s.b[i]), s.rest_length[i], s.stiffness[i]);
  return e;
}

double bending_energy(const Model& model, const Points& x) {
  const Bending& b = model.bending;
  double e = 0.0;
  for (int i = 0; i < b.size(); ++i) {
    const auto& v = b.v[i];
    e += bend_eval(x.col(v[0]), x.col(v[1]), x.col(v[2]), b.stiffness[i]).energy;
  }
  return e;
}

double hinge_energy(const Model& model, const Points& x) {
  const Hinges& h = model.hinges;
  double e = 0.0;
  for (int i = 0; i < h.size(); ++i) {
    if (h.moment[i] == 0.0) continue;
    const auto& v = h.v[i];
    e += h.moment[i] * hinge_eval(x.col(v[0]), x.col(v[1]), x.col(v[2]), x.col(v[3])).theta;
  }
  return e;
}

double gravity_energy(const Model& model, const Points& x) {
  double e = 0.0;
  for (int p = 0; p < model.num_particles(); ++p) e -= model.mass[p] * model.gravity.dot(x.col(p));
  return e;
}

double potential_energy(const Model& model, const Points& x) {
  return elastic_energy(model, x) + bending_energy(model, x) + hinge_energy(model, x) +
         gravity_energy(model, x);
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
