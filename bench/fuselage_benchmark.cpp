// Fuselages through the plugin: time from opening a file to its fuselage built (the loft,
// with guide curves the Gordon surface, and every segment's solid), for the D150 variants
// of growing network size, and time per fuselage_point once built.
// Run: build/bin/airshape_bench_fuselage (needs ../shared/data/cpacs).
#include <filesystem>
#include <string>

#include <benchmark/benchmark.h>

#include "airshape/configuration.h"
#include "airshape/query/query_service.h"
#include "bench_support.h"

namespace {

using airshape::bench::host;
using airshape::bench::sharedCpacs;

const airshape::query::Json kPoint = {
    {"op", "fuselage_point"}, {"fuselage", 1}, {"segment", 3}, {"eta", 0.4}, {"zeta", 0.3}};

void openAndBuildFuselage(benchmark::State& state, const std::string& name) {
  const std::string path = sharedCpacs(name);
  if (!std::filesystem::exists(path)) return state.SkipWithError((path + " is absent").c_str());
  const auto* op = host().queries().find("fuselage_point");
  for (auto _ : state) {
    airshape::Configuration configuration = airshape::Configuration::open(path, host().componentLocations());
    benchmark::DoNotOptimize(op->handler(configuration, kPoint));
  }
}

void fuselagePoint(benchmark::State& state, const std::string& name) {
  const std::string path = sharedCpacs(name);
  if (!std::filesystem::exists(path)) return state.SkipWithError((path + " is absent").c_str());
  airshape::Configuration configuration = airshape::Configuration::open(path, host().componentLocations());
  const auto* op = host().queries().find("fuselage_point");
  op->handler(configuration, kPoint);  // builds the fuselage once
  for (auto _ : state) benchmark::DoNotOptimize(op->handler(configuration, kPoint));
}

#define FUSELAGE_FILE(id, file) \
  BENCHMARK_CAPTURE(openAndBuildFuselage, id, std::string(file))->Unit(benchmark::kMillisecond)->Iterations(3)

FUSELAGE_FILE(D150, "CPACS_30_D150.xml");
FUSELAGE_FILE(D150_4_guides_10_profiles, "D150_4_guides_10_profiles.xml");
FUSELAGE_FILE(D150_8_guides_8_profiles, "D150_8_guides_8_profiles.xml");
FUSELAGE_FILE(D150_16_guides_16_profiles, "D150_16_guides_16_profiles.xml");
FUSELAGE_FILE(D150WithGuides, "D150WithGuides.xml");
FUSELAGE_FILE(D150_16_guides_60_profiles, "D150_16_guides_60_profiles.xml");
BENCHMARK_CAPTURE(fuselagePoint, D150, std::string("CPACS_30_D150.xml"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(fuselagePoint, D150WithGuides, std::string("D150WithGuides.xml"))->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
