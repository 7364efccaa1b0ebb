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

void openAndExport(benchmark::State& state, const std::string& name, const std::string& extension, bool fused) {
  const std::string path = sharedCpacs(name);
  if (!std::filesystem::exists(path)) return state.SkipWithError((path + " is absent").c_str());
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "airshape-bench-export";
  std::filesystem::create_directories(folder);
  airshape::exporting::ExportOptions options;
  options.fused = fused;
  options.mirror = fused;
  airshape::bench::host();  // plugins loaded before the clock runs
  for (auto _ : state) {
    const airshape::Configuration configuration = openWithPlugins(path);
    airshape::exporting::exportConfiguration(configuration, (folder / ("out" + extension)).string(), options);
  }
  std::filesystem::remove_all(folder);
}

// The structural model of one component segment (export --structure --components UID): its
// structure built, joined with its faces by one general fuse, written as BREP.
void openAndExportStructure(benchmark::State& state, const std::string& name, const std::string& host) {
  const std::string path = sharedCpacs(name);
  if (!std::filesystem::exists(path)) return state.SkipWithError((path + " is absent").c_str());
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "airshape-bench-export-structure";
  std::filesystem::create_directories(folder);
  airshape::exporting::ExportOptions options;
  options.structure = true;
  options.components = {host};
  airshape::bench::host();
  for (auto _ : state) {
    const airshape::Configuration configuration = openWithPlugins(path);
    airshape::exporting::exportConfiguration(configuration, (folder / "out.brep").string(), options);
  }
  std::filesystem::remove_all(folder);
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
