// ejecta: hypervelocity-impact and subsurface-explosion simulation. See README.md.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <new>
#include <optional>
#include <string>
#include <thread>

#include "apps/cli_reference.hpp"
#include "apps/commands.hpp"
#include "apps/launch_check.hpp"
#include "apps/thread_limit.hpp"
#include "core/join.hpp"
#include "sim/io/snapshot.hpp"  // kEjectaVersion
#include "sim/parallel/communicator.hpp"

namespace {

// Thread and job counts: at least 1, at most 4 per core of this machine (oversubscription past
// that only slows a run; 100000 is a typo).
CLI::Validator countPerCore(const char* what) {
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const int most = static_cast<int>(4 * cores);
  return CLI::Validator(
      [most, cores, what](std::string& text) -> std::string {
        int n = 0;
        if (!CLI::detail::lexical_cast(text, n) || n < 1 || n > most)
          return std::string(what) + " must be a whole number from 1 to " + std::to_string(most) +
                 " (4 per core of the " + std::to_string(cores) + " here), not '" + text + "'";
        return {};
      },
      "1-" + std::to_string(most));
}

// A count from 1 to `most` (rays, zones, pixels), with the reason on refusal.
CLI::Validator countInRange(const char* what, long long most, const char* why) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        long long n = 0;
        if (!CLI::detail::lexical_cast(text, n) || n < 1 || n > most)
          return std::string(what) + " must be a whole number from 1 to " + std::to_string(most) + " (" + why +
                 "), not '" + text + "'";
        return {};
      },
      "1-" + std::to_string(most));
}

