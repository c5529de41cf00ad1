#pragma once
// The ejecta subcommands, each a thin shell over the libraries. main.cpp parses the command line
// (CLI11 lives there and in cli_reference.cpp, which writes the manual page and the completion
// from the same definition) and calls these.
#include <optional>
#include <string>
#include <vector>

namespace ejecta {
struct RunOptions;
struct Scene;
}  // namespace ejecta

namespace ejecta::app {

// The in-situ outputs `ejecta run` adds to a run of `scene` (grids and the crater, images,
// thermal passes), as RunOptions::configure adds them: what a sweep's variants run with too.
void addInSituOutputs(const Scene& scene, RunOptions& options, bool charts);

struct RunArgs {
  std::string scene;                  // path; empty = the embedded default scene
  std::string outDir;                 // empty = runs/<scene name>
  std::vector<std::string> overrides; // --set key=value
  int threads = 0;
  std::string restartDir;             // --restart RUN_DIR
  bool quiet = false;
  bool charts = true;                 // --no-charts: CSVs only (no matplotlib start-ups)
  bool overwrite = false;             // --overwrite: replace an earlier run in outDir
  double progressEvery = 60.0;        // --progress-every: seconds between the plain progress
                                      // lines when stderr is not a terminal
};
int runCommand(const RunArgs& args);

struct VerifyArgs {
  std::string name;
  bool list = false;
  bool json = false;
  int threads = 0;
  std::vector<std::string> overrides;  // applied to the problem's scene
  int resolutions = 0;                 // 0 = the problem's default
  std::string outDir;                  // optional: the profile CSVs, the convergence table and
                                       // their charts (coupling/verify_charts.hpp) go here
  bool noCharts = false;               // CSVs only
};
int verifyCommand(const VerifyArgs& args);

struct FieldsArgs {
  std::string snapshot;                // SNAPSHOT.h5
  std::string out;                     // FILE.vdb (default fields.vdb)
  std::string voxel;                   // "0.2 m"; empty = the scene's [fields] voxel or median h
  std::vector<std::string> grids;      // empty = the scene's [fields] grids or the default set
  std::string normalise;               // auto | shepard | none
  bool noLevelSet = false;
};
int fieldsCommand(const FieldsArgs& args);

struct CraterArgs {
  std::string input;                   // SNAPSHOT.h5 or FILE.vdb
  bool json = false;
  std::string profile;                 // write the radial profile CSV here
  std::string resolution;              // "0.1 m"; empty = half the median h / the voxel size
};
int craterCommand(const CraterArgs& args);

struct SweepArgs {
  std::string scene;                   // SCENE.toml
  std::vector<std::string> vary;       // key=v1,v2,... (axes vary together)
  std::vector<std::string> overrides;  // --set applied to every variant
  std::string outDir;                  // default runs/<scene name>_sweep
  int jobs = 0;                        // variants at once (default: one per core)
};
int sweepCommand(const SweepArgs& args);

struct ViewfactorArgs {
  std::string geometry;                // GEOMETRY.toml
  long long rays = 0;                  // --rays N (0: the file's [sampling])
  double tolerance = 0.0;              // --tol T, absolute on view factors (0: the file's)
  bool json = false;
  // --convergence DIR: the geometry at minRays, 4 x minRays, ... maxRays; the table and charts
  // go to DIR (radiation/view_factor_convergence.hpp).
  std::string convergenceDir;
  long long minRays = 4096, maxRays = 4194304;
  bool noCharts = false;
};
int viewfactorCommand(const ViewfactorArgs& args);

struct ThermalArgs {
  std::string scene;                   // THERMAL.toml (a [thermal] study: spacecraft, approach, wall)
  std::string from;                    // RUN_DIR (its last snapshot), SNAPSHOT.h5 or GRIDS.vdb
  std::string outDir;                  // default: thermal/ next to the snapshot's run, or runs/<name>
  bool json = false;                   // print thermal.json to stdout
  std::string emitters;                // particles | voxels; default particles (voxels for a .vdb)
  bool occlude = false, noOcclude = false;  // neither: occlude when the output has a surface grid
  double occluderInset = 1.5;          // voxels inside the surface (coupling/surface_occluder.hpp)
  bool noCharts = false;               // CSVs only (coupling/thermal_charts.hpp)
};
int thermalCommand(const ThermalArgs& args);

struct RenderArgs {
  std::string input;                   // SNAPSHOT.h5, FILE.vdb or RUN_DIR (its last snapshot; with
                                       // a grid option below, its last fields/fields_NNNN.vdb)
  std::string field;                   // particle field (default density)
  std::string plot;                    // materials | failure: a categorical picture instead
  bool axes = false;                   // distance axes (plane, RZ pictures and grid slices)
  std::string view;                    // auto | plane | rz | 3d
  std::string out;                     // FILE.png (default <field>.png, grid_<G>.png, iso_<G>.png)
  int size = 1024;                     // pixels
  bool log = false;                    // log colour scale
  std::string cut;                     // 3D and iso-surfaces: none | x | y | z (keep the <= 0 half)
  std::string cutAt;                   // where the cut is: a length ("2.5 m")
  // 3D and iso-surfaces: the camera, "x,y,z" in metres (or with units: "0,-60 m,20 m"), and its
  // vertical field of view [degrees]; no position: the automatic camera.
  std::string cameraPosition, cameraTarget, cameraUp;
  double fovDegrees = 30.0;
  // Plane and RZ pictures: the centre "x,y" (RZ: "r,z") and the width shown, both lengths; none:
  // everything drawn, fitted.
  std::string center, width;
  // Grid files (coupling/grid_images.hpp): a slice of `grid` on a plane, or an iso-surface.
  std::string grid;                    // the grid to slice (default density)
  std::string slice;                   // x | y | z, optionally =VALUE ("z=2.5 m")
  std::string iso;                     // GRID, optionally =VALUE in the grid's units
  std::string colorBy;                 // the iso-surface coloured by this grid
};
int renderCommand(const RenderArgs& args);

struct WhippleArgs {
  std::string shield;                  // SHIELD.toml (docs/whipple.md)
  std::string outDir;                  // default runs/<study name>
  bool json = false;                   // print whipple.json to stdout
};
int whippleCommand(const WhippleArgs& args);

struct FragmentsArgs {
  std::string input;                   // SNAPSHOT.h5 or RUN_DIR (its last snapshot)
  std::string outDir;                  // default RUN_DIR/fragments_analysis
  std::optional<double> linkFactor, damageThreshold, resolvedSpacings;  // default: the scene's
  std::string follower;                // a thermal study (file or shipped name): the approach
  std::string shield;                  // a Whipple study (file or shipped name): its [shield]
  bool json = false;
  bool charts = true;
};
int fragmentsCommand(const FragmentsArgs& args);

struct WhippleLimitArgs {
  std::string scene;                   // a [shield] scene: file or shipped name
  std::vector<std::string> speeds;     // "3 km/s", ...
  std::vector<std::string> diameters;  // the starting bracket: two lengths
  int iterations = 4;
  std::vector<std::string> overrides;  // --set, every shot
  std::string outDir;                  // default runs/<scene name>_limit
  std::string wallYield;               // "330 MPa"; empty: the wall material's
  int threads = 0;
  bool charts = true;
};
int whippleLimitCommand(const WhippleLimitArgs& args);

struct ConvergeArgs {
  std::string scene;                   // file or shipped name
  std::vector<double> factors;         // spacing multipliers
  std::vector<std::string> quantities; // summary.json keys
  std::vector<std::string> keys;       // more scene keys scaled with the spacing
  std::vector<std::string> overrides;  // --set, every level
  std::string outDir;                  // default runs/<scene name>_converge
  int threads = 0;
  double formalOrder = 1.0;            // the fallback band's order (grid_convergence.hpp)
  std::vector<std::string> ranges;     // --range QUANTITY=MIN:MAX: the band clipped to it
  bool charts = true;
};
int convergeCommand(const ConvergeArgs& args);

struct UndexReferenceArgs {
  std::string scene;                   // SCENE.toml: a centred charge in one inert medium
  int zones = 10000;                   // zones from the centre to the medium's edge
  std::string outDir;                  // default runs/<scene name> (beside the SPH gauges.csv)
  std::vector<std::string> overrides;  // --set key=value
};
int undexReferenceCommand(const UndexReferenceArgs& args);

struct KeysArgs {
  bool markdown = false;               // the key reference of docs/scenes.md
  std::string write;                   // rewrite the reference between this file's markers
};
int keysCommand(const KeysArgs& args);

struct ScenesArgs {
  std::string show;                    // `ejecta scenes show NAME`: print that file
  std::string kind;                    // --kind scene|geometry|study: list only these
};
int scenesCommand(const ScenesArgs& args);

// True when stderr is a terminal and CI is not set: show progress lines.
bool interactive();

}  // namespace ejecta::app
