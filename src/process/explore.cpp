#include "membra/process/explore.hpp"

#include <algorithm>
#include <string>

#include "membra/measure/form_distance.hpp"
#include "membra/process/run.hpp"

namespace membra {
namespace {

bool any_pinned(const Model& m) {
  for (int p = 0; p < m.num_particles(); ++p)
    if (m.pinned(p)) return true;
  return false;
}

bool same_form(const RunResult& a, const RunResult& b) {
  const Points& xa = a.prepared.membrane.state.x;
  const Points& xb = b.prepared.membrane.state.x;
  if (xa.cols() != xb.cols()) return false;  // a cut made another sheet
  // A cut after the release pulled back through another form meshes the sheet another way
  // (cut_after_motion.hpp): the particles are not the same ones.
  if (a.prepared.membrane.sheet.model.reference != b.prepared.membrane.sheet.model.reference)
    return false;
  const double size = (xa.rowwise().maxCoeff() - xa.rowwise().minCoeff()).norm();
  const bool free = !any_pinned(a.prepared.membrane.sheet.model);
  return form_distance(xa, xb, free) <= kSameFormTolerance * size;
}

// Release k's progress, named as such.
ProgressFn explore_progress(const ProgressFn& progress, int k, int n) {
  if (!progress) return {};
  return [progress, k, n](const Progress& p) {
    Progress q = p;
    q.stage = "explore " + std::to_string(k + 1) + "/" + std::to_string(n) + ": " + p.stage;
    progress(q);
  };
}

}  // namespace

Scene exploration_scene(const Scene& scene, int k) {
  Scene s = scene;
  s.simulation.explore = 1;
  if (k == 0) return s;
  for (ProtocolStep& step : s.protocol)
    std::visit(
        [k](auto& st) {
          if constexpr (requires { st.path.seed; }) {
            st.path.seed += static_cast<std::uint64_t>(k);
            st.path.random_imperfection = true;
          }
        },
        step.step);
  return s;
}

void explore_branches(const Scene& scene, RunResult& first, const ProgressFn& progress) {
  const int n = scene.simulation.explore;
  std::vector<Branch> branches;
  first.explored = n;
  first.unsettled = 0;
  auto consider = [&](const RunResult& r, int k) {
    if (!settled(r)) {
      ++first.unsettled;
      return;
    }
    for (Branch& b : branches)
      if (same_form(b.run, r)) {
        b.releases.push_back(k);
        return;
      }
    branches.push_back({r, {k}});
    branches.back().run.branches.clear();
  };
  consider(first, 0);
  for (int k = 1; k < n; ++k)
    consider(run_scene(exploration_scene(scene, k), explore_progress(progress, k, n)), k);
  // The form found most often first; ties in the order found.
  std::stable_sort(branches.begin(), branches.end(), [](const Branch& a, const Branch& b) {
    return a.releases.size() > b.releases.size();
  });
  first.branches = std::move(branches);
}

}  // namespace membra
