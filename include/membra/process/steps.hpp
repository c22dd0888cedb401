#pragma once
// The protocol's steps, one apply_<kind> each (docs/process.md): each changes the membrane as its
// step says, fills in what it did, and returns the path along which the sheet must then be
// solved (path.hpp). The runner (run.hpp) follows the paths at once; the viewer in slices.
// Each throws InputError naming the step's field when it cannot be carried out (a pattern that
// covers no spring).
#include <vector>

#include "membra/measure/stress_concentration.hpp"
#include "membra/process/path.hpp"

namespace membra {

// What a step did besides changing the membrane, for the report.
struct StepEffects {
  StepReport report;                                // counts; the solve is filled in later
  std::vector<StressFeature> features;              // cut: the new cut or hole edges
  std::optional<CurvatureMapResult> curvature_map;  // curvature_map: target and reach
};

// `pointer` ("/protocol/2") names the step in messages.
Path apply_stretch(Membrane& m, const StretchStep& step, StepEffects& out);
Path apply_impregnate(Membrane& m, const ImpregnateStep& step, const std::string& pointer,
                      StepEffects& out);
Path apply_release(Membrane& m, const ReleaseStep& step, StepEffects& out);
Path apply_grow(Membrane& m, const GrowStep& step, const std::string& pointer, StepEffects& out);
Path apply_curvature_map(Membrane& m, const CurvatureMapStep& step, const std::string& pointer,
                         StepEffects& out);
Path apply_add_springs(Membrane& m, const AddSpringsStep& step, const std::string& pointer,
                       StepEffects& out);
Path apply_cut(Membrane& m, const CutStep& step, const std::string& pointer, StepEffects& out);
// load also pins: it needs the prepared scene's pin count.
Path apply_load(PreparedScene& p, const LoadStep& step, const std::string& pointer,
                StepEffects& out);

// The apply_<kind> of the step's kind.
Path apply_step(PreparedScene& p, const ProtocolStep& step, StepEffects& out);

}  // namespace membra
