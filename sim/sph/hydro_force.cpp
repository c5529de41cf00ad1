// The force pass: accelerations and energy rates from the stress (pressure alone for fluids,
// pressure plus deviatoric stress for solids), artificial viscosity and conductivity, and for
// solids the velocity gradient that drives the stress rate (docs/design.md, docs/materials.md).
//
// The pair force is the divergence of the stress in one of two forms (SphOptions::form), each
// with the energy equation that is its exact conjugate, so total energy is conserved:
//   Lagrangian: a_i = sum_j m_j [T_i dW_i + T_j dW_j],   T = sigma / (Omega rho s)
//   Interface:  a_i = sum_j m_j [sigma_i/(rho_i s_j) + sigma_j/(rho_j s_i)] dW_ij
// where s is rho (1D, 2D, 3D) or the ring area density eta = 2 pi r rho (RZ), and
//   du_i/dt = sigma_i : L_i / rho_i,  L_i = -sum_j w_ij v_ij (x) grad W
// with the same weights w (m_j/(Omega_i s_i) with grad W(h_i), or m_j/s_j with the averaged
// gradient), so L_i is also the velocity gradient the stress rate uses.
// With sph.gradients = "iad" (fluids, Lagrangian form) each grad W of i is replaced by its
// integral-approach vector A_ij = C_i (x_j - x_i) W_ij(h_i), and j's by C_j (x_j - x_i) W_ij(h_j)
// (sim/sph/iad_matrix.hpp); the viscosity takes their mean. The pairs stay antisymmetric. Unlike
// the kernel gradient's, the mean vector need not point along x_ij, so a single approaching pair
// may heat or cool by its viscosity (SPH-EXA clips each particle's viscous heating at zero, giving
// up exact energy conservation; ejecta keeps the conservation).
// With sph.volume_elements = "generalised" (fluids, Lagrangian form, kernel gradient) the
// volumes are V = X / sum_j X_j W (Hopkins 2013, MNRAS 428, 2840), and the pressure pair term of
// i weighs r_j / r_i, j's r_i / r_j (r = X / m):
//   a_i = -sum_j m_j [(r_j/r_i) P_i/(Omega_i rho_i^2) grad W(h_i)
//                     + (r_i/r_j) P_j/(Omega_j rho_j^2) grad W(h_j)],
// with the energy equation to match: the Lagrangian derivation with X held fixed through the
// step, still antisymmetric in each pair.
// With sph.dissipation = "riemann" (fluids, Lagrangian form, kernel gradient, 1D/2D/3D/RZ) there
// is no artificial viscosity; each pair's pressure is the star pressure P*_ij of its Riemann
// problem along n = (x_j - x_i)/r (sim/sph/terms/riemann_dissipation.hpp; Inutsuka 2002), the
// approaching velocities reconstructed to the midpoint as the reconstructed viscosity does,
// receding ones without a jump (pairStar below), and the pair volume squared is Inutsuka's lowest
// order V_ij^2 = ((1/rho_i + 1/rho_j)/2) ((1/s_i + 1/s_j)/2), s as above (so ((1/rho_i +
// 1/rho_j)/2)^2 but in RZ, where it is the pair mean of each of P/(rho eta)'s two factors):
//   a_i = -sum_j m_j P*_ij V_ij^2 [grad W(h_i) + grad W(h_j)]   (+ RZ's hoop term, as below)
//   du_i/dt = sum_j m_j P*_ij V_ij^2 (v_i . n - u*_ij) |dW(h_i) + dW(h_j)|   (- its work),
// so that the pair's work on i, m_i (v_i . a_i + du_i/dt), is -m_i m_j P*_ij V_ij^2 |dW| u*_ij,
// which j's cancels (its n and u* reversed): total energy is conserved, as is momentum (P* is the
// same seen from either side; in RZ the axial momentum).
#include "sim/sph/hydro_force.hpp"

