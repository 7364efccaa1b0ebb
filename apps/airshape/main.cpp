// The airshape command: one word per task (info, query, validate, save, plugins).
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <system_error>

#include <Standard_Failure.hxx>

#include "airshape/error.h"
#include "airshape/plugin/plugin_host.h"
#include "airshape/xml/read_ahead.h"
#include "commands.h"
#include "open_configuration.h"

namespace airshape::cli {
namespace {

struct Command {
  int (*run)(const Arguments&, plugin::PluginHost&);
  const char* usage;
  const char* help;
};

const std::map<std::string, Command>& commands() {
  static const std::map<std::string, Command> table = {
      {"info",
       {runInfo, "airshape info FILE",
        "Prints the CPACS version and the geometric elements of every model in build order:\n"
        "each one's component type, uID, parent, model (after the first) and the plugin\n"
        "that builds it (or 'no builder yet', 'not built: <why>', or 'none loaded')."}},
      {"query",
       {runQuery, "airshape query FILE [--duct-cutouts]",
        "Answers JSON queries, one per line on stdin, one answer per line on\n"
        "stdout: {\"ok\": result} or {\"error\": message}. See docs/query.md."}},
      {"validate",
       {runValidate, "airshape validate FILE",
        "Checks the document against the CPACS schema model and its uIDs, and lists every\n"
        "problem with its XPath. Exit status 1 if there is any."}},
      {"save",
       {runSave, "airshape save IN -o OUT [--force] | airshape save IN --in-place",
        "Loads IN into the model and writes it back, every node preserved. OUT is written\n"
        "atomically; an existing OUT is replaced only with --force, IN only with --in-place."}},
      {"build",
       {runBuild, "airshape build FILE [--duct-cutouts]",
        "Builds the solid of every component of every model that a plugin builds, in build\n"
        "order, and checks it (BRepCheck); prints one line per geometric element: validity,\n"
        "volume and time, what BRepCheck found in an invalid solid, why it failed, or\n"
        "'no builder yet for <type> (plugin <name>)' / 'not built: <why>' / 'not supported: ...'.\n"
        "Warnings of "
        "building go to stderr. Exit status 1 if any fails or is invalid, 0 otherwise (also\n"
        "when there is nothing to build), 2 when the file cannot be used."}},
      {"export",
       {runExportModule,
        "airshape export FILE -o OUT [-o OUT ...] [--components UID,...] [--mirror] [--fused]\n"
        "                 [--deflect UID=P[,UID=P...]] [--structure] [--profiles]\n"
        "                 [--deflection LINEAR[,ANGULAR]] [--duct-cutouts] [--force] [--quiet]",
        "Builds the components and writes them, in the format each OUT's extension names:\n"
        "  .step .stp   STEP AP214, an assembly with one product per component (named by uID),\n"
        "               face names as STEP names            .iges .igs  IGES, names and levels\n"
        "  .brep        OCCT BREP                           .stl        binary STL\n"
        "  .vtp         VTK PolyData, per-cell arrays 'component' and 'face'\n"
        "  .gltf .glb   glTF 2.0, one node per component    .obj        Wavefront OBJ\n"
        "  .html .htm   a page that shows the aircraft in any browser, from disk, with no\n"
        "               network: the viewer and the geometry in one file (docs/viewer.md)\n"
        "--components   only these uIDs (default: every component a plugin builds)\n"
        "--mirror       add the mirrored halves of components with a symmetry plane\n"
        "--fused        write one solid, the Boolean union of all (face names kept)\n"
        "--deflect      control devices (flaps, slats, spoilers) at control parameter P (a\n"
        "               number, min or max; all=min|max for every device): each written as\n"
        "               a solid of its own, its wing with their cut-outs (one Boolean cut)\n"
        "--structure    the structural model instead: per component segment its faces split\n"
        "               at spars and ribs, the spar webs and the ribs, one shell sharing edges\n"
        "--profiles     frames and stringers with their structural profiles swept along their\n"
        "               lines (each sheet a surface) instead of the lines; where a profile\n"
        "               cannot be swept the line is written and a note says why\n"
        "--deflection   triangulation of STL/VTK/glTF/OBJ: largest distance to the surface\n"
        "               in metres (default per component: 1 % of volume/area), and the\n"
        "               largest angle between normals in radians (default 0.2)\n"
        "--force        replace existing outputs       --quiet  no progress or summary\n"
        "Each file is written under a temporary name and moved into place when complete.\n"
        "Components that fail to build are left out with a line on stderr (exit status 1);\n"
        "nothing is written when none could be built or one named with --components failed\n"
        "(status 1), or when no plugin builds any (status 0, said). 2: unusable input.\n"
        "Prints progress on stderr and a summary (volume and area per solid) on stdout."}},
      {"mesh",
       {runMeshModule,
        "airshape mesh FILE -o OUT [-o OUT ...] [--components UID,...] [--mirror] [--deflect UID=P,...]\n"
        "                 [--size SIZE] [--size UID=SIZE,...] [--min-size SIZE] [--curvature N]\n"
        "                 [--farfield [box:|sphere:]D[L]] [--symmetry] [--boundary-layer N,H[,G]]\n"
        "                 [--structure [--order 2]] [--duct-cutouts] [--force] [--quiet]",
        "Meshes the aircraft through Gmsh (docs/meshing.md) and writes the mesh in the format each\n"
        "OUT's extension names: .msh (Gmsh 4.1, ASCII: OpenFOAM's gmshToFoam reads it), .su2,\n"
        ".vtu, .inp (Abaqus/CalculiX), .stl. Without --farfield: the surface of the fused\n"
        "aircraft, watertight, a physical group per component uID and per named face.\n"
        "--components   only these uIDs            --mirror  with the mirrored halves\n"
        "--deflect      control devices at control parameter P, as for export\n"
        "--size         largest element size in metres (default: the aircraft's length / 50);\n"
        "               UID=SIZE: on that component's surfaces\n"
        "--min-size     smallest element size (default: size / 50)\n"
        "--curvature    elements per full turn of the surface's curvature (default 40)\n"
        "--farfield     a CFD domain: the fluid between the aircraft and a box (or sphere) D\n"
        "               metres (DL: D aircraft lengths) around it, in tetrahedra; groups\n"
        "               farfield, symmetry, each component's uID, and the volume fluid\n"
        "--symmetry     the half domain y >= 0 with a symmetry plane (a half model; far field\n"
        "               20L unless given)\n"
        "--boundary-layer  N layers of prisms on the aircraft's walls under the tetrahedra, the\n"
        "               first H metres high, each G times the one below (default 1.2); thinner\n"
        "               where the walls' elements are short or fold sharply (said in a note)\n"
        "--structure    the structural model (as export --structure) in quadrilateral shells for\n"
        "               FEM: an element set and a node set per structural model and per spar,\n"
        "               rib set and skin segment uID; .inp writes S4 (with --order 2: S8)\n"
        "--force        replace existing outputs     --quiet  no progress\n"
        "Prints one summary line per mesh on stdout: nodes, elements by type, the worst\n"
        "element quality (Gmsh's inverse condition number), time. A component that cannot be\n"
        "built or meshed is said on stderr with its CPACS path, the rest meshed: exit status 1."}},
      {"study",
       {runStudy,
        "airshape study STUDY.toml -o RESULTS.csv|.jsonl [--workers N] [--scheduler tcp://HOST:PORT]\n"
        "                 [--restart] [--quiet]",
        "Runs a design study (docs/studies.md): the parameters, design of experiments and outputs\n"
        "a TOML file names, a row per sample in RESULTS (parameter values, outputs, seconds, and\n"
        "for a failed sample its error and CPACS path). Samples run in local worker processes\n"
        "(one per core unless --workers), or on the Dask cluster of --scheduler. Samples that\n"
        "RESULTS holds already are not run again (--restart: start anew); Ctrl-C stops and keeps\n"
        "what is done. A [plot] of the study is written beside RESULTS as .png. Exit status: 0\n"
        "all samples done, 1 some failed, 2 the study cannot be run, 130 interrupted."}},
      {"gordon",
       {runGordon, "airshape gordon PROFILES.brep GUIDES.brep -o SURFACE.brep [--report]",
        "Interpolates a curve network (two BREP compounds of edges) by one Gordon B-spline\n"
        "surface, writes it as one face and prints a JSON report: degrees, pole counts, time,\n"
        "how far profiles and guides are apart where they cross; with --report also how far\n"
        "the input curves and crossings lie from the surface (sampled: several times slower)."}},
      {"view",
       {runViewModule, "airshape view FILE [--port P] [--no-browser] [--duct-cutouts]",
        "Serves the aircraft to a browser on 127.0.0.1 (a free port unless --port; the address\n"
        "is printed on stdout) and opens it in the desktop's browser unless --no-browser: the\n"
        "aircraft shaded, orbit/pan/zoom, the component tree (click: highlight and measures;\n"
        "double-click: show it alone), mirrored halves on or off, a length scale, a slider per\n"
        "control device. When FILE changes on disk the page reloads the geometry by itself; a\n"
        "file that no longer loads is said in the page, which keeps the last good geometry.\n"
        "Ends on Ctrl-C or when the page's 'stop the server' is pressed. See docs/viewer.md."}},
      {"plugins",
       {runPlugins, "airshape plugins [--json]",
        "Lists the loaded plugins: name, version, file, node types, query ops. With --json: the\n"
        "plugins and every query op with its owner, arguments (required and optional) and answer,\n"
        "as one JSON object (what the Python binding's methods are generated from)."}},
  };
  return table;
}

void printUsage(std::ostream& out) {
  out << "airshape: CPACS aircraft descriptions to exact B-spline geometry\n\nusage:\n";
  for (const auto& [name, command] : commands()) out << "  " << command.usage << '\n';
  out << "  airshape help [COMMAND]\n\nPlugins are loaded from the core library's folder and AIRSHAPE_PLUGIN_PATH.\n"
         "Exit status: 0 success, 1 problems found (validate, build, export: a component\n"
         "failed), 2 the input or the arguments cannot be used.\n";
}

/// Whether a command opens a file to build from it, and so takes the plugins' build options.
bool takesBuildOptions(const std::string& command) {
  return command == "build" || command == "export" || command == "view" || command == "query" || command == "mesh";
}

int runHelp(const Arguments& arguments) {
  if (arguments.empty()) {
    printUsage(std::cout);
    return kSuccess;
  }
  const auto command = commands().find(arguments[0]);
  if (command == commands().end()) throw Error(ErrorCode::InvalidArgument, "no command '" + arguments[0] + "'");
  std::cout << "usage: " << command->second.usage << "\n\n" << command->second.help << '\n';
  if (takesBuildOptions(arguments[0])) {
    plugin::PluginHost host;
    host.loadDefaultPlugins();
    if (const std::string flags = optionFlagsHelp(host); !flags.empty())
      std::cout << "\nBuild options of the loaded plugins (off unless given):\n" << flags;
  }
  return kSuccess;
}

int run(int argc, char** argv) {
  if (argc < 2) {
    printUsage(std::cerr);
    return kFailure;
  }
  const std::string word = argv[1];
  const Arguments arguments(argv + 2, argv + argc);
  if (word == "help" || word == "--help" || word == "-h") return runHelp(arguments);
  if (word == "--version") {
    std::cout << "airshape " << AIRSHAPE_VERSION << '\n';
    return kSuccess;
  }
  const auto command = commands().find(word);
  if (command == commands().end())
    throw Error(ErrorCode::InvalidArgument, "unknown command '" + word + "' (see airshape help)");
  plugin::PluginHost host;
  // Loading the plugins links OCCT's toolkits they use (tens of milliseconds): only for the
  // commands that read CPACS files or list plugins, which meanwhile read their file.
  std::optional<xml::ReadAhead> readAhead;  // waits for its thread on the way out, however left
  if (word != "gordon" && word != "study") {
    std::error_code unreadable;  // the command itself says what is wrong with its file
    if (!arguments.empty() && std::filesystem::is_regular_file(arguments[0], unreadable))
      readAhead.emplace(arguments[0]);
    host.loadDefaultPlugins();
    for (const std::string& message : host.messages()) std::cerr << "airshape: plugin: " << message << '\n';
  }
  return command->second.run(arguments, host);
}

}  // namespace
}  // namespace airshape::cli

int main(int argc, char** argv) {
  try {
    return airshape::cli::run(argc, argv);
  } catch (const airshape::Error& error) {
    std::cerr << "airshape: " << error.what() << '\n';
  } catch (const std::exception& error) {
    std::cerr << "airshape: internal error: " << error.what() << '\n';
  } catch (const Standard_Failure& failure) {
    std::cerr << "airshape: geometry kernel failure: " << failure.GetMessageString() << '\n';
  }
  return airshape::cli::kFailure;
}
