#include "membra/process/run.hpp"

#include "membra/process/path.hpp"
#include "membra/process/steps.hpp"
#include "membra/process/summary.hpp"

namespace membra {

RunResult run_scene(const Scene& scene, const ProgressFn& progress) {
  RunResult r;
  r.prepared = prepare_scene(scene);
  FrameRecorder recorder{scene.output.frames, &r.frames};
  State& s = r.prepared.membrane.state;
  auto record = [&](StepReport step) {
    accumulate(r.solve, step.solve);
    r.steps.push_back(std::move(step));
    return !r.solve.diverged;
  };
  if (scene.protocol.empty())
    record({"solve", solve_scene_step(scene, r.prepared, s, "solve", progress, &recorder), 0});
  std::function<double(const Vec2&)> curvature_field;  // of the last curvature_map step
  for (const ProtocolStep& step : scene.protocol) {
    StepEffects effects;
    const Path path = apply_step(r.prepared, step, effects);
    for (StressFeature& f : effects.features) r.features.push_back(std::move(f));
    if (effects.curvature_map) r.curvature_map = std::move(effects.curvature_map);
    const StepReport followed =
        follow_path(scene, r.prepared, s, effects.report.name, path, progress, recorder);
    effects.report.solve = followed.solve;
    if (const auto* cm = step.as<CurvatureMapStep>()) curvature_field = cm->curvature;
    if (!record(std::move(effects.report))) break;
  }
  if (!r.solve.diverged) summarize_run(r, curvature_field);
  return r;
}

}  // namespace membra
