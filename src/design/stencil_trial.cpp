#include "membra/design/stencil_trial.hpp"

#include "membra/core/input_error.hpp"

namespace membra {

Scene stencil_scene(const DesignSpec& spec, const Stencil& stencil) {
  Scene scene = spec.scene;
  if (stencil.pattern) {
    auto& resin = std::get<ImpregnateStep>(scene.protocol[1].step);
    resin.pattern = stencil.pattern;
    resin.pattern_spec = stencil.spec;
  } else {
    // No resin: stretch and release only, numbered as the scene file numbers them.
    scene.protocol.erase(scene.protocol.begin() + 1);
    scene.protocol[1].pointer = "/protocol/1";
  }
  return scene;
}

StencilTrial try_stencil(const DesignSpec& spec, const TargetSurface& target,
                         const std::function<double(const Vec2&)>& density) {
  const Box2 frame{Vec2::Zero(), Vec2(spec.frame, spec.frame)};
  const Vec2 centre = 0.5 * frame.max;
  const auto inside = [&](const Vec2& p) {
    return !target.disk || (p - centre).norm() <= 0.5 * spec.frame;
  };
  return simulate_stencil(spec, target, layout_stencil(density, frame, spec.layout, inside));
}

StencilTrial simulate_stencil(const DesignSpec& spec, const TargetSurface& target,
                              Stencil stencil) {
  StencilTrial e;
  e.stencil = std::move(stencil);
  e.scene = stencil_scene(spec, e.stencil);
  try {
    e.run = run_scene(e.scene);
  } catch (const InputError& err) {
    // E.g. squares so small on a coarse grid that they cover no spring: not a form.
    e.note = std::string("not simulated: ") + err.what();
    return e;
  }
  if (e.run.solve.diverged) {
    e.note = "diverged";
    return e;
  }
  if (!e.run.solve.converged) e.note = "did not converge";
  const Membrane& m = e.run.prepared.membrane;
  e.error = compare_shapes(m.state.x, m.sheet.triangles, target);
  e.rms = 100.0 * e.error.rms / target.diameter;
  e.max = 100.0 * e.error.max / target.diameter;
  return e;
}

DesignIteration trial_iteration(const StencilTrial& trial, int index, double seconds) {
  DesignIteration it;
  it.index = index;
  it.rms_error = trial.rms;
  it.max_error = trial.max;
  it.resin_share = trial.stencil.resin_share;
  it.pieces = trial.stencil.pieces;
  it.seconds = seconds;
  it.note = trial.note;
  return it;
}

void adopt_stencil(StencilTrial&& trial, DesignResult& r) {
  r.scene = std::move(trial.scene);
  r.stencil = std::move(trial.stencil);
  r.run = std::move(trial.run);
  r.error = std::move(trial.error);
  r.rms_error = trial.rms;
  r.max_error = trial.max;
}

}  // namespace membra
