// Time to open a CPACS file (parse, read the model, register uIDs, build the component
// graph) and to save it. Run: build/bin/airshape_bench_open. Needs ../shared/data/cpacs.
#include <filesystem>
#include <string>

#include <benchmark/benchmark.h>

#include "airshape/configuration.h"

namespace {

const std::string kData = std::string(AIRSHAPE_SHARED_DATA) + "/data/cpacs/";

void openFile(benchmark::State& state, const std::string& name) {
  const std::string path = kData + name;
  if (!std::filesystem::exists(path)) {
    state.SkipWithError((path + " is absent").c_str());
    return;
  }
  for (auto _ : state) {
    airshape::Configuration configuration = airshape::Configuration::open(path);
    benchmark::DoNotOptimize(configuration.components().components().size());
  }
}

void saveFile(benchmark::State& state, const std::string& name) {
  const std::string path = kData + name;
  if (!std::filesystem::exists(path)) {
    state.SkipWithError((path + " is absent").c_str());
    return;
  }
  airshape::Configuration configuration = airshape::Configuration::open(path);
  const std::string out = (std::filesystem::temp_directory_path() / "airshape-bench-save.xml").string();
  for (auto _ : state) configuration.save(out);
  std::filesystem::remove(out);
}

BENCHMARK_CAPTURE(openFile, simpletest, std::string("simpletest.cpacs.xml"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(openFile, D150, std::string("CPACS_30_D150.xml"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(openFile, D150WithGuides, std::string("D150WithGuides.xml"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(openFile, crm, std::string("crm.xml"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(saveFile, D150, std::string("CPACS_30_D150.xml"))->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
