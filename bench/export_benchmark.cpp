// Exports as a user runs them: time from opening a file to the output written (components
// built, triangulated for the mesh formats, written), per format for D150, STEP for the
// larger files, the fused D150 (mirrored halves included), and the structural model of D250's
// winglet.
// Run: build/bin/airshape_bench_export (needs ../shared/data/cpacs).
#include <filesystem>
#include <string>

#include <benchmark/benchmark.h>

#include "airshape/export/exporter.h"
#include "bench_support.h"

namespace {

using airshape::bench::openWithPlugins;
using airshape::bench::sharedCpacs;

/// Opens the file and exports it with `options` to a file of the given extension, per iteration.
void timeExport(benchmark::State& state, const std::string& name, const std::string& extension,
                const airshape::exporting::ExportOptions& options) {
  const std::string path = sharedCpacs(name);
  if (!std::filesystem::exists(path)) return state.SkipWithError((path + " is absent").c_str());
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "airshape-bench-export";
  std::filesystem::create_directories(folder);
  airshape::bench::host();  // plugins loaded before the clock runs
  for (auto _ : state) {
    const airshape::Configuration configuration = openWithPlugins(path);
    airshape::exporting::exportConfiguration(configuration, (folder / ("out" + extension)).string(), options);
  }
  std::filesystem::remove_all(folder);
}

void openAndExport(benchmark::State& state, const std::string& name, const std::string& extension, bool fused) {
  airshape::exporting::ExportOptions options;
  options.fused = fused;
  options.mirror = fused;
  timeExport(state, name, extension, options);
}

// The structural model of one component segment (export --structure --components UID): its
// structure built, joined with its faces by one general fuse, written as BREP.
void openAndExportStructure(benchmark::State& state, const std::string& name, const std::string& host) {
  airshape::exporting::ExportOptions options;
  options.structure = true;
  options.components = {host};
  timeExport(state, name, ".brep", options);
}

BENCHMARK_CAPTURE(openAndExportStructure, D250_winglet, std::string("CPACS_30_D250_10.xml"),
                  std::string("D250_wing_winglet"))
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

#define EXPORT(id, file, extension, fused)                                               \
  BENCHMARK_CAPTURE(openAndExport, id, std::string(file), std::string(extension), fused) \
      ->Unit(benchmark::kMillisecond)                                                    \
      ->Iterations(3)

EXPORT(D150_step, "CPACS_30_D150.xml", ".step", false);
EXPORT(D150_iges, "CPACS_30_D150.xml", ".iges", false);
EXPORT(D150_brep, "CPACS_30_D150.xml", ".brep", false);
EXPORT(D150_stl, "CPACS_30_D150.xml", ".stl", false);
EXPORT(D150_vtp, "CPACS_30_D150.xml", ".vtp", false);
EXPORT(D150_glb, "CPACS_30_D150.xml", ".glb", false);
EXPORT(D150_obj, "CPACS_30_D150.xml", ".obj", false);
EXPORT(D150WithGuides_step, "D150WithGuides.xml", ".step", false);
EXPORT(crm_step, "crm.xml", ".step", false);
EXPORT(D150_fused_step, "CPACS_30_D150.xml", ".step", true);
EXPORT(D150_fused_stl, "CPACS_30_D150.xml", ".stl", true);

}  // namespace

BENCHMARK_MAIN();
