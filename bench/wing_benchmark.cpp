// Wings through the plugin, as a user meets them: time from opening a file to every wing
// built (solids included), the main wing alone once the file is open, and time per
// wing_upper_point once built.
// Run: build/bin/airshape_bench_wing (needs ../shared/data/cpacs).
#include <filesystem>
#include <string>

#include <benchmark/benchmark.h>

#include "airshape/configuration.h"
#include "airshape/query/query_service.h"
#include "bench_support.h"

namespace {

using airshape::bench::host;
using airshape::bench::sharedCpacs;

void openAndBuildWings(benchmark::State& state, const std::string& name) {
  const std::string path = sharedCpacs(name);
  if (!std::filesystem::exists(path)) return state.SkipWithError((path + " is absent").c_str());
  for (auto _ : state) {
    airshape::Configuration configuration = airshape::Configuration::open(path, host().componentLocations());
    const std::size_t wings =
        airshape::query::answer(configuration, host().queries(), R"({"op":"wing_count"})")["ok"].get<std::size_t>();
    for (std::size_t w = 1; w <= wings; ++w)
      benchmark::DoNotOptimize(airshape::query::answer(configuration, host().queries(),
                                                       R"({"op":"wing_volume","wing":)" + std::to_string(w) + "}"));
  }
}

/// The main wing alone, the file already open: its geometry and solid (and volume).
void buildMainWing(benchmark::State& state, const std::string& name) {
  const std::string path = sharedCpacs(name);
  if (!std::filesystem::exists(path)) return state.SkipWithError((path + " is absent").c_str());
  for (auto _ : state) {
    state.PauseTiming();
    airshape::Configuration configuration = airshape::Configuration::open(path, host().componentLocations());
    state.ResumeTiming();
    benchmark::DoNotOptimize(
        airshape::query::answer(configuration, host().queries(), R"({"op":"wing_volume","wing":1})"));
  }
}

void upperPoint(benchmark::State& state, const std::string& name) {
  const std::string path = sharedCpacs(name);
  if (!std::filesystem::exists(path)) return state.SkipWithError((path + " is absent").c_str());
  airshape::Configuration configuration = airshape::Configuration::open(path, host().componentLocations());
  const auto* op = host().queries().find("wing_upper_point");
  const airshape::query::Json query = {
      {"op", "wing_upper_point"}, {"wing", 1}, {"segment", 1}, {"eta", 0.4}, {"xsi", 0.3}};
  op->handler(configuration, query);  // builds the wing once
  for (auto _ : state) benchmark::DoNotOptimize(op->handler(configuration, query));
}

BENCHMARK_CAPTURE(openAndBuildWings, D150, std::string("CPACS_30_D150.xml"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(openAndBuildWings, D150WithGuides, std::string("D150WithGuides.xml"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(buildMainWing, D150, std::string("CPACS_30_D150.xml"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(upperPoint, D150, std::string("CPACS_30_D150.xml"))->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