#include "sim/solid/porosity.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "sim/sph/terms/artificial_conductivity.hpp"
#include "sim/sph/terms/artificial_stress.hpp"
#include "sim/sph/terms/monaghan_viscosity.hpp"
#include "sim/sph/terms/pair.hpp"
#include "sim/sph/terms/riemann_dissipation.hpp"
#include "sim/sph/terms/stress_divergence.hpp"
#include "sim/state/tensor.hpp"

namespace ejecta {

namespace {

// The integral-approach vector of a pair for the particle whose matrix is C and smoothing length
// h: C (x_j - x_i) W(r, h), with dx = x_i - x_j; where C is zero, the kernel gradient
// dW/dr dx / r (dW its derivative at h).
template <template <int> class K, int D>
inline void iadVector(const double* C, bool valid, const double* dx, double r, double rInv,
                      double h, double dW, double A[3]) {
  if (!valid) {
    for (int a = 0; a < D; ++a) A[a] = dW * rInv * dx[a];
    return;
  }
  const double W = r < kKernelSupport * h ? kernelValue<K, D>(r, h) : 0.0;
  for (int a = 0; a < D; ++a) {
    double sum = 0.0;
    for (int b = 0; b < D; ++b) sum -= C[3 * a + b] * dx[b];
    A[a] = sum * W;
  }
}

// Fluids: P/(Omega rho s) (Lagrangian) or P/rho (Interface) of particles [begin, end), real
// and ghost. (The integral-approach gradient keeps omega: the energy equation's compression
// sum_j m_j v_ij . A_ij / omega_i then follows the summation density's own rate, which carries
// omega; without it the 1D Sedov's shock ran 4% fast and did not converge.)
// Godunov (the Riemann-solver dissipation): 1/rho, from which its pairs build their volumes.
template <bool RZ, MomentumForm Form, bool Godunov = false>
void fillPressureTerms(const ParticleSet& p, std::vector<double>& out, TermParticles which) {
  out.resize(p.size());
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < which.count(); ++k) {
    const std::size_t i = which[k];
    const double sigma = RZ ? p.areaDensity[i] : p.rho[i];
    if constexpr (Godunov) out[i] = 1.0 / p.rho[i];
    else
      out[i] = Form == MomentumForm::Interface ? p.P[i] / p.rho[i]
                                               : p.P[i] / (p.omega[i] * p.rho[i] * sigma);
  }
}

// The pair's star state (Riemann dissipation) along n = (x_j - x_i)/r, i on the left, from the
// particles' own densities, pressures and sound speeds and their velocities along n. The
// velocity jump is reconstructed to the midpoint when the particles carry velocity gradients (G:
// 9 per particle, or nullptr), limited by van Leer and never beyond the raw jump, as the
// reconstructed viscosity's; and a receding pair gets none (both sides at its mean velocity, so
// P* is the pressures' impedance-weighted mean): the acoustic rarefaction of a receding pair
// lowers P* by about Z |w| / 2 and so resists every expansion to first order in the spacing,
// which in a blast held the hot interior back (docs/verification.md). Dissipation on approach
// only, as the artificial viscosity's (and the low-dissipation limiter of Zhang, Hu & Adams,
// J. Comput. Phys. 335, 605, 2017). Solved with the lower index on the left, so that both sides
// of a pair of real particles see the same P* to the last bit (through a periodic image, whose
// index follows the real ones, the two sides solve it mirrored: the same to round-off).
template <int D>
StarState pairStar(const PairOrigin& o, const Pair& g, const ParticleSet& p, const double* vi,
                   const double* G) {
  const std::size_t j = g.j;
  double ui = 0.0, uj = 0.0;
  for (int d = 0; d < D; ++d) {
    ui -= vi[d] * g.dx[d] * g.rInv;
    uj -= p.v[d][j] * g.dx[d] * g.rInv;
  }
  const double raw = ui - uj;  // = -v_ij . x_ij / r: positive when approaching
  double jump = std::max(raw, 0.0);
  if (G && jump > 0.0)
    jump = std::clamp(-reconstructedApproach<D>(g.dx, g.dv, &G[9 * o.i], &G[9 * j]) * g.rInv,
                      0.0, jump);
  const double mean = 0.5 * (ui + uj);
  const RiemannSide left{o.rho, mean + 0.5 * jump, o.P, o.cs},
      right{p.rho[j], mean - 0.5 * jump, p.P[j], p.cs[j]};
  if (o.i < j) return twoShockStar(left, right);
  const StarState mirrored = twoShockStar({right.rho, -right.u, right.P, right.c},
                                      {left.rho, -left.u, left.P, left.c});
  return {mirrored.P, -mirrored.u};
}

// pairStar for the pair (i, j) from the particles alone, with the pair's geometry as the force
// pass computes it (SharedPairStars solves the pairs both sides sum before the pass). The pass
// skips a pair at zero distance, so its state is never read.
template <int D>
StarState pairStarOf(const ParticleSet& p, std::size_t i, std::size_t j, const double* G) {
  PairOrigin o;
  o.i = i;
  o.cs = p.cs[i];
  o.rho = p.rho[i];
  o.P = p.P[i];
  const double xi[3] = {p.x[0][i], p.x[1][i], p.x[2][i]};
  const double vi[3] = {p.v[0][i], p.v[1][i], p.v[2][i]};
  Pair g;
  g.j = static_cast<std::uint32_t>(j);
  for (int d = 0; d < D; ++d) {
    g.dx[d] = xi[d] - p.x[d][j];
    g.dv[d] = vi[d] - p.v[d][j];
    g.r2 += g.dx[d] * g.dx[d];
  }
  if (g.r2 == 0.0) return {0.0, 0.0};
  g.r = std::sqrt(g.r2);
  g.rInv = 1.0 / g.r;
  return pairStar<D>(o, g, p, vi, G);
}

// The particles the pairs of `active` read, themselves included, ascending: the only ones whose
// per-particle terms an individual-step sub-step needs (each term's preparation is O(N) work
// otherwise, for the few percent of particles a sub-step evaluates).
std::vector<std::size_t> touchedBy(const ParticleSet& p, const HydroWorkspace& ws,
                                   const std::vector<std::size_t>& active) {
  std::vector<char> mark(p.size(), 0);
  for (std::size_t i : active) {
    mark[i] = 1;
    for (std::uint32_t j : ws.lists.pairs(i)) mark[j] = 1;
  }
  std::vector<std::size_t> touched;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (mark[i]) touched.push_back(i);
  return touched;
}

// The real particles with a pair among the halos [first, ...), and those without, in order.
// (`active`: of those listed only.)
void splitAtHalos(const ParticleSet& p, const HydroWorkspace& ws, std::size_t first,
                  const std::vector<std::size_t>* active, std::vector<std::size_t>& interior,
                  std::vector<std::size_t>& boundary) {
  const std::size_t count = active ? active->size() : p.numReal;
  std::vector<char> touches(count, 0);
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < count; ++k)
    for (std::uint32_t j : ws.lists.pairs(active ? (*active)[k] : k))
      if (j >= first) {
        touches[k] = 1;
        break;
      }
  for (std::size_t k = 0; k < count; ++k)
    (touches[k] ? boundary : interior).push_back(active ? (*active)[k] : k);
}

