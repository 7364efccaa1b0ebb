// Intersections of components as `intersection_length` computes them: the wing–fuselage line
// of CPACS_30_D150.xml (ruled wing) and of D150WithGuides.xml (guided wing), both solids
// already built.
// Run: build/bin/airshape_bench_intersection (needs ../shared/data/cpacs).
#include <filesystem>
#include <string>

#include <benchmark/benchmark.h>

#include "airshape/configuration.h"
#include "airshape/query/query_service.h"
#include "bench_support.h"

namespace {

using airshape::bench::host;
using airshape::bench::openWithPlugins;
using airshape::bench::sharedCpacs;

void wingAndFuselage(benchmark::State& state, const std::string& name, const std::string& wing,
                     const std::string& fuselage) {
  const std::string path = sharedCpacs(name);
  if (!std::filesystem::exists(path)) return state.SkipWithError((path + " is absent").c_str());
  airshape::Configuration configuration = openWithPlugins(path);
  configuration.shapes().shapeOf(configuration, wing);
  configuration.shapes().shapeOf(configuration, fuselage);
  const std::string query = R"({"op":"intersection_length","uid1":")" + wing + R"(","uid2":")" + fuselage + R"("})";
  for (auto _ : state) benchmark::DoNotOptimize(airshape::query::answer(configuration, host().queries(), query));
}

BENCHMARK_CAPTURE(wingAndFuselage, D150, std::string("CPACS_30_D150.xml"), std::string("D150_VAMP_W1"),
                  std::string("D150_VAMP_FL1"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(wingAndFuselage, D150WithGuides, std::string("D150WithGuides.xml"), std::string("D150_wing_1ID"),
                  std::string("D150Fuselage1ID"))
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