constexpr const char* kExitCodes =
    "Exit status: 0 success; 1 bad input or a refused request (the message names the file, key "
    "and reason); 2 a run or study that started and failed (its summary says why); 130 / 143 a "
    "run stopped by SIGINT / SIGTERM after writing a last snapshot (resume with --restart).";

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ejecta: SPH hydrocode for impacts and explosions on asteroids"};
  app.footer(kExitCodes);
  app.require_subcommand(1);
  const std::string version = "ejecta " + std::string(ejecta::kEjectaVersion);
  app.set_version_flag("--version", version);

  ejecta::app::RunArgs run;
  CLI::App* runCmd = app.add_subcommand("run", "Run a scene (no SCENE: the embedded default scene)");
  runCmd->add_option("scene", run.scene, "Scene file (TOML), or a shipped scene's name (ejecta scenes)");
  runCmd->add_option("--out,-o", run.outDir, "Output directory (default runs/<scene name>)");
  runCmd->add_option("--set", run.overrides, "Override a scene key: --set sph.kernel=wendland_c2")->take_all();
  runCmd->add_option("--threads,-j", run.threads, "OpenMP threads (default: all cores)")
      ->check(countPerCore("--threads"));
  runCmd->add_flag("--overwrite", run.overwrite,
                   "Replace an earlier run in the output directory (its outputs are removed)");
  runCmd->add_option("--restart", run.restartDir,
                     "Resume the run in RUN_DIR from its last snapshot (with --set time.t_end=...: extend it)");
  runCmd
      ->add_option(
          "--progress-every", run.progressEvery,
          "When stderr is not a terminal (a batch job's log): a progress line every this many seconds (default 60)")
      ->check(CLI::Range(0.001, 1e6).description("0.001 to 1e6 s"));
  runCmd->add_flag("--quiet,-q", run.quiet, "No progress line");
  runCmd->add_flag("!--no-charts", run.charts, "Write the CSVs but draw no charts");

  ejecta::app::VerifyArgs verify;
  CLI::App* verifyCmd = app.add_subcommand("verify", "Run a verification problem against its exact solution");
  verifyCmd->add_option("name", verify.name,
                        "Problem name (see --list), or \"all\" for a markdown table of every problem");
  verifyCmd->add_flag("--list", verify.list, "List the problems");
  verifyCmd->add_flag("--json", verify.json, "Print the error measures as JSON");
  verifyCmd->add_option("--threads,-j", verify.threads, "OpenMP threads")->check(countPerCore("--threads"));
  verifyCmd->add_option("--set", verify.overrides, "Override a key of the problem's scene")->take_all();
  verifyCmd->add_option("--resolutions", verify.resolutions, "Number of resolutions for the convergence study");
  verifyCmd->add_option("--out,-o", verify.outDir,
                        "Write profiles, the convergence table (CSV) and their charts (PNG) here");
  verifyCmd->add_flag("--no-charts", verify.noCharts, "With --out: the CSVs only");

  // --threads of the commands that do not hand a count to a library (apps/thread_limit.hpp).
  int commandThreads = 0;
  const auto addThreads = [&commandThreads](CLI::App* command) {
    command->add_option("--threads,-j", commandThreads, "Threads (OpenMP and TBB; default: all cores)")
        ->check(countPerCore("--threads"));
  };

  ejecta::app::FieldsArgs fieldsArgs;
  CLI::App* fieldsCmd = app.add_subcommand("fields", "Grid a snapshot's particles into sparse OpenVDB grids");
  fieldsCmd->add_option("snapshot", fieldsArgs.snapshot, "Snapshot (.h5)")->required();
  fieldsCmd->add_option("--out,-o", fieldsArgs.out, "Output file (default fields.vdb)");
  fieldsCmd->add_option("--voxel", fieldsArgs.voxel, "Voxel size, e.g. \"0.2 m\" (default: median smoothing length)");
  fieldsCmd->add_option("--grids", fieldsArgs.grids, "Grids: density,temperature,pressure,damage,fractions,...")
      ->delimiter(',');
  fieldsCmd->add_option("--normalise", fieldsArgs.normalise, "auto | shepard | none");
  fieldsCmd->add_flag("--no-level-set", fieldsArgs.noLevelSet, "Do not add the surface level set");

  ejecta::app::CraterArgs craterArgs;
  CLI::App* craterCmd = app.add_subcommand("crater", "Measure the crater in a snapshot or a grid file");
  craterCmd->add_option("input", craterArgs.input, "Snapshot (.h5) or grid file (.vdb)")->required();
  craterCmd->add_flag("--json", craterArgs.json, "Print the measures and profile as JSON");
  craterCmd->add_option("--profile", craterArgs.profile, "Write the radial profile as CSV");
  craterCmd->add_option("--resolution", craterArgs.resolution, "Measuring resolution, e.g. \"0.1 m\"");

  ejecta::app::SweepArgs sweepArgs;
  CLI::App* sweepCmd =
      app.add_subcommand("sweep", "Run variants of a scene and tabulate what each coupled into the target");
  sweepCmd->add_option("scene", sweepArgs.scene, "Scene file (TOML), or a shipped scene's name")->required();
  sweepCmd->add_option("--vary", sweepArgs.vary, "key=v1,v2,...: values of one key; several --vary change together")
      ->required()
      ->take_all();
  sweepCmd->add_option("--set", sweepArgs.overrides, "Override a key in every variant")->take_all();
  sweepCmd->add_option("--out,-o", sweepArgs.outDir, "Output directory (default runs/<scene name>_sweep)");
  sweepCmd->add_option("--jobs", sweepArgs.jobs, "Variants run at once (default: one per core)")
      ->check(countPerCore("--jobs"));

  ejecta::app::ViewfactorArgs vfArgs;
  CLI::App* vfCmd =
      app.add_subcommand("viewfactor", "View factors and incident flux by ray casting (docs/view_factors.md)");
  vfCmd
      ->add_option("geometry", vfArgs.geometry,
                   "Geometry file (TOML), or a shipped geometry's name (ejecta scenes), e.g. geometry/seed_follower")
      ->required();
  auto* raysOpt = vfCmd->add_option("--rays", vfArgs.rays, "Rays per receiving patch (fixed count)")
                      ->check(countInRange("--rays", 1LL << 32, "rays per patch; the error falls as rays^-1/2"));
  vfCmd->add_option("--tol", vfArgs.tolerance, "Absolute tolerance on view factors (adaptive ray count)")
      ->check(CLI::Range(1e-7, 0.5).description("1e-7 to 0.5"))
      ->excludes(raysOpt);
  vfCmd->add_flag("--json", vfArgs.json, "Print the report as JSON");
  auto* convergenceOpt =
      vfCmd
          ->add_option("--convergence", vfArgs.convergenceDir,
                       "Cast at 4x more rays per step and write the error against rays and time (CSV, charts) here")
          ->excludes(raysOpt);
  vfCmd->add_option("--min-rays", vfArgs.minRays, "With --convergence: the first ray count (default 4096)")
      ->needs(convergenceOpt);
  vfCmd->add_option("--max-rays", vfArgs.maxRays, "With --convergence: the last ray count (default 4194304)")
      ->needs(convergenceOpt);
  vfCmd->add_flag("--no-charts", vfArgs.noCharts, "With --convergence: the CSV only");

  ejecta::app::ThermalArgs thermalArgs;
  CLI::App* thermalCmd = app.add_subcommand(
      "thermal", "Flux on a spacecraft's faces from hot crater material, wall temperatures and shield sizing");
  thermalCmd
      ->add_option("scene", thermalArgs.scene,
                   "Thermal study (TOML), or a shipped study's name (ejecta scenes), e.g. thermal/follower")
      ->required();
  thermalCmd->add_option("--from", thermalArgs.from,
                         "Run directory, snapshot (.h5) or grid file (.vdb) with the hot material");
  thermalCmd->add_option("--out,-o", thermalArgs.outDir, "Output directory");
  thermalCmd->add_flag("--json", thermalArgs.json, "Print thermal.json");
  thermalCmd->add_option("--emitters", thermalArgs.emitters,
                         "particles | voxels (the output's temperature grid); default particles, voxels for a .vdb");
  thermalCmd->add_flag("--occlude", thermalArgs.occlude,
                       "The asteroid's surface (the grid file's level set) blocks rays (default when it exists)");
  thermalCmd->add_flag("--no-occlude", thermalArgs.noOcclude, "Nothing but the spacecraft blocks rays");
  thermalCmd->add_flag("--no-charts", thermalArgs.noCharts, "Write the CSVs but no charts");
  thermalCmd->add_option("--occluder-inset", thermalArgs.occluderInset,
                         "Voxels inside the surface where the occluder lies (default 1.5, 0-2)");

  ejecta::app::RenderArgs renderArgs;
  CLI::App* renderCmd = app.add_subcommand(
      "render", "Draw a snapshot's particles coloured by a field, or a slice or iso-surface of a grid file (PNG)");
  renderCmd->add_option("input", renderArgs.input, "Snapshot (.h5), grid file (.vdb) or run directory")->required();
  renderCmd->add_option("--field,-f", renderArgs.field, "Particle field (default density)");
  renderCmd->add_flag("--axes", renderArgs.axes,
                      "Distance axes in metres along the picture's edges (plane and RZ pictures, grid slices)");
  renderCmd->add_option("--plot", renderArgs.plot,
                        "materials: where each material is; failure: each particle's status (no strength, intact, "
                        "plastic, damaged, failed)");
  renderCmd->add_option("--view", renderArgs.view, "auto | plane | rz | 3d");
  renderCmd->add_option("--out,-o", renderArgs.out,
                        "Output PNG (default <field>.png; grid files: grid_<G>.png, iso_<G>.png)");
  renderCmd->add_option("--size", renderArgs.size, "Image size in pixels, 64 to 8192 (default 1024)");
  renderCmd->add_flag("--log", renderArgs.log, "Logarithmic colour scale");
  renderCmd->add_option("--cut", renderArgs.cut,
                        "3D particles and iso-surfaces: none | x | y | z (keep the half below 0)");
  renderCmd->add_option("--cut-at", renderArgs.cutAt, "Where the cut is along its axis (\"2 m\"; default 0)");
  renderCmd->add_option("--camera", renderArgs.cameraPosition,
                        "3D: the camera's position X,Y,Z [m] (default: an automatic camera)");
  renderCmd->add_option("--target", renderArgs.cameraTarget,
                        "3D: where the camera looks, X,Y,Z [m] (default: the centre of what is drawn)");
  renderCmd->add_option("--up", renderArgs.cameraUp, "3D: the camera's up direction X,Y,Z (default 0,0,1)");
  renderCmd->add_option("--fov", renderArgs.fovDegrees,
                        "3D: the camera's vertical field of view [degrees] (default 30)");
  renderCmd->add_option("--center", renderArgs.center,
                        "Plane and RZ pictures: the centre shown, X,Y [m] (RZ: R,Z), with --width");
  renderCmd->add_option("--width", renderArgs.width,
                        "Plane and RZ pictures: the width shown, e.g. \"0.3 m\" (default: fit everything)");
  renderCmd->add_option("--grid,-g", renderArgs.grid, "Grid file: the grid to slice (default density)");
  renderCmd->add_option("--slice", renderArgs.slice,
                        "Grid file: the plane x|y|z[=VALUE] (default z, at 0 or the grid's middle)");
  renderCmd->add_option("--iso", renderArgs.iso, "Grid file: the iso-surface GRID[=VALUE] (default surface=0)");
  renderCmd->add_option("--color-by", renderArgs.colorBy, "Grid file: colour the iso-surface by this grid");

  ejecta::app::WhippleArgs whippleArgs;
  CLI::App* whippleCmd =
      app.add_subcommand("whipple", "Whipple-shield ballistic-limit curves and rear-wall sizing (docs/whipple.md)");
  whippleCmd
      ->add_option("shield", whippleArgs.shield,
                   "Shield and threat (TOML), or a shipped study's name (ejecta scenes), e.g. whipple/haiv")
      ->required();
  whippleCmd->add_option("--out,-o", whippleArgs.outDir, "Output directory (default runs/<name>)");
  whippleCmd->add_flag("--json", whippleArgs.json, "Print whipple.json");

  ejecta::app::WhippleLimitArgs limitArgs;
  CLI::App* limitCmd = app.add_subcommand("whipple-limit",
                                          "Ballistic limit of a Whipple-shield scene by simulation: bisect the "
                                          "projectile diameter at each speed, against Christiansen's equations");
  limitCmd
      ->add_option("scene", limitArgs.scene,
                   "Scene with a [shield] table (file or shipped name, e.g. whipple_sph/emi_71)")
      ->required();
  limitCmd->add_option("--speeds", limitArgs.speeds, "Impact speeds, e.g. \"3 km/s,5 km/s,7 km/s\"")
      ->delimiter(',')
      ->required();
  limitCmd
      ->add_option("--diameters", limitArgs.diameters, "Starting bracket of projectile diameters, e.g. \"2 mm,12 mm\"")
      ->delimiter(',')
      ->required();
  limitCmd->add_option("--iterations", limitArgs.iterations, "Bisections after the two ends (default 4)")
      ->check(CLI::Range(0, 30));
  limitCmd->add_option("--set", limitArgs.overrides, "Override a scene key for every shot (e.g. a coarser spacing)")
      ->take_all();
  limitCmd->add_option("--out,-o", limitArgs.outDir, "Output directory (default runs/<scene name>_limit)");
  limitCmd->add_option("--wall-yield", limitArgs.wallYield,
                       "The rear wall's yield stress for the equations (default: the wall material's Johnson-Cook A)");
  limitCmd->add_option("--threads,-j", limitArgs.threads, "OpenMP threads")->check(countPerCore("--threads"));
  limitCmd->add_flag("!--no-charts", limitArgs.charts, "Write the CSVs but draw no chart");

  ejecta::app::ConvergeArgs convergeArgs;
  CLI::App* convergeCmd = app.add_subcommand("converge",
                                             "Run a scene at successively finer spacings: each quantity's observed "
                                             "order, extrapolated value and GCI uncertainty");
  convergeCmd->add_option("scene", convergeArgs.scene, "Scene file (TOML), or a shipped scene's name")->required();
  convergeCmd
      ->add_option("--factors", convergeArgs.factors,
                   "Spacing multipliers, e.g. 1,0.7,0.5 (three or more for an order)")
      ->delimiter(',')
      ->required()
      ->check(CLI::PositiveNumber);
  convergeCmd
      ->add_option("--quantity,-q", convergeArgs.quantities,
                   "A number summary.json holds (repeatable), e.g. crater_depth_m")
      ->required();
  convergeCmd->add_option("--key", convergeArgs.keys,
                          "Another scene key scaled with the spacing (repeatable), e.g. fields.voxel");
  convergeCmd->add_option("--set", convergeArgs.overrides, "Override a scene key at every level")->take_all();
  convergeCmd->add_option("--out,-o", convergeArgs.outDir, "Output directory (default runs/<scene name>_converge)");
  convergeCmd->add_option("--threads,-j", convergeArgs.threads, "OpenMP threads")->check(countPerCore("--threads"));
  convergeCmd
      ->add_option("--formal-order", convergeArgs.formalOrder,
                   "The method's order for the quantities: 1 across shocks (default), 2 for smooth flow. An observed "
                   "order above twice it or below 0.5, none, or oscillating changes: the fallback band")
      ->check(CLI::Range(0.25, 8.0));
  convergeCmd->add_option("--range", convergeArgs.ranges,
                          "What a quantity can be, QUANTITY=MIN:MAX (repeatable; either side may be empty), e.g. "
                          "target_share_of_yield=0:1: its band is reported and drawn clipped to it");
  convergeCmd->add_flag("!--no-charts", convergeArgs.charts, "Write the CSVs but draw no charts");

  ejecta::app::FragmentsArgs fragmentsArgs;
  CLI::App* fragmentsCmd = app.add_subcommand(
      "fragments", "Fragments of a snapshot (friends-of-friends split by damage), and the debris a follower meets");
  fragmentsCmd->add_option("input", fragmentsArgs.input, "Snapshot (.h5) or run directory (its last snapshot)")
      ->required();
  fragmentsCmd->add_option("--out,-o", fragmentsArgs.outDir, "Output directory (default RUN_DIR/fragments_analysis)");
  fragmentsCmd
      ->add_option("--link-factor", fragmentsArgs.linkFactor,
                   "Friends within F (h_i + h_j) / 2 (default: the scene's, 2)")
      ->check(CLI::Range(1e-3, 100.0));
  fragmentsCmd
      ->add_option("--damage-threshold", fragmentsArgs.damageThreshold,
                   "Failed at or above this damage (default: the scene's, 0.99)")
      ->check(CLI::Range(1e-6, 1e6));
  fragmentsCmd
      ->add_option("--resolved-spacings", fragmentsArgs.resolvedSpacings,
                   "Sizes measured from this many spacings (default 4)")
      ->check(CLI::Range(1e-3, 1e6));
  fragmentsCmd->add_option("--follower", fragmentsArgs.follower,
                           "Thermal study (file or shipped name, e.g. thermal/follower): the spacecraft's approach "
                           "from the snapshot's time");
  fragmentsCmd
      ->add_option("--shield", fragmentsArgs.shield,
                   "Whipple study (file or shipped name, e.g. whipple/haiv): the shield the fragments met must pass")
      ->needs(fragmentsCmd->get_option("--follower"));
  fragmentsCmd->add_flag("--json", fragmentsArgs.json, "Print fragments.json");
  fragmentsCmd->add_flag("!--no-charts", fragmentsArgs.charts, "Write the CSVs but draw no charts");

  ejecta::app::UndexReferenceArgs undexArgs;
  CLI::App* undexCmd = app.add_subcommand(
      "undex-reference", "Converged 1D Lagrangian reference of a centred charge's gauges (docs/undex.md)");
  undexCmd
      ->add_option("scene", undexArgs.scene,
                   "Scene file (TOML): one explosive body centred on its detonation, one inert body")
      ->required();
  undexCmd->add_option("--zones", undexArgs.zones, "Zones from the centre to the medium's edge (default 10000)")
      ->check(countInRange("--zones", 10000000, "zones of the 1D reference"));
  undexCmd->add_option("--out,-o", undexArgs.outDir,
                       "Output directory for gauges_reference.csv (default runs/<scene name>)");
  undexCmd->add_option("--set", undexArgs.overrides, "Override a scene key")->take_all();

  ejecta::app::KeysArgs keysArgs;
  CLI::App* keysCmd = app.add_subcommand("keys", "List every key a scene may hold, with its type, default and meaning");
  keysCmd->add_flag("--markdown", keysArgs.markdown, "The key reference of docs/scenes.md (Markdown)");
  keysCmd->add_option("--write", keysArgs.write,
                      "Replace the reference between the markers of this file (docs/scenes.md)");

  for (CLI::App* command :
       {fieldsCmd, craterCmd, sweepCmd, vfCmd, thermalCmd, renderCmd, whippleCmd, fragmentsCmd, undexCmd})
    addThreads(command);

  ejecta::app::ScenesArgs scenesArgs;
  CLI::App* scenesCmd = app.add_subcommand("scenes", "List the shipped scenes (run one by name: ejecta run impact_rz)");
  scenesCmd->add_option(
      "--kind", scenesArgs.kind,
      "Only this kind: scene (ejecta run), geometry (ejecta viewfactor), study (ejecta thermal, ejecta whipple)");
  CLI::App* scenesShowCmd =
      scenesCmd->add_subcommand("show", "Print a shipped scene, to run as it is or to copy as a template");
  scenesShowCmd->add_option("name", scenesArgs.show, "Scene name, e.g. impact_rz or verification/sod_1d")->required();

  // The manual page and the bash completion, from the definitions above (apps/cli_reference.hpp).
  if (argc == 2 && std::string(argv[1]) == "--man") {
    std::fputs(ejecta::app::manPage(app, version).c_str(), stdout);
    return 0;
  }
  if (argc == 2 && std::string(argv[1]) == "--bash-completion") {
    std::fputs(ejecta::app::bashCompletion(app).c_str(), stdout);
    return 0;
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // A mistyped command reads to CLI11 as a stray argument: name it.
    if (argc > 1 && argv[1][0] != '-' && app.get_subcommands().empty()) {
      const std::string commands =
          ejecta::joinList(app.get_subcommands({}), [](const CLI::App* sub) { return sub->get_name(); });
      std::fprintf(stderr, "ejecta: error: unknown command '%s' (commands: %s)\n", argv[1], commands.c_str());
      return 1;
    }
    // --help and --version exit 0; a bad option is bad input (1), as the documented codes say.
    return app.exit(e) == 0 ? 0 : 1;
  }
  const std::string subcommand = app.get_subcommands().front()->get_name();
  if (const auto refusal = ejecta::app::multiRankRefusal(subcommand)) {
    if (ejecta::app::isFirstRank()) std::fprintf(stderr, "ejecta: error: %s\n", refusal->c_str());
    return 2;
  }
  // MPI starts only for the distributed commands under a launcher: a plain `ejecta run` needs
  // no MPI runtime, and the other commands run on one rank.
  std::optional<ejecta::MpiSession> mpi;
  if (ejecta::app::launchedRanks() && ejecta::app::distributedCommand(subcommand)) mpi.emplace(&argc, &argv);
  const bool distributed = mpi && ejecta::app::launchedRanks().value_or(1) > 1;
  const ejecta::app::ThreadLimit threadLimit(commandThreads);
  try {
    if (*runCmd) return ejecta::app::runCommand(run);
    if (*verifyCmd) return ejecta::app::verifyCommand(verify);
    if (*fieldsCmd) return ejecta::app::fieldsCommand(fieldsArgs);
    if (*craterCmd) return ejecta::app::craterCommand(craterArgs);
    if (*sweepCmd) return ejecta::app::sweepCommand(sweepArgs);
    if (*vfCmd) return ejecta::app::viewfactorCommand(vfArgs);
    if (*thermalCmd) return ejecta::app::thermalCommand(thermalArgs);
    if (*renderCmd) return ejecta::app::renderCommand(renderArgs);
    if (*whippleCmd) return ejecta::app::whippleCommand(whippleArgs);
    if (*fragmentsCmd) return ejecta::app::fragmentsCommand(fragmentsArgs);
    if (*limitCmd) return ejecta::app::whippleLimitCommand(limitArgs);
    if (*convergeCmd) return ejecta::app::convergeCommand(convergeArgs);
    if (*undexCmd) return ejecta::app::undexReferenceCommand(undexArgs);
    if (*keysCmd) return ejecta::app::keysCommand(keysArgs);
    if (*scenesCmd) return ejecta::app::scenesCommand(scenesArgs);
  } catch (const std::exception& e) {
    // Every error names the file it is about: the readers name theirs; an error from deeper
    // down (a solver refusing a patch, an allocator) gets the command's input in front.
    std::string message = e.what();
    const std::string input =
        *runCmd      ? (run.restartDir.empty() ? run.scene : run.restartDir)
        : *fieldsCmd ? fieldsArgs.snapshot
        : *craterCmd ? craterArgs.input
        : *sweepCmd  ? sweepArgs.scene
        : *vfCmd     ? vfArgs.geometry
        : *thermalCmd
            ? (thermalArgs.from.empty() ? thermalArgs.scene : thermalArgs.scene + " --from " + thermalArgs.from)
        : *renderCmd    ? renderArgs.input
        : *whippleCmd   ? whippleArgs.shield
        : *fragmentsCmd ? fragmentsArgs.input
        : *limitCmd     ? limitArgs.scene
        : *convergeCmd  ? convergeArgs.scene
        : *undexCmd     ? undexArgs.scene
        : *scenesCmd    ? scenesArgs.show
                        : std::string();
    const bool named =
        input.empty() || message.find(*thermalCmd ? thermalArgs.scene : input) != std::string::npos ||
        (*thermalCmd && !thermalArgs.from.empty() && message.find(thermalArgs.from) != std::string::npos);
    if (!named) message = input + ": " + message;
    if (dynamic_cast<const std::bad_alloc*>(&e))
      message += " (out of memory: the request is larger than this machine; use a coarser resolution)";
    std::fprintf(stderr, "ejecta: error: %s\n", message.c_str());
    // The other ranks may be waiting in a collective for this one: end them all.
    if (distributed) ejecta::MpiSession::abortAll(1);
    return 1;
  }
  return 1;
}
