// The underwater-explosion references of docs/undex.md as library code: Cole's and Swisdak's
// similitude laws (sim/exact/underwater_explosion_laws.hpp) against the constants they are quoted
// with, and the mapping of an UNDEX scene onto the 1D Lagrangian hydrocode
// (sim/verify/undex_reference.hpp): what it maps a centred charge to, and the key it names when
// it refuses a scene.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/exact/underwater_explosion_laws.hpp"
#include "sim/setup/scene.hpp"
#include "sim/verify/undex_reference.hpp"
#include "support/tiny_undex.hpp"

namespace ejecta {
namespace {

TEST(UnderwaterExplosionLaws, ColeInSiIsHisImperialLaw) {
  // Cole (1948), ch. 7: 21,600 (W^(1/3)/R)^1.13 psi and 58 W^(1/3) (W^(1/3)/R)^(-0.22) us, W in
  // lb and R in ft. The same charge and distance in both unit systems read the same pressure and
  // theta to the rounding of the SI constants (0.02%).
  const double lb = 0.45359237, ft = 0.3048, psi = 6894.757;
  const exact::SimilitudeLaw& cole = exact::kColeTnt;
  for (const auto& [w, r] : {std::pair{1.0, 1.0}, std::pair{0.5, 0.75}, std::pair{100.0, 30.0}}) {
    const double wLb = w / lb, rFt = r / ft;
    const double peakPsi = 21600.0 * std::pow(std::cbrt(wLb) / rFt, 1.13);
    const double thetaUs = 58.0 * std::cbrt(wLb) * std::pow(std::cbrt(wLb) / rFt, -0.22);
    EXPECT_NEAR(cole.peakPressure(w, r), peakPsi * psi, 2e-4 * peakPsi * psi) << w << " kg " << r;
    EXPECT_NEAR(cole.decayTime(w, r), thetaUs * 1e-6, 2e-4 * thetaUs * 1e-6) << w << " kg " << r;
  }
}

TEST(UnderwaterExplosionLaws, ValuesOfDocsUndexTable) {
  // docs/undex.md's table, 1 kg TNT: Cole's peak 52.4 MPa at 1 m and 251 MPa at 0.25 m; theta
  // 92.5 and 68.2 us (Cole), 84.0 and 61.1 us (Swisdak).
  EXPECT_NEAR(exact::kColeTnt.peakPressure(1.0, 1.0), 52.4e6, 0.01e6);
  EXPECT_NEAR(exact::kColeTnt.peakPressure(1.0, 0.25), 251e6, 0.5e6);
  EXPECT_NEAR(exact::kSwisdakTnt.peakPressure(1.0, 1.0), 52.4e6, 1.0);
  EXPECT_NEAR(exact::kColeTnt.decayTime(1.0, 1.0), 92.5e-6, 0.05e-6);
  EXPECT_NEAR(exact::kColeTnt.decayTime(1.0, 0.25), 68.2e-6, 0.05e-6);
  EXPECT_NEAR(exact::kSwisdakTnt.decayTime(1.0, 1.0), 84.0e-6, 0.05e-6);
  EXPECT_NEAR(exact::kSwisdakTnt.decayTime(1.0, 0.25), 61.1e-6, 0.05e-6);
  // Both scale with the cube root of the charge: 8 kg at 2 m reads 1 kg at 1 m, theta twice.
  EXPECT_NEAR(exact::kSwisdakTnt.peakPressure(8.0, 2.0), 52.4e6, 1e-6);
  EXPECT_NEAR(exact::kSwisdakTnt.decayTime(8.0, 2.0), 2.0 * 84.0e-6, 1e-15);
}

// A 1 kg TNT sphere (the undex_rz charge) in a 0.3 m quarter of water: gauges on the axis at 0.1
// m and on the diagonal.
const std::string kRzScene = test::tinyUndexRzScene(R"(
[[gauges]]
name = "axis"
position = ["0.1 m", 0.0]
[[gauges]]
name = "diagonal"
position = ["0.1 m", "0.1 m"]
)");

TEST(UndexReferenceScene, MapsAnRzChargeToASphere) {
  const Scene scene = parseScene(kRzScene, "tiny.toml");
  const verify::UndexReference ref = verify::buildUndexReference(scene, 300);
  EXPECT_EQ(ref.symmetry, 3);
  EXPECT_EQ(ref.side, 0);
  EXPECT_DOUBLE_EQ(ref.chargeRadius, 0.0527);
  EXPECT_DOUBLE_EQ(ref.extent, 0.3);  // the box's far faces; the axis and the wall are mirrors
  EXPECT_NEAR(ref.ambient, 101325.0, 1e-6);
  EXPECT_GT(ref.chargeDetonationEnergy, 4e6);  // TNT's e0, ~4.3 MJ/kg (Dobratz & Crawford)
  ASSERT_EQ(ref.gaugeRadius.size(), 2u);
  EXPECT_DOUBLE_EQ(ref.gaugeRadius[0], 0.1);
  EXPECT_DOUBLE_EQ(ref.gaugeRadius[1], std::hypot(0.1, 0.1));
  EXPECT_DOUBLE_EQ(ref.gaugeDirection[0][0], 1.0);
  EXPECT_DOUBLE_EQ(ref.gaugeDirection[1][0], ref.gaugeDirection[1][1]);
  const exact::RadialSetup& s = ref.setup;
  EXPECT_EQ(s.geometry, 3);
  EXPECT_DOUBLE_EQ(s.zoneWidth, 0.001);
  EXPECT_DOUBLE_EQ(s.outerPressure, ref.ambient);
  ASSERT_EQ(s.regions.size(), 2u);
  EXPECT_EQ(s.regions[0].name, "tnt");
  EXPECT_DOUBLE_EQ(s.regions[0].outerRadius, 0.0527);
  EXPECT_DOUBLE_EQ(s.regions[0].density, 1630.0);
  EXPECT_GT(s.regions[0].burn.velocity, 6000.0);  // TNT's D ~ 6.9 km/s
  EXPECT_EQ(s.regions[1].name, "water");
  EXPECT_DOUBLE_EQ(s.regions[1].outerRadius, 0.3);
  EXPECT_EQ(s.regions[1].burn.velocity, 0.0);
}

TEST(UndexReferenceScene, MapsTheWalledSlabAndThePlanarCharge) {
  const Scene slab =
      loadScene(std::string(EJECTA_SOURCE_DIR) + "/scenes/verification/undex_1d.toml");
  const verify::UndexReference line = verify::buildUndexReference(slab, 800);
  EXPECT_EQ(line.symmetry, 1);
  EXPECT_EQ(line.side, 1);  // lit at its walled end, the slab and the water on one side
  EXPECT_NEAR(line.chargeRadius, 0.1, 1e-12);
  EXPECT_NEAR(line.extent, 0.16, 1e-12);
  const Scene planar = loadScene(std::string(EJECTA_SOURCE_DIR) + "/scenes/undex_2d.toml");
  EXPECT_EQ(verify::buildUndexReference(planar, 100).symmetry, 2);
}

TEST(UndexReferenceScene, RefusesNamingTheFileAndTheKey) {
  auto refusal = [](const std::string& from, const std::string& to) -> std::string {
    std::string text = kRzScene;
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    try {
      verify::buildUndexReference(parseScene(text, "bad.toml"), 100);
    } catch (const SceneError& e) {
      return e.what();
    }
    ADD_FAILURE() << "not refused: " << to;
    return {};
  };
  const std::string offCentre = refusal("center = [0.0, 0.0]", "center = [0.0, 0.02]");
  EXPECT_NE(offCentre.find("bad.toml:"), std::string::npos) << offCentre;
  EXPECT_NE(offCentre.find("key 'bodies[0].center'"), std::string::npos) << offCentre;
  const std::string moving =
      refusal("pressure = \"101325 Pa\"", "pressure = \"101325 Pa\"\nvelocity = [0.0, 10.0]");
  EXPECT_NE(moving.find("key 'bodies[1].velocity'"), std::string::npos) << moving;
  const std::string open = refusal("lower = \"wall\", ", "");
  EXPECT_NE(open.find("key 'bodies[1]'"), std::string::npos) << open;
  EXPECT_NE(open.find("mirror wall"), std::string::npos) << open;
  EXPECT_THROW(verify::buildUndexReference(parseScene(kRzScene, "tiny.toml"), 3),
               std::invalid_argument);
}

}  // namespace
}  // namespace ejecta