// One fused loop over the pairs of each real particle; the optional terms are small inline
// objects (sim/sph/terms/) that hold their own per-particle data and say whether they are on.
// Iad: the fluid pair terms with the integral-approach gradient (sim/sph/iad_matrix.hpp) in
// place of the kernel's (Lagrangian form, fluids, 1D/2D/3D; the scene reader refuses the rest).
// Weighted: the generalised volumes' pressure terms (ws.volumeWeight; fluids, Lagrangian form,
// kernel gradient, 1D/2D/3D), a template parameter so that the other passes pay nothing for them.
// Godunov: the Riemann-solver dissipation in place of the viscosity (fluids, Lagrangian form,
// kernel gradient, mass volumes; planar or RZ).
template <template <int> class K, int D, bool RZ, MomentumForm Form, bool Solid, bool Iad = false,
          bool Weighted = false, bool Godunov = false>
void forcePassImpl(ParticleSet& p, HydroWorkspace& ws, const HaloArrival* halos,
                   const std::vector<std::size_t>* active) {
  static_assert(!Iad || (!RZ && !Solid && Form == MomentumForm::Lagrangian));
  static_assert(!Weighted || (!RZ && !Solid && !Iad && Form == MomentumForm::Lagrangian));
  static_assert(!Godunov || (!Solid && !Iad && !Weighted && Form == MomentumForm::Lagrangian));
  const SphOptions& sph = ws.sph;
  const std::size_t nReal = p.numReal;
  constexpr bool kInterface = Form == MomentumForm::Interface;
  const bool continuityHere = kInterface && sph.density == DensityMethod::Continuity;
  const bool evolveAlpha = sph.viscositySwitch != ViscositySwitch::None;

  // The per-particle terms of every particle the pairs read whose values are here: all of them
  // (with `active`, those its pairs read), or all but the halos still in flight (theirs are
  // computed when they arrive).
  const std::size_t known = halos ? halos->first : p.size();
  std::vector<std::size_t> touched;
  TermParticles here{nullptr, 0, known}, arriving{nullptr, known, p.size()};
  if (active) {
    touched = touchedBy(p, ws, *active);
    const auto split = static_cast<std::size_t>(
        std::lower_bound(touched.begin(), touched.end(), known) - touched.begin());
    here = {touched.data(), 0, split};
    arriving = {touched.data(), split, touched.size()};
  }
  MonaghanViscosity<D> viscosity(p, ws, here);
  const ArtificialConductivity conduction(p, sph);
  if (conduction.enabled()) ws.conductionSignal.resize(nReal);
  std::vector<double> pressureTerm;
  std::optional<StressDivergence<D, RZ>> stress;
  std::optional<ArtificialStress<K, D, RZ>> artificialStress;
  if constexpr (Solid) {
    stress.emplace(p, ws, Form, here);
    artificialStress.emplace(p, ws, here);
  }
  const double* iad = Iad ? ws.iadMatrix.data() : nullptr;
  // Generalised volumes (fluids, Lagrangian form): i's pressure term in a pair weighs r_j / r_i,
  // j's r_i / r_j (docs/verification.md); nullptr with the standard volumes.
  const double* volumeWeight = Weighted ? ws.volumeWeight.data() : nullptr;
  if (Weighted && ws.volumeWeight.size() < p.size())
    throw std::logic_error("generalised volumes: a weight for every particle, ghosts included");
  // The Riemann dissipation's velocity gradients (nullptr: the particles' own velocities).
  const double* velocityGradient =
      Godunov && sph.viscosityReconstruction != ViscosityReconstruction::None
          ? ws.velocityGradient.data()
          : nullptr;
  if (velocityGradient && ws.velocityGradient.size() < 9 * p.size())
    throw std::logic_error("riemann dissipation: a velocity gradient for every particle");
  if constexpr (!Solid) fillPressureTerms<RZ, Form, Godunov>(p, pressureTerm, here);
  const bool artificial = Solid && artificialStress->enabled();
  // A porous particle's shear modulus is its matrix's over its distention, times the matrix's
  // share f of the strain (sim/solid/porosity_model.hpp).
  const double* distention = Solid ? distentionColumn(p) : nullptr;
  const double* compaction = Solid ? compactionFactorColumn(p) : nullptr;

  // Godunov: the pairs whose two particles this pass sums, solved once before it.
  SharedPairStars* shared = nullptr;
  if constexpr (Godunov) {
    shared = &ws.sharedStars;
    shared->solveAll(ws.lists, nReal, active, [&](std::size_t i, std::size_t j) {
      return pairStarOf<D>(p, i, j, velocityGradient);
    });
  }

  // Sums particles list[begin, end) (not Listed: begin to end themselves) over their pairs, each
  // into its own derivatives alone. Dynamic chunks balance uneven pair counts. (The loop holds
  // the body: a call per particle cost the solid pass 6% more instructions.)
  auto sumParticles = [&]<bool Listed>(std::size_t begin, std::size_t end, const std::size_t* list) {
#pragma omp parallel for schedule(dynamic, 256)
    for (std::size_t at = begin; at < end; ++at) {
      const std::size_t i = Listed ? list[at] : at;
      PairOrigin o;
      o.i = i;
      o.h = p.h[i];
      o.cs = p.cs[i];
      o.rho = p.rho[i];
      o.u = p.u[i];
      o.P = p.P[i];
      o.sigma = RZ ? p.areaDensity[i] : o.rho;
      const double reachI = kKernelSupport * o.h;
      const double xi[3] = {p.x[0][i], p.x[1][i], p.x[2][i]};
      const double vi[3] = {p.v[0][i], p.v[1][i], p.v[2][i]};
      const double lagrangeWeight = 1.0 / (p.omega[i] * o.sigma);
      double acc[3] = {0.0, 0.0, 0.0};
      double grad[3][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};  // -L_i
      double dudtDivergence = 0.0, dudtViscous = 0.0, dudtConduction = 0.0, dudtRiemann = 0.0;
      double signal = 0.0;  // the conductivity's fastest pair signal heating i
      // The conductivity's exchange with one neighbour, and the fastest signal heating i.
      const auto conduct = [&](const Pair& g) {
        if (!conduction.enabled()) return;
        const auto c = conduction.term(o, g);
        dudtConduction += c.rate;
        signal = std::max(signal, c.inflowSignal);
      };
      const double* Ci = Iad ? &iad[9 * i] : nullptr;
      const bool iadI = Iad && Ci[0] != 0.0;
      std::optional<SharedPairStars::Walk> walk;
      if constexpr (Godunov) walk.emplace(shared->walk(i, omp_get_thread_num()));

      for (std::uint32_t j : ws.lists.pairs(i)) {
        // Every partner, in order, before any is skipped: the walk counts them.
        std::uint32_t sharedAt = SharedPairStars::kNotShared;
        if constexpr (Godunov) sharedAt = walk->index(j);
        Pair g;
        g.j = j;
        for (int d = 0; d < D; ++d) {
          g.dx[d] = xi[d] - p.x[d][j];
          g.dv[d] = vi[d] - p.v[d][j];
          g.r2 += g.dx[d] * g.dx[d];
          g.vdotx += g.dv[d] * g.dx[d];
        }
        if (g.r2 == 0.0) continue;
        g.r = std::sqrt(g.r2);
        g.rInv = 1.0 / g.r;
        g.hj = p.h[j];
        g.dWi = g.r < reachI ? kernelDerivative<K, D>(g.r, o.h) : 0.0;
        g.dWj = g.r < kKernelSupport * g.hj ? kernelDerivative<K, D>(g.r, g.hj) : 0.0;
        g.dWavg = 0.5 * (g.dWi + g.dWj);
        g.mj = p.mass[j];
        g.sigmaJ = RZ ? p.areaDensity[j] : p.rho[j];
        g.sigmaIJ = 0.5 * (o.sigma + g.sigmaJ);
        const double* dx = g.dx;

        if constexpr (Iad) {
          // A_ij = C_i (x_j - x_i) W_ij(h_i) for i, and for j's term its mirror C_j (x_j - x_i)
          // W_ij(h_j) (minus j's own A_ji); the kernel gradient where C is zero.
          const double* Cj = &iad[9 * j];
          double Ai[3], Aj[3];
          iadVector<K, D>(Ci, iadI, dx, g.r, g.rInv, o.h, g.dWi, Ai);
          iadVector<K, D>(Cj, Cj[0] != 0.0, dx, g.r, g.rInv, g.hj, g.dWj, Aj);
          const double visc = g.mj * viscosity.coefficient(o, g);
          double dvA = 0.0, dvAi = 0.0;
          for (int d = 0; d < D; ++d) {
            const double mean = 0.5 * (Ai[d] + Aj[d]);
            acc[d] -= visc * mean + g.mj * (pressureTerm[i] * Ai[d] + pressureTerm[j] * Aj[d]);
            dvA += g.dv[d] * mean;
            dvAi += g.dv[d] * Ai[d];
          }
          dudtViscous += 0.5 * visc * dvA;
          dudtDivergence += g.mj * dvAi;
          conduct(g);
          continue;
        }
        if constexpr (Godunov) {
          const StarState star = sharedAt != SharedPairStars::kNotShared
                                     ? shared->star(sharedAt)
                                     : pairStar<D>(o, g, p, vi, velocityGradient);
          // Inutsuka's (2002) pair volume squared in its lowest order, ((1/rho_i + 1/rho_j)/2)^2,
          // on both kernels: the same for i and j. (The grad-h weights 1/(Omega rho^2) of each
          // side, as the viscosity's pressure terms take them, put 1/rho^2 of the cold side of a
          // shock on P*: with a first version of the solver the 1D Sedov shell then ran 2.5%
          // behind, L1 0.26, against 1.1% and 0.09 with these.) In RZ the kernel sums are of
          // ring masses and the pressure term's 1/(rho eta) becomes the product of its two
          // factors' pair means: with the hoop term it then gives the 3D gradient of P over rho,
          // as the standard RZ form does (docs/rz.md).
          const double volume = 0.5 * (pressureTerm[i] + pressureTerm[j]);  // 1/rho each
          const double area = RZ ? 0.5 * (1.0 / o.sigma + 1.0 / g.sigmaJ) : volume;
          const double weight = g.mj * volume * area * (g.dWi + g.dWj);
          const double f = star.P * weight * g.rInv;
          double ui = 0.0;  // v_i . n
          for (int d = 0; d < D; ++d) {
            acc[d] -= f * dx[d];
            ui -= vi[d] * dx[d] * g.rInv;
          }
          // weight <= 0 (dW <= 0): a particle approaching its partner faster than the contact
          // (u_i > u*) heats when P* > 0.
          dudtRiemann -= star.P * weight * (ui - star.u);
          conduct(g);
          continue;
        }
        const double fVisc = g.mj * viscosity.coefficient(o, g) * g.dWavg * g.rInv;
        for (int d = 0; d < D; ++d) acc[d] -= fVisc * dx[d];
        dudtViscous += 0.5 * fVisc * g.vdotx;

        // Weight of this pair in the velocity gradient (and the energy equation).
        const double wGrad = kInterface ? g.mj / g.sigmaJ * g.dWavg * g.rInv
                                        : g.mj * lagrangeWeight * g.dWi * g.rInv;
        if constexpr (Solid) {
          double wI, wJ;  // factors of T_i and T_j in the pair force
          if constexpr (kInterface) {
            wI = g.mj / g.sigmaJ * g.dWavg * g.rInv;
            wJ = g.mj / o.sigma * g.dWavg * g.rInv;
          } else {
            wI = g.mj * g.dWi * g.rInv;
            wJ = g.mj * g.dWj * g.rInv;
          }
          const double fArt = artificial ? artificialStress->pairWeight(o, g) : 0.0;
          for (int a = 0; a < D; ++a) {
            double sum = 0.0;
            for (int b = 0; b < D; ++b) {
              const int k = kSymIndex[a][b];
              sum += (wI * stress->T[k][i] + wJ * stress->T[k][j]) * dx[b];
              if (artificial) {
                const double rij = artificialStress->sum(k, i, j) * fArt;
                sum += rij * dx[b];
                dudtViscous -= 0.5 * g.dv[a] * rij * dx[b];
              }
              grad[a][b] += wGrad * g.dv[a] * dx[b];
            }
            acc[a] += sum;
          }
        } else {
          double f, ratio = 1.0, inverse = 1.0;
          if constexpr (kInterface) {
            f = g.mj * (pressureTerm[i] / g.sigmaJ + pressureTerm[j] / o.sigma) * g.dWavg * g.rInv;
          } else {
            if constexpr (Weighted) {  // r_j / r_i weighs i's term, r_i / r_j j's
              ratio = volumeWeight[j] / volumeWeight[i];
              inverse = 1.0 / ratio;
            }
            f = g.mj * (ratio * pressureTerm[i] * g.dWi + inverse * pressureTerm[j] * g.dWj) *
                g.rInv;
          }
          for (int d = 0; d < D; ++d) acc[d] -= f * dx[d];
          dudtDivergence += ratio * wGrad * g.vdotx;
        }
        conduct(g);
      }
      if (conduction.enabled()) ws.conductionSignal[i] = signal;

      // Hoop rate v_r / r of RZ, with the smoothed radius near the axis (docs/rz.md).
      const double hoopRate = RZ ? vi[0] * ws.dSmoothedR[i] / ws.smoothedR[i] : 0.0;
      double dudt = dudtViscous + dudtConduction;
      if constexpr (Godunov) dudt += dudtRiemann;
      double divergence;  // div v of the pair weights, for the continuity density
      if constexpr (Solid) {
        Mat3 L{};
        for (int a = 0; a < D; ++a)
          for (int b = 0; b < D; ++b) L[a][b] = -grad[a][b];
        if constexpr (RZ) {
          L[2][2] = hoopRate;
          acc[0] -= stress->hoop[i] * ws.dSmoothedR[i] / (o.rho * ws.smoothedR[i]);
        }
        // sigma_i : L_i / rho_i, with sigma recovered from T (scale undone).
        const double unscale = kInterface ? 1.0 : p.omega[i] * o.sigma;
        double power = 0.0;
        for (int a = 0; a < D; ++a)
          for (int b = 0; b < D; ++b) power += stress->T[kSymIndex[a][b]][i] * unscale * L[a][b];
        if constexpr (RZ) power += stress->hoop[i] * L[2][2] / o.rho;
        dudt += power;
        divergence = L[0][0] + L[1][1] + L[2][2];
        const double G = ws.shearModulus[p.material[i]];
        storeStressRate(p, i, L, distention ? G / distention[i] : G,
                        compaction ? compaction[i] : 1.0);
      } else {
        // P_i/rho_i sum_j w_ij v_ij . grad W = -(P_i/rho_i) (div v)_i
        divergence = -dudtDivergence + hoopRate;
        if constexpr (Iad) dudt += pressureTerm[i] * dudtDivergence;  // sum_j m_j v_ij . A_ij
        else dudt += o.P / o.rho * dudtDivergence;
        if constexpr (RZ) {
          const double hoop = o.P * ws.dSmoothedR[i] / (o.rho * ws.smoothedR[i]);
          acc[0] += hoop;
          dudt -= hoop * vi[0];
        }
      }
      if (continuityHere) {
        // Volume-weighted continuity, d rho/dt = -rho div v with the pair weights m_j/s_j, which
        // does not see the neighbour's density jump at an interface.
        p.drho_dt[i] = -o.rho * divergence;
        if (sph.smoothingLength == SmoothingLengthMethod::Seed)
          p.dh_dt[i] = -sph.relaxation * o.h / (o.rho * D) * p.drho_dt[i];
      }
      for (int d = 0; d < 3; ++d) p.a[d][i] = d < D ? acc[d] : 0.0;
      p.du_dt[i] = dudt;
      if (evolveAlpha)
        p.dalpha_dt[i] = viscositySwitchRate(p.alpha[i], sph.alpha, p.divv[i], o.cs, o.h, sph);
    }
  };

  if (!halos) {
    if (active) sumParticles.template operator()<true>(0, active->size(), active->data());
    else sumParticles.template operator()<false>(0, nReal, nullptr);
    return;
  }
  std::vector<std::size_t> interior, boundary;
  splitAtHalos(p, ws, halos->first, active, interior, boundary);
  constexpr std::size_t kSlices = 8;  // progress() between them
  for (std::size_t s = 0; s < kSlices; ++s) {
    sumParticles.template operator()<true>(interior.size() * s / kSlices,
                                           interior.size() * (s + 1) / kSlices, interior.data());
    if (halos->progress) halos->progress();
  }
  halos->arrive();
  // The halos' own terms, from the values that arrived.
  viscosity.refresh(p, arriving);
  if constexpr (Solid) {
    stress->refresh(p, ws, arriving);
    artificialStress->refresh(p, ws, arriving);
  } else {
    fillPressureTerms<RZ, Form, Godunov>(p, pressureTerm, arriving);
  }
  sumParticles.template operator()<true>(0, boundary.size(), boundary.data());
}

}  // namespace

