#include "membra/design/stencil_trial.hpp"

#include "membra/core/input_error.hpp"
#include "membra/design/resin_face.hpp"

namespace membra {

namespace {

// The pieces laid on `face`, as a stencil of their own (an empty one when there are none).
Stencil on_face(const Stencil& stencil, int face) {
  std::vector<StencilSquare> squares;
  for (const StencilSquare& q : stencil.squares)
    if (q.face == face) squares.push_back(q);
  return stencil_of(squares, stencil.outline_area);
}

// Pieces on both faces: the impregnate step at index 1 takes the top's, a copy after it the
// bottom's, each a bilayer on its own face.
void split_faces(Scene& scene, const Stencil& stencil) {
  Stencil top, bottom;
  if (stencil.squares.empty()) {  // darts: the two parts as laid out
    top.pattern = stencil.pattern;
    top.spec = stencil.spec;
    bottom.pattern = stencil.pattern_bottom;
    bottom.spec = stencil.spec_bottom;
  } else {
    top = on_face(stencil, +1);
    bottom = on_face(stencil, -1);
  }
  auto& resin = std::get<ImpregnateStep>(scene.protocol[1].step);
  ImpregnateStep under = resin;
  under.pattern = bottom.pattern;
  under.pattern_spec = bottom.spec;
  under.resin_side = -1;
  resin.pattern = top.pattern;
  resin.pattern_spec = top.spec;
  resin.resin_side = +1;
  if (!top.pattern) {
    resin = under;
  } else if (bottom.pattern) {
    scene.protocol.insert(scene.protocol.begin() + 2, ProtocolStep{"", under});
  }
  for (size_t i = 0; i < scene.protocol.size(); ++i)
    scene.protocol[i].pointer = "/protocol/" + std::to_string(i);
}

// With `"resin_side": "convex"`: each piece on the face the target's curvature asks for.
void lay_on_convex_faces(Stencil& stencil, const TargetSurface& target, const Box2& frame) {
  for (StencilSquare& q : stencil.squares)
    q.face = convex_face(target, frame, q.centre, 0.5 * q.cell.minCoeff());
}

}  // namespace

Scene stencil_scene(const DesignSpec& spec, const Stencil& stencil) {
  Scene scene = spec.scene;
  if (stencil.pieces_bottom() > 0) {
    split_faces(scene, stencil);
  } else if (stencil.pattern) {
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
  return simulate_stencil(spec, target, design_stencil(spec, target, density));
}

Stencil design_stencil(const DesignSpec& spec, const TargetSurface& target,
                       const std::function<double(const Vec2&)>& density) {
  const Box2 frame{Vec2::Zero(), Vec2(spec.frame, spec.frame)};
  const Vec2 centre = 0.5 * frame.max;
  const auto inside = [&](const Vec2& p) {
    return !target.disk || (p - centre).norm() <= 0.5 * spec.frame;
  };
  Stencil stencil = layout_stencil(density, frame, spec.layout, inside);
  if (spec.resin_side == "convex") lay_on_convex_faces(stencil, target, frame);
  return stencil;
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
