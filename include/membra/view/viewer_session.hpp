#pragma once
// What the viewer edits and simulates, with no window: a scene's membrane taken through the
// protocol one button at a time (stretch, impregnate, release) or step by step through the
// scene's own protocol, every step applied by process/steps.hpp and its path followed in slices
// as `membra run` follows it at once; brush strokes of resin, cuts,
// holes and pins, live K, G, T, D, undo/redo, and a simulation advanced in slices so the UI
// stays responsive. Every action is also logged as a protocol step, so the session saves as an
// ordinary scene that `membra run` reproduces.
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "membra/io/scene.hpp"
#include "membra/measure/self_intersection.hpp"
#include "membra/model/membrane.hpp"
#include "membra/process/increment_walk.hpp"
#include "membra/process/path.hpp"
#include "membra/process/run.hpp"
#include "membra/solve/static_solver.hpp"

namespace membra {

// Where the membrane is in the process.
enum class Stage { flat, stretched, impregnated, released };
const char* stage_name(Stage stage);

// The paper's live mesh variables, in SI, and the stretch the next `stretch` applies.
struct LiveParameters {
  double K = 0.0;   // stretch spring stiffness, N/m (shear and flex keep their ratios)
  double G = 9.81;  // gravity, m/s^2 along -z
  double T = 1e-4;  // time step of the dynamics mode, s
  double D = 0.0;   // damping of the dynamics mode, 1/s
  Vec2 lambda{1.5, 1.0};
};

// How the live simulation moves: relax (the static solver in slices, stable at any setting) or
// dynamics (the scene's integrator with T and D: motion in time, may diverge if T is too big).
enum class LiveMode { relax, dynamics };

// A brush stroke: a disc of resin added (or erased) in frame coordinates.
struct Stroke {
  Vec2 centre;  // m
  double radius = 0.0;
  bool erase = false;
};

// One slice of simulation.
struct SliceReport {
  long iterations = 0;             // solver iterations or time steps in this slice
  double residual_relative = 0.0;  // of the current state
  bool settled = false;            // converged, and no release increment left
  bool diverged = false;           // the state blew up: it was put back as before the slice
  std::string message;
};

// Not to be moved while a step's path is followed: the path refers to the session's membrane.
class ViewerSession {
 public:
  // Builds the flat sheet of `scene` (throws InputError like prepare_scene). The stretch, resin
  // pattern and material of the scene's own steps are the defaults of the buttons.
  explicit ViewerSession(Scene scene);

  const Scene& scene() const { return scene_; }
  // "" or what to know before trusting the live form: the scene's grid may be too coarse for its
  // pattern (grid_resolution.hpp), self-contact is not applied to the live relaxation.
  const std::string& grid_warning() const { return grid_warning_; }
  const Membrane& membrane() const { return prepared_.membrane; }
  Stage stage() const { return stage_; }
  const LiveParameters& parameters() const { return params_; }
  LiveMode mode() const { return mode_; }
  // The pattern the next impregnate applies: the scene's impregnate patterns and the strokes
  // (nullptr when there is none). Frame coordinates.
  PatternPtr resin_pattern() const;
  // The same pattern's description (nothing when there is none).
  std::optional<PatternSpec> resin_pattern_spec() const;
  const std::vector<Stroke>& strokes() const { return strokes_; }
  // The protocol steps done so far.
  const std::vector<ProtocolStep>& log() const { return log_; }

  // The protocol buttons. Each returns "" or why it cannot be done now (then nothing changes).
  std::string stretch();
  std::string impregnate();
  std::string release();
  // Carries out the scene's own protocol, one step each time the sheet has settled.
  void play_scene_protocol();

  // Editing (frame coordinates, m). Paint and erase on the stretched sheet before impregnation;
  // cuts, holes and pins at any stage. Each returns "" or why not (nothing changes then).
  std::string paint(const Vec2& centre, double radius, bool erase = false);
  std::string cut(const Vec2& a, const Vec2& b);
  std::string hole(const Vec2& centre, double radius);
  // Pins the particle nearest to `at` (in the current xy), or frees it if pinned.
  std::string toggle_pin(const Vec2& at);
  // Back to the flat sheet of the scene (undoable).
  void reset();

