// Tillotson EOS: reference values, region boundaries, sound speed, inversion, batching.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/eos/tillotson.hpp"

namespace ejecta {
namespace {

const TillotsonParameters& granite() { return tillotsonLibrary("granite"); }

// Independent long-double transcription of Benz & Asphaug (1999), appendix, written with
// omega = u/(E0 eta^2) + 1 as printed there (the class uses s = 1/omega).
long double refCold(const TillotsonParameters& p, long double rho, long double u) {
  const long double eta = rho / p.rho0;
  const long double mu = eta - 1.0L;
  const long double omega = u / (p.E0 * eta * eta) + 1.0L;
  return (p.a + p.b / omega) * rho * u + p.A * mu + p.B * mu * mu;
}

long double refHot(const TillotsonParameters& p, long double rho, long double u) {
  const long double eta = rho / p.rho0;
  const long double mu = eta - 1.0L;
  const long double omega = u / (p.E0 * eta * eta) + 1.0L;
  const long double x = p.rho0 / rho - 1.0L;
  return p.a * rho * u +
         (p.b * rho * u / omega + p.A * mu * std::exp(-p.beta * x)) * std::exp(-p.alpha * x * x);
}

long double refPressure(const TillotsonParameters& p, long double rho, long double u) {
  if (rho >= p.rho0 || u <= p.Eiv) return refCold(p, rho, u);
  if (u >= p.Ecv) return refHot(p, rho, u);
  const long double w = (u - p.Eiv) / (p.Ecv - p.Eiv);
  return (1.0L - w) * refCold(p, rho, u) + w * refHot(p, rho, u);
}

double relDiff(double x, double y, double floor = 0.0) {
  return std::abs(x - y) / std::max({std::abs(x), std::abs(y), floor});
}

// c^2 = dP/drho along an isentrope: step du = (P/rho^2) drho with RK4 to rho +- h, then a
// central difference of P. Uses only pressure().
double isentropicC2(const Tillotson& eos, double rho, double u, double h) {
  auto rhs = [&](double r, double e) { return eos.pressure(r, e) / (r * r); };
  auto step = [&](double dr) {
    const double k1 = rhs(rho, u);
    const double k2 = rhs(rho + dr / 2, u + dr / 2 * k1);
    const double k3 = rhs(rho + dr / 2, u + dr / 2 * k2);
    const double k4 = rhs(rho + dr, u + dr * k3);
    return u + dr / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  };
  return (eos.pressure(rho + h, step(h)) - eos.pressure(rho - h, step(-h))) / (2 * h);
}

TEST(Tillotson, LibraryHasTheRequestedMaterialsAndRejectsOthers) {
  for (const char* name : {"granite", "basalt", "ice", "iron", "aluminium"}) {
    EXPECT_EQ(tillotsonLibrary(name).name, name);
    EXPECT_FALSE(tillotsonLibrary(name).source.empty());
  }
  try {
    tillotsonLibrary("unobtainium");
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    for (const auto& name : tillotsonLibraryNames()) EXPECT_NE(what.find(name), std::string::npos);
  }
}

TEST(Tillotson, GraniteMatchesSeedTable32) {
  const auto& g = granite();
  EXPECT_EQ(g.A, 18.0e9);
  EXPECT_EQ(g.B, 18.0e9);
  EXPECT_EQ(g.a, 0.5);
  EXPECT_EQ(g.b, 1.3);
  EXPECT_EQ(g.alpha, 5.0);
  EXPECT_EQ(g.beta, 5.0);
  EXPECT_EQ(g.E0, 16.0e6);
  EXPECT_EQ(g.Eiv, 3.5e6);
  EXPECT_EQ(g.Ecv, 18.0e6);
  EXPECT_EQ(g.rho0, 2680.0);
}

TEST(Tillotson, RejectsInvalidParameters) {
  TillotsonParameters p = granite();
  p.Ecv = p.Eiv;
  EXPECT_THROW(Tillotson{p}, std::invalid_argument);
  TillotsonOptions o;
  o.soundSpeedFloorFraction = 0.0;
  EXPECT_THROW(Tillotson(granite(), o), std::invalid_argument);
}

TEST(Tillotson, ReferenceStateHasZeroPressure) {
  for (const auto& name : tillotsonLibraryNames()) {
    const Tillotson eos(tillotsonLibrary(name));
    EXPECT_EQ(eos.pressure(eos.parameters().rho0, 0.0), 0.0) << name;
  }
}

TEST(Tillotson, HandComputedGranitePointsInEveryRegion) {
  const Tillotson eos(granite());
  const double rho0 = granite().rho0;
  // By hand: 1.2 rho0, u = 0 -> A 0.2 + B 0.04 = 3.6 GPa + 0.72 GPa.
  EXPECT_NEAR(eos.pressure(1.2 * rho0, 0.0), 4.32e9, 4.32e9 * 1e-15);  // 2 roundings
  struct Point {
    double eta, u;
    Tillotson::Region region;
  };
  const std::vector<Point> points{
      {1.2, 1.0e6, Tillotson::Region::Compressed},
      {2.0, 50.0e6, Tillotson::Region::Compressed},
      {0.9, 1.0e6, Tillotson::Region::ColdExpanded},
      {0.7, 3.0e6, Tillotson::Region::ColdExpanded},
      {0.9, 10.0e6, Tillotson::Region::Hybrid},
      {0.5, 15.0e6, Tillotson::Region::Hybrid},
      {0.5, 30.0e6, Tillotson::Region::HotExpanded},
      {0.05, 100.0e6, Tillotson::Region::HotExpanded},
  };
  for (const auto& pt : points) {
    const double rho = pt.eta * rho0;
    EXPECT_EQ(eos.region(rho, pt.u), pt.region) << pt.eta << " " << pt.u;
    const double ref = static_cast<double>(refPressure(granite(), rho, pt.u));
    // ~30 double operations and exp() of arguments <= 5 * 19^2: rounding well below 1e-12.
    EXPECT_LT(relDiff(eos.pressure(rho, pt.u), ref), 1e-12) << pt.eta << " " << pt.u;
  }
}

TEST(Tillotson, GraniteColdCompressionCurveIsAmuPlusBmu2) {
  const Tillotson eos(granite());
  const auto& g = granite();
  for (double eta = 1.0; eta <= 3.0; eta += 0.01) {
    const double mu = eta - 1.0;
    const double expected = g.A * mu + g.B * mu * mu;
    // The energy term is exactly zero at u = 0; only rounding of mu and the sum remains.
    EXPECT_LE(std::abs(eos.pressure(eta * g.rho0, 0.0) - expected), 1e-14 * g.A) << eta;
  }
}

TEST(Tillotson, SeedEquation22VariantDropsQuadraticTermOnlyWhenExpanded) {
  TillotsonOptions o;
  o.quadraticTermWhenExpanded = false;
  const Tillotson eos(granite(), o);
  const auto& g = granite();
  EXPECT_NEAR(eos.pressure(0.8 * g.rho0, 0.0), g.A * (0.8 - 1.0), 1e-15 * g.A);  // rounding
  EXPECT_NEAR(eos.pressure(1.5 * g.rho0, 0.0), g.A * 0.5 + g.B * 0.25, 1e-15 * g.A);
}

TEST(Tillotson, PressureIsContinuousAcrossReferenceDensity) {
  // The standard form is continuous at rho0 for every u: mu = 0 there, and the hot branch's
  // exponentials are 1, so both branches give (a + b/omega) rho0 u.
  for (const auto& name : tillotsonLibraryNames()) {
    const Tillotson eos(tillotsonLibrary(name));
    const auto& p = eos.parameters();
    const double below = std::nextafter(p.rho0, 0.0);
    for (double u : {0.0, 0.5 * p.Eiv, p.Eiv, 0.5 * (p.Eiv + p.Ecv), p.Ecv, 10.0 * p.Ecv,
                     100.0 * p.Ecv}) {
      // One ulp in rho moves P by ~c^2 rho0 1e-16; scale floor 1e-3 A covers P = 0 at u = 0.
      EXPECT_LT(relDiff(eos.pressure(p.rho0, u), eos.pressure(below, u), 1e-3 * p.A), 1e-12)
          << name << " u=" << u;
      // c^2 is continuous there too (the B mu^2 slope and the mu-terms vanish at mu = 0).
      EXPECT_LT(relDiff(eos.soundSpeed(p.rho0, u), eos.soundSpeed(below, u)), 1e-9)
          << name << " u=" << u;
    }
  }
}

TEST(Tillotson, PressureIsContinuousAcrossVaporisationEnergies) {
  for (const auto& name : tillotsonLibraryNames()) {
    const Tillotson eos(tillotsonLibrary(name));
    const auto& p = eos.parameters();
    for (double eta : {0.95, 0.8, 0.5, 0.2}) {
      const double rho = eta * p.rho0;
      const double aboveIv = std::nextafter(p.Eiv, 2.0 * p.Eiv);
      const double belowCv = std::nextafter(p.Ecv, 0.0);
      EXPECT_EQ(eos.region(rho, aboveIv), Tillotson::Region::Hybrid);
      EXPECT_EQ(eos.region(rho, belowCv), Tillotson::Region::Hybrid);
      // One ulp in u; floor 1e-3 A so a near-zero P does not inflate the ratio.
      EXPECT_LT(relDiff(eos.pressure(rho, p.Eiv), eos.pressure(rho, aboveIv), 1e-3 * p.A), 1e-12)
          << name << " eta=" << eta;
      EXPECT_LT(relDiff(eos.pressure(rho, p.Ecv), eos.pressure(rho, belowCv), 1e-3 * p.A), 1e-12)
          << name << " eta=" << eta;
    }
  }
}

TEST(Tillotson, SoundSpeedJumpAtVaporisationEnergiesHasTheKnownSize) {
  // The linear interpolation in u makes dP/du jump by (Ph - Pc)/(Ecv - Eiv) at Eiv and Ecv, so
  // c^2 jumps by (P/rho^2)(Ph - Pc)/(Ecv - Eiv): a property of the standard Tillotson form.
  const Tillotson eos(granite());
  const auto& g = granite();
  for (double eta : {0.5, 0.3}) {  // where the jump is 0.7% to 30% of c^2, above the floor
    const double rho = eta * g.rho0;
    for (double u : {g.Eiv, g.Ecv}) {
      const double below = std::nextafter(u, 0.0);
      const double above = std::nextafter(u, 2.0 * u);
      const long double P = refPressure(g, rho, u);
      const long double dPdu = (refHot(g, rho, u) - refCold(g, rho, u)) / (g.Ecv - g.Eiv);
      const double expected = static_cast<double>(P / (rho * static_cast<long double>(rho)) *
                                                   dPdu * (u == g.Eiv ? 1.0L : -1.0L));
      const double cBelow = eos.soundSpeed(rho, below);
      const double cAbove = eos.soundSpeed(rho, above);
      const double jump = cAbove * cAbove - cBelow * cBelow;
      ASSERT_GT(std::abs(expected), 1e-3 * cBelow * cBelow);  // a jump worth testing
      // Each c^2 is good to ~1e-14 relative; the jump is >= 1e-3 of c^2.
      EXPECT_NEAR(jump, expected, 1e-9 * cBelow * cBelow) << eta << " " << u;
    }
  }
}

TEST(Tillotson, SoundSpeedIsRealAndPositiveOnADenseGridForEveryMaterial) {
  for (const auto& name : tillotsonLibraryNames()) {
    const Tillotson eos(tillotsonLibrary(name));
    const auto& p = eos.parameters();
    const double cMin = std::sqrt(eos.options().soundSpeedFloorFraction * p.A / p.rho0);
    int floored = 0;
    for (int i = 0; i <= 300; ++i) {
      const double eta = 0.01 + (3.0 - 0.01) * i / 300.0;
      for (int j = 0; j <= 300; ++j) {
        const double u = (j == 0) ? 0.0 : 100.0 * p.Ecv * std::pow(1e-6, (300 - j) / 299.0);
        const double c = eos.soundSpeed(eta * p.rho0, u);
        ASSERT_TRUE(std::isfinite(c)) << name << " eta=" << eta << " u=" << u;
        ASSERT_TRUE(std::isfinite(eos.pressure(eta * p.rho0, u))) << name;
        ASSERT_GE(c, cMin) << name << " eta=" << eta << " u=" << u;
        if (c == cMin) ++floored;
      }
    }
    RecordProperty(name + "_floored_points", floored);
  }
}

TEST(Tillotson, SoundSpeedMatchesIsentropicFiniteDifferenceInEachRegion) {
  for (const auto& name : tillotsonLibraryNames()) {
    const Tillotson eos(tillotsonLibrary(name));
    const auto& p = eos.parameters();
    struct Point {
      double eta, u;
    };
    const std::vector<Point> points{
        {1.3, 0.5 * p.Eiv},                   // compressed, cold
        {2.0, 3.0 * p.Ecv},                   // compressed, hot
        {0.9, 0.5 * p.Eiv},                   // cold expanded
        {0.9, 0.5 * (p.Eiv + p.Ecv)},         // hybrid
        {0.6, 0.3 * p.Eiv + 0.7 * p.Ecv},     // hybrid, deeper
        {0.5, 3.0 * p.Ecv},                   // hot expanded
        {0.1, 10.0 * p.Ecv},                  // hot, nearly ideal gas
    };
    for (const auto& pt : points) {
      const double rho = pt.eta * p.rho0;
      const double h = 1e-4 * rho;
      const Tillotson::State st = eos.state(rho, pt.u);
      const double c2 = st.dPdrho + st.P / (rho * rho) * st.dPdu;
      ASSERT_GT(c2, eos.options().soundSpeedFloorFraction * p.A / p.rho0) << name;  // unfloored
      ASSERT_EQ(eos.region(rho - h, pt.u), eos.region(rho + h, pt.u)) << name;  // interior
      const double c = eos.soundSpeed(rho, pt.u);
      // O(h^2) truncation ~1e-8 and rounding ~eps P/(h c^2) ~1e-12; the brief's bound 1e-4.
      EXPECT_LT(relDiff(c * c, isentropicC2(eos, rho, pt.u, h)), 1e-4)
          << name << " eta=" << pt.eta << " u=" << pt.u;
    }
  }
}

TEST(Tillotson, SpecificEnergyRoundTrips) {
  for (const auto& name : tillotsonLibraryNames()) {
    const Tillotson eos(tillotsonLibrary(name));
    const auto& p = eos.parameters();
    for (double eta : {0.05, 0.3, 0.7, 0.95, 1.0, 1.5, 2.5}) {
      const double rho = eta * p.rho0;
      for (double f : {0.0, 0.1, 0.5, 0.99, 1.5, 3.0, 20.0}) {
        const double u = f * 0.5 * (p.Eiv + p.Ecv);
        const double P = eos.pressure(rho, u);
        const double back = eos.specificEnergy(rho, P);
        // The solver stops at machine precision; pressure is resolved to a few ulps of its
        // largest term (A or rho u).
        const double scale = std::max({std::abs(P), p.A * std::abs(eta - 1.0), rho * u, 1.0});
        EXPECT_LT(std::abs(eos.pressure(rho, back) - P), 1e-12 * scale)
            << name << " eta=" << eta << " u=" << u;
        // Smallest root: never above u; equal to u where P rises monotonically with u.
        EXPECT_LE(back, u * (1.0 + 1e-10) + 1e-6) << name;
        const Tillotson::Region r = eos.region(rho, u);
        if (r != Tillotson::Region::Hybrid && r != Tillotson::Region::HotExpanded) {
          EXPECT_NEAR(back, u, 1e-9 * std::max(u, p.Eiv)) << name << " eta=" << eta;
        }
      }
    }
  }
}

TEST(Tillotson, SpecificEnergyRejectsUnreachablePressures) {
  const Tillotson eos(granite());
  const double rho = 1.1 * granite().rho0;
  const double cold = eos.pressure(rho, 0.0);
  EXPECT_THROW(eos.specificEnergy(rho, cold - 1e6), std::domain_error);
  EXPECT_THROW(eos.specificEnergy(0.0, 1e9), std::domain_error);
  EXPECT_THROW(eos.specificEnergy(rho, std::nan("")), std::domain_error);
  EXPECT_EQ(eos.specificEnergy(granite().rho0, 0.0), 0.0);
}

TEST(Tillotson, MinimumPressureClampsTensionAndFloorsSoundSpeed) {
  TillotsonOptions o;
  o.minimumPressure = -1.0e8;
  const Tillotson eos(granite(), o);
  const double rho = 0.8 * granite().rho0;  // cold tension of about -2.9 GPa
  EXPECT_EQ(eos.pressure(rho, 0.0), -1.0e8);
  EXPECT_DOUBLE_EQ(eos.soundSpeed(rho, 0.0),
                   std::sqrt(o.soundSpeedFloorFraction * granite().A / granite().rho0));
  EXPECT_THROW(eos.specificEnergy(rho, -2.0e8), std::domain_error);
  // Without the option the tension is kept.
  EXPECT_LT(Tillotson(granite()).pressure(rho, 0.0), -1.0e9);
}

TEST(Tillotson, BatchedEvaluateEqualsSinglePointFunctions) {
  const Tillotson eos(tillotsonLibrary("basalt"));
  const double rho0 = eos.parameters().rho0;
  std::vector<double> rho, u;
  for (int k = 0; k < 64; ++k) {
    rho.push_back(rho0 * (0.02 + 0.047 * k));
    u.push_back(1.0e5 * std::pow(1.15, k));
  }
  std::vector<std::size_t> idx;
  for (std::size_t k = 1; k < rho.size(); k += 3) idx.push_back(k);
  std::vector<double> P(rho.size(), -7.0), cs(rho.size(), -7.0);
  eos.evaluate(rho.data(), u.data(), P.data(), cs.data(), idx.data(), idx.size());
  for (std::size_t k = 0; k < rho.size(); ++k) {
    const bool listed = (k % 3) == 1;
    // Same code path: bitwise equal; unlisted entries untouched.
    EXPECT_EQ(P[k], listed ? eos.pressure(rho[k], u[k]) : -7.0) << k;
    EXPECT_EQ(cs[k], listed ? eos.soundSpeed(rho[k], u[k]) : -7.0) << k;
  }
}

TEST(Tillotson, DegenerateInputsStayFinite) {
  const Tillotson eos(tillotsonLibrary("iron"));
  for (double rho : {0.0, -1.0, 1e-300}) {
    for (double u : {0.0, -1.0, 1e7, 1e12}) {
      EXPECT_TRUE(std::isfinite(eos.pressure(rho, u))) << rho << " " << u;
      EXPECT_GT(eos.soundSpeed(rho, u), 0.0) << rho << " " << u;
    }
  }
}

}  // namespace
}  // namespace ejecta
