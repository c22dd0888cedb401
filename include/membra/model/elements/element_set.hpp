#pragma once
// What every element kind provides, stated once as a C++20 concept, and the loops written once
// over any kind. A kind is one header and source in model/elements/ that owns its elements'
// particles, rest state and material state (latex and resin) and its kernel; Model::for_each_set
// registers it, and forces, Hessians, solvers, cuts, impregnation and measures visit the sets
// through these names (docs/architecture.md, "Adding an element kind").
#include <array>
#include <concepts>
#include <cstddef>
#include <functional>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "membra/core/vec.hpp"

namespace membra {

// Which energy an element stores, for the report's split (stretching or bending; a support's
// contact and the sheet's contact with itself are neither).
enum class EnergyKind { stretching, bending, support, contact };

// Where the release stands: latex rest lengths move from their frame length (level 1) to their
// natural length (level 0) once the release has begun (docs/process.md).
struct ReleaseLevel {
  bool releasing = false;
  double level = 1.0;
};

class GrowthField;   // set_context.hpp
struct LocalGrowth;  // set_context.hpp

// Does the segment between particles p and q cross the cut? (the cut rule's question)
using CrossesCut = std::function<bool(int p, int q)>;

// Where an element lies, for the design's resin maps (frame coordinates, m): the shares of its
// length along one or two segments (a bending element's two halves), and the point where a
// density field is read. `count` 0: the design places no resin on it (an added spring, a hinge).
struct ResinFootprint {
  struct Segment {
    Vec2 a = Vec2::Zero(), b = Vec2::Zero();
    double weight = 0.0;
  };
  std::array<Segment, 2> segment;
  int count = 0;
  Vec2 site = Vec2::Zero();
};

// An element's in-plane read-out, for pictures and the report: its stress (Pa, tension > 0;
// `carries` false for an element that has none, bending and hinges, or none known, a spring of
// unknown width), its largest strain against its rest state (`strained`: springs, the latex of
// membrane triangles) and an axial element's force (`axial`: springs, N).
struct ElementStress {
  bool carries = false;
  double stress = 0.0;
  bool strained = false;
  double strain = 0.0;
  bool axial = false;
  double force = 0.0;
};

template <typename S>
concept ElementSet = requires(const S& s, S& w, const Points& x, const Points* v, Points& f, int i,
                              bool project, const std::vector<bool>& keep,
                              std::vector<double>& diag, const CrossesCut& crosses,
                              const ReleaseLevel& release, const GrowthField& field,
                              const std::vector<LocalGrowth>& growth) {
  // The number of particles an element joins, and the kind's name (docs, messages).
  { S::kArity } -> std::convertible_to<int>;
  { S::kName } -> std::convertible_to<std::string_view>;
  { S::kEnergy } -> std::convertible_to<EnergyKind>;
  { s.size() } -> std::same_as<int>;
  // The particles of element i.
  { s.ids(i) } -> std::same_as<std::array<int, S::kArity>>;
  // False for an element that stores no energy now (it is skipped by every loop).
  { s.active(i) } -> std::same_as<bool>;
  // Kernel: energy (J), forces added into f over elements [begin, end) (with velocities v for
  // damping, or nullptr), and the analytic Hessian (N/m), PSD-projected with `project`.
  { s.energy(i, x) } -> std::same_as<double>;
  s.add_forces(x, v, i, i, f);
  { s.hessian(i, x, project) } -> std::same_as<Eigen::Matrix<double, 3 * S::kArity, 3 * S::kArity>>;
  // A diagonal stiffness per particle (N/m) for the static solver's scaled masses.
  s.add_stiffness_estimate(x, diag);
  // The composite rule: rest state and stiffness from the latex, the resin and the release; the
  // state the release starts from is recorded at positions x when the frame lets go.
  w.update(release);
  w.begin_release(x);
  // For the design: where the element lies, its resin fraction set by the composite rule, and
  // d/df of (grad E(x) . w) in that fraction (0 for an element the design places no resin on).
  { s.footprint(i, x) } -> std::same_as<ResinFootprint>;
  w.set_resin_fraction(i, 0.5, release);
  { s.resin_rate(i, x, x, release) } -> std::same_as<double>;
  // The stress read-out at positions x for a sheet of the given thickness (m).
  { s.stress(i, x, 1.0) } -> std::same_as<ElementStress>;
  // The cut rule: which elements a cut severs; then keep only those where keep[i].
  { s.severed(i, crosses) } -> std::same_as<bool>;
  w.filter(keep);
  // The growth rule: each element's growth read from the field at the paper positions x (a
  // kind that does not grow returns none), then that growth raised to an exponent (a share of it
  // along a path) applied to the latex's rest state.
  { s.growth(field, x) } -> std::same_as<std::vector<LocalGrowth>>;
  w.grow(growth, x, 0.5, release);
  // The resin rule (returns how many elements took resin) and the carry-over of a rebuilt
  // sheet's elements (set_context.hpp; declared there, checked where the sets are defined).
};

// Keeps the entries of v where keep is true, in order.
template <typename T>
void keep_where(std::vector<T>& v, const std::vector<bool>& keep) {
  size_t out = 0;
  for (size_t k = 0; k < v.size(); ++k)
    if (keep[k]) v[out++] = v[k];
  v.resize(out);
}

// The energy of a set's active elements, summed in element order (J).
template <ElementSet S>
double set_energy(const S& s, const Points& x) {
  double e = 0.0;
  for (int i = 0; i < s.size(); ++i)
    if (s.active(i)) e += s.energy(i, x);
  return e;
}

// Appends the particles of every element (the set's topology, to compare two models).
template <ElementSet S>
void append_ids(const S& s, std::vector<int>& out) {
  for (int i = 0; i < s.size(); ++i)
    for (int p : s.ids(i)) out.push_back(p);
}

// The elements of the set that the cut severs, as a keep mask.
template <ElementSet S>
std::vector<bool> survivors_of_cut(const S& s, const CrossesCut& crosses) {
  std::vector<bool> keep(static_cast<size_t>(s.size()), true);
  for (int i = 0; i < s.size(); ++i) keep[static_cast<size_t>(i)] = !s.severed(i, crosses);
  return keep;
}

}  // namespace membra