void initialiseViscosityAlpha(ParticleSet& p, const SphOptions& sph) {
  if (sph.viscositySwitch == ViscositySwitch::None || p.hasViscositySwitch()) return;
  p.enableViscositySwitch(sph.alphaMin);
  if (!p.hasBurn()) return;
  for (std::size_t i = 0; i < p.numReal; ++i)
    if (std::isfinite(p.lightingTime[i])) p.alpha[i] = sph.alpha;
}

void runForcePass(ParticleSet& p, HydroWorkspace& ws, const HaloArrival* halos,
                  const std::vector<std::size_t>* active) {
  const bool solid = p.stressComponents() > 0;
  const MomentumForm form = ws.sph.form;
  const bool weighted = !ws.volumeWeight.empty();
  dispatchHydro(ws, [&]<template <int> class K, int D, bool RZ>() {
    if (ws.sph.dissipation == Dissipation::Riemann) {
      if (weighted || solid || form != MomentumForm::Lagrangian ||
          ws.sph.gradients != GradientScheme::Kernel)
        throw std::logic_error("riemann dissipation: fluids, the Lagrangian form, the kernel "
                               "gradient, mass volumes");
      forcePassImpl<K, D, RZ, MomentumForm::Lagrangian, false, false, false, true>(p, ws, halos,
                                                                                 active);
      return;
    }
    if (ws.sph.gradients == GradientScheme::IntegralApproach) {
      if (weighted) throw std::logic_error("generalised volumes take the kernel gradient");
      if (solid || RZ || form != MomentumForm::Lagrangian || ws.iadMatrix.size() < 9 * p.size())
        throw std::logic_error("integral-approach gradients: fluids, the Lagrangian form, 1D/2D/3D, "
                               "with their matrices computed");
      if constexpr (!RZ) forcePassImpl<K, D, false, MomentumForm::Lagrangian, false, true>(p, ws, halos, active);
      return;
    }
    if (weighted) {
      if (solid || RZ || form != MomentumForm::Lagrangian)
        throw std::logic_error("generalised volumes: fluids, the Lagrangian form, the kernel "
                               "gradient, 1D/2D/3D");
      if constexpr (!RZ)
        forcePassImpl<K, D, false, MomentumForm::Lagrangian, false, false, true>(p, ws, halos, active);
      return;
    }
    if (form == MomentumForm::Interface) {
      if (solid) forcePassImpl<K, D, RZ, MomentumForm::Interface, true>(p, ws, halos, active);
      else forcePassImpl<K, D, RZ, MomentumForm::Interface, false>(p, ws, halos, active);
    } else {
      if (solid) forcePassImpl<K, D, RZ, MomentumForm::Lagrangian, true>(p, ws, halos, active);
      else forcePassImpl<K, D, RZ, MomentumForm::Lagrangian, false>(p, ws, halos, active);
    }
  });
}

}  // namespace ejecta
