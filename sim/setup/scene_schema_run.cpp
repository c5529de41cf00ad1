// The scene's schema: the document's tables, [scene], [domain], [sph], [time] and [output]
// (read in scene_run_sections.cpp). Defaults are those the reader applies: SphOptions
// (sim/sph/sph_options.hpp), TimeOptions, OutputOptions.
#include "sim/setup/scene_schema.hpp"

namespace ejecta::scene_schema_detail {

using namespace config::keys;

std::vector<SceneTable> runTables() {
  const Dimension m = Dimension::Length;
  const Dimension s = Dimension::Time;
  const std::vector<std::string_view> sides{"open", "periodic", "wall"};
  const config::KeyList axis{
      quantity("min", m, "required", "lower bound (RZ r: 0, the axis)"),
      quantity("max", m, "required", "upper bound, > min"),
      choice("boundary", sides, "—", "both sides; not together with `lower`/`upper`"),
      choice("lower", sides, "\"open\"",
             "the lower side (RZ r: the axis; absent or `\"axis\"`)"),
      choice("upper", sides, "\"open\"", "the upper side (RZ r: not periodic)"),
  };
  return {
      {"",
       "Top-level tables",
       "",
       {table("scene", "required", "`[scene]`: name and dimension"),
        table("domain", "unbounded, open", "`[domain]`: bounds and boundaries per axis"),
        table("sph", "defaults below", "`[sph]`: kernel, density, smoothing length, time step, "
                                        "artificial viscosity"),
        table("time", "required", "`[time]`: end time and step limits"),
        table("output", "defaults below", "`[output]`: snapshots"),
        table("fields", "no grids", "`[fields]`: sparse VDB grids during the run (docs/fields.md)"),
        table("crater", "impact scenes are measured",
              "`[crater]`: the crater measured at the end of an impact run (docs/crater.md)"),
        table("fragments", "none",
              "`[fragments]`: fragments identified at the end of the run (docs/fragments.md)"),
        table("shield", "none",
              "`[shield]`: a Whipple shield's perforation verdict and debris cloud (docs/whipple.md)"),
        tableArray("materials", "required", "`[[materials]]`: at least one"),
        tableArray("bodies", "required",
                   "`[[bodies]]`: at least one making particles; earlier bodies win where shapes "
                   "overlap"),
        tableArray("energy_deposits", "none", "`[[energy_deposits]]`: energy added to particles"),
        tableArray("detonations", "none",
                   "`[[detonations]]`: programmed burn of a JWL explosive (docs/sources.md)"),
        tableArray("gauges", "none",
                   "`[[gauges]]`: pressure, density and velocity every step into `gauges.csv` "
                   "(docs/undex.md)"),
        table("images", "no pictures", "`[images]`: pictures during the run (docs/render.md)"),
        table("thermal", "none",
              "`[thermal]`: the radiation chain in-situ (docs/thermal.md)")}},
      {"scene",
       "`[scene]` (required)",
       "",
       {text("name", "required", "run name (non-empty)"),
        text("description", "\"\"", "free text"),
        choice("dimension", {"1d", "2d", "rz", "3d"}, "required",
               "`\"2d\"` is planar, per unit depth; `\"rz\"` axisymmetric (x = r ≥ 0, y = z)")}},
      {"domain",
       "`[domain]`",
       "An omitted axis is unbounded and open; axes beyond the dimension are errors (`z` in 2D).",
       {table("x", "unbounded, open", "axis x (RZ: r), a table such as "
                                      "`{ min = -1, max = 1, boundary = \"wall\" }`"),
        table("y", "unbounded, open", "axis y (RZ: z)"),
        table("z", "unbounded, open", "axis z (3D only)")}},
      {"domain.x", "`[domain.x]`, `[domain.y]`, `[domain.z]`", "", axis},
      {"domain.y", "", "", axis},
      {"domain.z", "", "", axis},
      {"sph",
       "`[sph]`",
       "",
       {choice("kernel", {"cubic_spline", "wendland_c2", "wendland_c4"}, "\"cubic_spline\"",
               "the smoothing kernel"),
        choice("density", {"summation", "continuity"}, "\"summation\"",
               "density by kernel summation or by the continuity equation"),
        choice("smoothing_length", {"neighbours", "seed", "constant"}, "\"neighbours\"",
               "`\"neighbours\"`: h = η (m/ρ)^(1/d); `\"seed\"`: relaxed update; `\"constant\"`"),
        number("eta", "1.2", "η in [0.5, 3]; also sets the initial h = η·(cell volume)^(1/d)"),
        number("relaxation", "1.0", "θ of the seed's h update, in (0, 1]"),
        number("courant", "0.3", "Courant factor, in (0, 1]"),
        number("force_factor", "0.25", "dt ≤ force_factor·√(h/|a|), > 0"),
        number("h_min_factor", "1e-3", "h below this × initial h stops the run, in [0, 1)"),
        number("h_max_factor", "0",
               "each particle's h held at this × its first h (0: no cap; else [1, 30]): "
               "particles thrown clear of a body keep a bounded kernel"),
        table("viscosity", "defaults below", "`[sph.viscosity]`: Monaghan artificial viscosity"),
        table("conductivity", "off", "`[sph.conductivity]`: artificial conductivity"),
        choice("form", {"lagrangian", "interface"}, "\"lagrangian\"",
               "pair force: `\"lagrangian\"` (grad-h) or `\"interface\"` ((σ_i+σ_j)/(ρ_iρ_j): "
               "use it, with continuity density, for material interfaces; `docs/materials.md`)"),
        choice("gradients", {"kernel", "iad"}, "\"kernel\"",
               "the gradient of the pair terms: `\"kernel\"`, the kernel's own; `\"iad\"`: the "
               "integral approach (García-Senz et al. 2012), exact for linear fields on any "
               "particle arrangement; fluids, Lagrangian form, summation density, 1D/2D/3D, "
               "global steps, one rank (`docs/verification.md`, \"Sharper shocks\")"),
        choice("volume_elements", {"mass", "generalised"}, "\"mass\"",
               "the particle volumes of the kernel sums: `\"mass\"`, m/ρ; `\"generalised\"`: "
               "X/Σ X_j W with X = (m/ρ)^p (Hopkins 2013; Cabezón et al. 2017), sharper across "
               "density jumps; fluids, Lagrangian form, summation density, kernel gradient, "
               "1D/2D/3D, global steps, one rank (`docs/verification.md`, \"Generalised volume "
               "elements\")"),
        number("volume_exponent", "0.7",
               "p of X = (m/ρ)^p for `volume_elements = \"generalised\"`, in [0, 1] (0: X = 1; "
               "1: the step before's volumes; 0.7 measured the better balance on the blasts)"),
        choice("dissipation", {"viscosity", "riemann"}, "\"viscosity\"",
               "what dissipates at a shock: `\"viscosity\"`, Monaghan's artificial viscosity "
               "(`[sph.viscosity]`); `\"riemann\"`: Godunov SPH (Inutsuka 2002), each pair's "
               "pressure the star pressure of its Riemann problem (shocks by the γ = 1.4 gas's "
               "jump conditions, rarefactions acoustic), approaching pairs' velocities "
               "reconstructed as `sph.viscosity.reconstruction` says (default `\"monotone\"` "
               "with it); `[sph.viscosity]` alpha and beta then set only the time step's signal "
               "speed and its switch and Balsara's factor do nothing, while `[sph.conductivity]` "
               "adds to it (in RZ it holds the axis without it: `docs/rz.md`); fluids, "
               "Lagrangian form, summation density, kernel gradient, mass volumes, 1D/2D/3D/RZ, "
               "global or individual steps, one rank "
               "(`docs/verification.md`, \"Riemann-solver dissipation\")"),
        table("artificial_stress", "defaults below",
              "`[sph.artificial_stress]`: Monaghan (2000) against the tensile instability; "
              "solids only")}},
      {"sph.viscosity",
       "`[sph.viscosity]`",
       "Monaghan artificial viscosity.",
       {number("alpha", "1.0", "linear term, ≥ 0; with a switch, its maximum α_max"),
        number("beta", "2.0", "quadratic term, ≥ 0; with a switch, the pair's β is (β/α_max)·α_ij"),
        number("epsilon", "0.01", "regulariser φ² = ε h², > 0"),
        boolean("balsara", "false", "Balsara shear switch"),
        choice("switch", {"none", "morris_monaghan"}, "\"none\"",
               "`\"none\"`: constant α; `\"morris_monaghan\"`: α per particle, dα_i/dt = −(α_i − α_min) ℓ c_i/h_i + "
               "max(−∇·v_i, 0)(α_max − α_i) (Morris & Monaghan 1997; `docs/undex.md`)"),
        number("alpha_min", "0.1", "the switch's floor α_min, in [0, alpha]"),
        number("decay", "0.2", "the switch's ℓ: α decays over τ = h/(ℓ c), > 0"),
        choice("reconstruction", {"none", "van_leer", "monotone"}, "\"none\"",
               "velocities the linear (α) term compares: `\"none\"`, the particles' own; "
               "`\"monotone\"`: "
               "each carried to the pair's midpoint along its corrected velocity gradient, "
               "limited to its neighbours' range (Barth & Jespersen) and by van Leer's limiter "
               "(a linear flow feels no viscosity, a weak shock stays a few h wide; the UNDEX "
               "scenes use it); `\"van_leer\"`: without the range limit (rings behind weak "
               "shocks, not recommended). The quadratic term takes the raw velocities; "
               "`docs/undex.md`, \"The reconstructed viscosity\". With `sph.dissipation = "
               "\"riemann\"` it reconstructs the Riemann problems' approaching velocities the "
               "same way and defaults to `\"monotone\"`")}},
      {"sph.conductivity",
       "`[sph.conductivity]`",
       "",
       {number("alpha", "0", "artificial conductivity coefficient (Price 2008), ≥ 0; 0 = off")}},
      {"sph.artificial_stress",
       "`[sph.artificial_stress]`",
       "",
       {number("epsilon", "0.3 with a strength material, else 0",
               "ε of the artificial stress, ≥ 0; 0 = off"),
        number("n", "4", "exponent of f = W(r)/W(Δp), > 0")}},
      {"time",
       "`[time]` (required)",
       "",
       {quantity("t_end", s, "required", "end time, > 0"),
        quantity("dt_max", s, "0", "largest step; 0 = unlimited"),
        quantity("dt_min", s, "0",
                 "a step below this stops the run; 0 = 1e-12 t_end; below dt_max"),
        integer("max_steps", "0", "most steps; 0 = unlimited (sub-steps with individual steps)"),
        choice("stepping", {"global", "individual"}, "\"global\"",
               "one step for all particles, or each on its own power-of-two time bin "
               "(docs/time_steps.md)"),
        integer("limiter_factor", "2",
                "individual steps: most a step may exceed a neighbour's, a power of two; 0 = "
                "no limiter"),
        boolean("closing_speed", "false",
                "the Courant step takes the fastest closing pair where it exceeds h |div v| "
                "(bodies that meet; docs/time_steps.md)")}},
      {"output",
       "`[output]`",
       "",
       {quantity("snapshot_interval", s, "0", "time between snapshots, at least t_end / 100000; 0 = first and last only"),
        boolean("snapshots", "true", "write snapshots at all")}},
  };
}

}  // namespace ejecta::scene_schema_detail
