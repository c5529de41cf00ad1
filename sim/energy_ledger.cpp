#include "sim/energy_ledger.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace ejecta {

namespace {

bool moving(const BodySpec& b) {
  return b.velocity[0] != 0.0 || b.velocity[1] != 0.0 || b.velocity[2] != 0.0;
}

bool contains(const std::vector<int>& v, int x) { return std::find(v.begin(), v.end(), x) != v.end(); }

}  // namespace

LedgerGroups ledgerGroups(const Scene& scene) {
  LedgerGroups g;
  for (const BodySpec& b : scene.bodies)
    if (moving(b) && !contains(g.impactor, b.material)) g.impactor.push_back(b.material);
  for (const BodySpec& b : scene.bodies)
    if (!moving(b) && !contains(g.impactor, b.material) && !contains(g.target, b.material))
      g.target.push_back(b.material);
  return g;
}

std::string ledgerKey(const std::string& materialName) {
  std::string out = materialName;
  for (char& c : out)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_')) c = '_';
  return out;
}

void addEnergyPartition(const Scene& scene, const std::vector<double>& initialKinetic,
                        const std::vector<double>& initialInternal,
                        const std::vector<ConservedTotals>& now, RunSummary& summary) {
  const std::size_t n = std::min(scene.materials.size(), now.size());
  const bool haveInitial = initialKinetic.size() == n && initialInternal.size() == n;
  for (std::size_t m = 0; m < n; ++m) {
    const std::string key = "energy_" + ledgerKey(scene.materials[m].name);
    if (haveInitial) {
      summary.extras.push_back({key + "_kinetic_initial_J", initialKinetic[m]});
      summary.extras.push_back({key + "_internal_initial_J", initialInternal[m]});
    }
    summary.extras.push_back({key + "_kinetic_J", now[m].kinetic});
    summary.extras.push_back({key + "_internal_J", now[m].internal});
  }
  const LedgerGroups g = ledgerGroups(scene);
  if (!haveInitial || g.impactor.empty() || g.target.empty()) return;
  double impactorKinetic = 0.0, targetKinetic = 0.0, targetInternalGain = 0.0;
  for (int m : g.impactor) impactorKinetic += initialKinetic[static_cast<std::size_t>(m)];
  for (int m : g.target) {
    const std::size_t k = static_cast<std::size_t>(m);
    targetKinetic += now[k].kinetic - initialKinetic[k];
    targetInternalGain += now[k].internal - initialInternal[k];
  }
  summary.extras.push_back({"impactor_kinetic_energy_J", impactorKinetic});
  summary.extras.push_back({"target_kinetic_gain_J", targetKinetic});
  summary.extras.push_back({"target_internal_gain_J", targetInternalGain});
  if (impactorKinetic > 0.0)
    summary.extras.push_back(
        {"target_share_of_impactor_energy", (targetKinetic + targetInternalGain) / impactorKinetic});
}

}  // namespace ejecta
