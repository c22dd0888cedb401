#pragma once
// The springs of a model (the paper's lattice: stretch, shear and flex), stored as parallel arrays
// (structure of arrays) so force passes stream through memory. The set owns its kernel
// (spring_kernel.hpp), its latex and resin state and the composite rule that turns them into a rest
// length and a stiffness (docs/process.md).
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "membra/model/elements/element_set.hpp"
#include "membra/model/elements/set_context.hpp"

namespace membra {

// Which lattice family a spring belongs to (the paper's three), and `added` for the springs of
// add_springs (added_springs.hpp), so that a grow step can name them.
enum class SpringFamily : std::uint8_t { stretch, shear, flex, added };

std::string_view to_string(SpringFamily f);

// d/df of a spring's stiffness (N/m) and rest length (m) under the composite rule, f its resin
// fraction (the design's sensitivities).
struct SpringRate {
  double dk = 0.0, dl0 = 0.0;
};

struct Springs {
  static constexpr int kArity = 2;
  static constexpr std::string_view kName = "springs";
  static constexpr EnergyKind kEnergy = EnergyKind::stretching;

  std::vector<int> a, b;            // particle indices
  std::vector<double> rest_length;  // l0, m (what the kernel reads; the composite rule sets it)
  std::vector<double> stiffness;    // k, N/m (likewise)
  std::vector<double> damping;      // c, N*s/m, acts on the relative velocity along the spring
  std::vector<SpringFamily> family;
  std::vector<double> width;  // tributary width of sheet it stands for, m (0: unknown)
  // Material state: the latex, the resin in it and the frame (the composite rule's inputs).
  std::vector<double> natural_length;   // latex rest length, m
  std::vector<double> latex_stiffness;  // k of the latex alone, N/m
  std::vector<double> resin_fraction;   // share of the spring's length inside resin, 0..1
  std::vector<double> resin_stiffness;  // k of the resin alone, N/m
  std::vector<double> resin_length;     // length at impregnation (the resin's rest length), m
  std::vector<double> frame_length;     // length when the release began, m

  int size() const { return static_cast<int>(a.size()); }
  std::array<int, 2> ids(int i) const { return {a[i], b[i]}; }
  bool active(int) const { return true; }
  // Appends a spring of bare latex at rest (natural length l0) and returns its index.
  int add(int pa, int pb, double l0, double k, double c, SpringFamily f, double w = 0.0);
  // Removes the springs for which keep[s] is false, preserving order.
  void filter(const std::vector<bool>& keep);
  // Takes the current rest lengths and stiffnesses as the bare latex's (a new membrane).
  void reset_material();

  // Kernel.
  double energy(int i, const Points& x) const;
  void add_forces(const Points& x, const Points* v, int begin, int end, Points& f) const;
  Eigen::Matrix<double, 6, 6> hessian(int i, const Points& x, bool project) const;
  void add_stiffness_estimate(const Points& x, std::vector<double>& diag) const;
  // Stress read-out: force / (tributary width x thickness), for springs of known width.
  ElementStress stress(int i, const Points& x, double thickness) const;

  // Composite rule: the resin part (resin and latex in parallel, the resin at rest at its
  // impregnation length) in series with the latex part along the spring.
  void update(int s, const ReleaseLevel& release);
  void update(const ReleaseLevel& release);
  // The frame lets go: every spring's current length is its frame length.
  void begin_release(const Points& x);
  // The latex's rest length at this point of the release, m.
  double latex_rest(int s, const ReleaseLevel& release) const;
  // d/df of stiffness and rest length at the spring's current state.
  SpringRate rate(int s, const ReleaseLevel& release) const;
  // The design's view: the spring's segment, its fraction set, and d/df of (grad E . w).
  ResinFootprint footprint(int s, const Points& x) const;
  void set_resin_fraction(int s, double f, const ReleaseLevel& release);
  double resin_rate(int s, const Points& x, const Points& w, const ReleaseLevel& release) const;

  // Resin rule: springs inside the pattern become the composite,
  // the resin at rest at its current length, as stiff as the resin's lattice of the same family.
  int impregnate(const Impregnation& at);
  // Growth rule: a spring's latex grows by the growth's length ratio along it (read at its paper
  // midpoint; the resin keeps its length), through the composite rule.
  std::vector<LocalGrowth> growth(const GrowthField& field, const Points& paper) const;
  void grow(const std::vector<LocalGrowth>& g, const Points& paper, double exponent,
            const ReleaseLevel& release);
  // Cut rule: a spring goes when the cut crosses it.
  bool severed(int i, const CrossesCut& crosses) const { return crosses(a[i], b[i]); }
  // The rebuilt sheet's springs take the old ones' process state (springs an earlier cut removed
  // stay removed).
  void carry(const Springs& old, const Rebuild& r);
};

}  // namespace membra
