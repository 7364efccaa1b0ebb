// Editing in an optimisation loop: one cycle = change the D150 main wing's tip chord by
// XPath and rebuild every component's solid (only the wing is rebuilt; the fuselage and
// the tails come from the cache), against opening the file and building everything anew.
// Run: build/bin/airshape_bench_edit (needs ../shared/data/cpacs).
#include <filesystem>
#include <string>

#include <benchmark/benchmark.h>

#include "bench_support.h"

namespace {

using airshape::bench::openWithPlugins;
using airshape::bench::sharedCpacs;

const std::string kTipChord =
    "/cpacs/vehicles/aircraft/model/wings/wing[@uID='D150_VAMP_W1']/sections/section[4]/elements/element/"
    "transformation/scaling/x";

void buildEverything(const airshape::Configuration& configuration) {
  for (const auto& component : configuration.components().components())
    if (configuration.shapes().find(component.nodeType) != nullptr)
      benchmark::DoNotOptimize(configuration.shapes().shapeOf(configuration, component.uid));
}

void openAndBuildEverything(benchmark::State& state) {
  const std::string path = sharedCpacs("CPACS_30_D150.xml");
  if (!std::filesystem::exists(path)) return state.SkipWithError((path + " is absent").c_str());
  for (auto _ : state) buildEverything(openWithPlugins(path));
}

void editWingAndRebuild(benchmark::State& state) {
  const std::string path = sharedCpacs("CPACS_30_D150.xml");
  if (!std::filesystem::exists(path)) return state.SkipWithError((path + " is absent").c_str());
  airshape::Configuration configuration = openWithPlugins(path);
  buildEverything(configuration);
  const double chord = std::stod(configuration.value(kTipChord));
  int step = 0;
  for (auto _ : state) {
    configuration.setValue(kTipChord, std::to_string(chord * (1.0 + 0.01 * (++step % 10))));
    buildEverything(configuration);
  }
  state.counters["built per cycle"] =
      static_cast<double>(configuration.cache().statistics().buildsByKey.at("shape:D150_VAMP_W1")) /
      static_cast<double>(state.iterations() + 1);
}

BENCHMARK(openAndBuildEverything)->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK(editWingAndRebuild)->Unit(benchmark::kMillisecond)->Iterations(20);

}  // namespace

BENCHMARK_MAIN();
