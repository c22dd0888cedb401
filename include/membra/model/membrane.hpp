#pragma once
// The membrane being processed: its sheet and state, and what the protocol has done to it so
// far (frame, resin). The protocol steps (docs/process.md) are small functions of it; the
// solves between them are the caller's (see process/run.hpp).
#include <cstdint>
#include <vector>

#include "membra/model/material.hpp"
#include "membra/model/pattern.hpp"
#include "membra/model/sheet.hpp"

namespace membra {

struct Membrane {
  Sheet sheet;  // sheet.model's element sets hold their latex and resin state (model/elements/)
  State state;

  // The patterns impregnated since the sheet last moved (frame coordinates), all and the coats
  // on one face among them: a spring, element or hinge that two adjacent patterns share is as
  // much resin as their union makes it. A stretch or the release clears them (the sheet has moved
  // under the patterns' frame coordinates).
  std::vector<PatternPtr> impregnated, coats;

  std::vector<int> frame;      // particles the frame holds (empty once released)
  Vec2 stretch{1.0, 1.0};      // frame stretch ratios applied so far
  int resin_side = +1;         // +1 resin on top (z > 0 face), -1 on the bottom
  bool releasing = false;      // the release has begun: latex rest lengths follow release_level
  double release_level = 1.0;  // 1 = latex relaxed at its frame length, 0 = back to natural

  ReleaseLevel release() const { return {releasing, release_level}; }
};

// Wraps a freshly built sheet (at rest, nothing pinned by the frame).
Membrane make_membrane(Sheet sheet);

// What the process did to `from`, carried over to `to`, a sheet rebuilt without some of its
// particles (new_of_old: the new particle of each old one, -1 if removed): positions,
// velocities and time, pins, gravity and damping, the frame, the stretch, the resin and the
// release. The element sets carry their own state (set_context.hpp, Rebuild).
void carry_process_state(const Membrane& from, const std::vector<int>& new_of_old, Membrane& to);

// Which edges of the sheet the frame holds.
struct FrameEdges {
  bool left = true, right = true, bottom = true, top = true;
};

// stretch: maps positions by (lx, ly) and pins the held edges to the frame (all four by
// default; only left and right for a uniaxial stretch whose free sides may contract). An edge is
// the sheet's outer rim seen from that side (the first or last node of each row or column), so a
// disk is held all round its circle and the rims of holes are left free.
// Requires lx, ly > 0. Returns the number of frame particles.
int stretch_frame(Membrane& m, double lx, double ly, FrameEdges edges = {});

// impregnate: the elements of every set inside `pattern` (frame coordinates, evaluated at
// the current positions) become a latex-resin composite whose resin part is at rest at its
// current length. Returns the number of springs that received resin. `side` is +1 (top) or -1.
// With `bilayer`, the resin also sits on that face only and the composite curls on release
// (bilayer.hpp); without it, the resin soaks the whole thickness and only shortens in plane.
// The membrane keeps the pattern: a later pattern that meets it edge to edge makes the springs
// and elements they share whole resin.
int impregnate(Membrane& m, const PatternPtr& pattern, const Material& resin, int side,
               bool bilayer = false);

// release (start): the frame lets go. Latex rest lengths are set to the current lengths
// (release_level 1), so the sheet starts in equilibrium; lowering the level to 0 then returns
// the latex to its natural length gradually (a path, see docs/process.md).
void begin_release(Membrane& m);
// Sets the release level in [0, 1] and updates rest lengths, stiffnesses and hinge moments.
void set_release_level(Membrane& m, double level);

// Deterministic out-of-plane perturbation that breaks the symmetry of a flat sheet: a smooth
// bump of `amplitude` (m) towards the resin side plus 10 % seeded noise.
void perturb(Membrane& m, double amplitude, std::uint64_t seed);
// Another imperfection, for exploring the stable forms a pattern can take (simulation.explore):
// a seeded mix of the sheet's nine lowest sine modes (either sign, twist included), scaled so its
// largest deflection is `amplitude` (m), plus 10 % seeded noise.
void perturb_randomly(Membrane& m, double amplitude, std::uint64_t seed);

// Rest lengths, stiffnesses and moments of every element set from its composite rule and the
// release level (docs/process.md).
void update_elements(Membrane& m);

}  // namespace membra