  // Sets K, G, T, D at once (the model follows; not undoable) and lambda for the next stretch.
  std::string set_parameters(const LiveParameters& p);
  void set_mode(LiveMode mode);

  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }
  bool undo();
  bool redo();
  // An edit made of several calls (a brush drag): the calls between begin_edit() and end_edit()
  // undo as one.
  void begin_edit();
  void end_edit();

  // Advances the simulation by at most `max_iterations` iterations (or steps) and `max_seconds`
  // of wall time (0: no limit). Follows the release path: each increment is solved to
  // equilibrium before the next.
  SliceReport advance(long max_iterations, double max_seconds = 0.0);
  // Advances until settled or `max_iterations` in all have been spent.
  SliceReport settle(long max_iterations = 2'000'000);
  bool settled() const { return settled_; }
  // Where the settled form passes through itself (measure/self_intersection.hpp), as `membra run`
  // reports it: checked each time the sheet settles, none while it moves. The live relaxation
  // has no self-contact, so a form that rolls or folds onto itself can settle through itself.
  const SelfIntersection& crossings() const { return crossings_; }
  // What the last advance() did.
  const SliceReport& last_slice() const { return last_slice_; }

  // The index of the particle whose current xy is nearest to `at`.
  int nearest_particle(const Vec2& at) const;
  // The session as a scene: the source scene with this session's protocol and K, G, T, D.
  Scene to_scene() const;
  // The same as a scene file (io/scene_writer.hpp).
  nlohmann::json to_scene_json() const;

 private:
  struct Snapshot {
    Membrane membrane;
    Stage stage;
    std::vector<Stroke> strokes;
    std::vector<ProtocolStep> log;
    IncrementWalk walk;
    std::vector<Vec2> viewer_pins;
    bool scene_pattern_used;
  };
  Snapshot snapshot() const;
  void restore(const Snapshot& s);
  void push_undo();
  void model_changed();
  // The scene's first step of kind T, or nullptr.
  template <class T>
  const T* first_step() const {
    for (const ProtocolStep& s : scene_.protocol)
      if (const T* t = s.as<T>()) return t;
    return nullptr;
  }
  std::string apply_scene_step(const ProtocolStep& step);
  // Follows `path` from now on (at once in dynamics mode).
  void start_path(Path path);
  SliceReport advance_slice(long max_iterations, double max_seconds);
  // Applies `pattern` with the resin, face and bilayer of `step` (the scene's first impregnate
  // step for painted resin; epoxy on top, soaked through, when the scene has none).
  std::string impregnate_with(const PatternSpec& pattern, const ImpregnateStep* step);

  Scene scene_;
  std::string grid_warning_;
  PreparedScene prepared_;
  Stage stage_ = Stage::flat;
  LiveParameters params_;
  LiveMode mode_ = LiveMode::relax;
  std::vector<Stroke> strokes_;
  std::vector<ProtocolStep> log_;
  std::vector<Vec2> viewer_pins_;    // paper positions of particles pinned in the viewer
  bool scene_pattern_used_ = false;  // the scene's impregnate patterns have been applied
  // The path being followed (release, grow, add_springs, curvature_map: process/path.hpp),
  // increment by increment as `membra run` follows it.
  IncrementWalk walk_;
  bool settled_ = false;
  SelfIntersection crossings_;
  SliceReport last_slice_;
  bool editing_ = false;  // between begin_edit() and end_edit(): one snapshot in all
  bool edit_snapshot_taken_ = false;
  std::deque<Snapshot> undo_, redo_;
  std::deque<const ProtocolStep*> queue_;  // scene steps still to play
  StaticRelaxation relaxation_;
};

}  // namespace membra
