#include "membra/solve/integrator.hpp"

#include "membra/model/forces.hpp"

namespace membra {
namespace {

// a = f / m for free particles, 0 for pinned ones.
void accelerations(const Model& model, const Points& x, const Points& v, Points& f, Points& a) {
  compute_forces(model, x, v, f);
  a.resize(3, x.cols());
  for (int p = 0; p < model.num_particles(); ++p) a.col(p) = model.inv_mass[p] * f.col(p);
}

// Velocities of pinned particles are held at zero so they never drift.
void zero_pinned(const Model& model, Points& v) {
  for (int p = 0; p < model.num_particles(); ++p)
    if (model.pinned(p)) v.col(p).setZero();
}

class Rk4 final : public Integrator {
 public:
  std::string_view name() const override { return "rk4"; }
  int force_passes_per_step() const override { return 4; }

  void step(const Model& model, State& s, double dt) override {
    // Stage k_i = (dx, dv) = (v_i, a(x_i, v_i)).
    zero_pinned(model, s.v);
    accelerations(model, s.x, s.v, f_, a1_);
    v1_ = s.v;
    xt_ = s.x + 0.5 * dt * v1_;
    v2_ = s.v + 0.5 * dt * a1_;
    accelerations(model, xt_, v2_, f_, a2_);
    xt_ = s.x + 0.5 * dt * v2_;
    v3_ = s.v + 0.5 * dt * a2_;
    accelerations(model, xt_, v3_, f_, a3_);
    xt_ = s.x + dt * v3_;
    v4_ = s.v + dt * a3_;
    accelerations(model, xt_, v4_, f_, a4_);
    s.x += dt / 6.0 * (v1_ + 2.0 * v2_ + 2.0 * v3_ + v4_);
    s.v += dt / 6.0 * (a1_ + 2.0 * a2_ + 2.0 * a3_ + a4_);
    zero_pinned(model, s.v);
    s.time += dt;
  }

 private:
  Points f_, a1_, a2_, a3_, a4_, v1_, v2_, v3_, v4_, xt_;
};

class SymplecticEuler final : public Integrator {
 public:
  std::string_view name() const override { return "symplectic_euler"; }
  int force_passes_per_step() const override { return 1; }

  void step(const Model& model, State& s, double dt) override {
    zero_pinned(model, s.v);
    accelerations(model, s.x, s.v, f_, a_);
    s.v += dt * a_;
    zero_pinned(model, s.v);
    s.x += dt * s.v;
    s.time += dt;
  }

 private:
  Points f_, a_;
};

}  // namespace

std::unique_ptr<Integrator> make_rk4() {
  return std::make_unique<Rk4>();
}
std::unique_ptr<Integrator> make_symplectic_euler() {
  return std::make_unique<SymplecticEuler>();
}

std::unique_ptr<Integrator> make_integrator(std::string_view name) {
  if (name == "rk4") return make_rk4();
  if (name == "symplectic_euler") return make_symplectic_euler();
  return nullptr;
}

std::vector<std::string_view> integrator_names() {
  return {"rk4", "symplectic_euler"};
}

}  // namespace membra
