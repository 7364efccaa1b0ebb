// Rotors, pylons and nacelles through their plugins, as a user meets them: the file opened (not
// timed), then one component's shape built with everything it needs (a rotor its blade, a
// nacelle its profiles). Issue aim: under 50 ms for any nacelle, pylon or rotor.
// Run: build/bin/airshape_bench_components (needs ../shared/data).
#include <filesystem>
#include <string>

#include <benchmark/benchmark.h>

#include "airshape/configuration.h"
#include "bench_support.h"

namespace {

using airshape::bench::openWithPlugins;

void buildComponent(benchmark::State& state, const std::string& path, const std::string& uid) {
  if (!std::filesystem::exists(path)) return state.SkipWithError((path + " is absent").c_str());
  for (auto _ : state) {
    state.PauseTiming();
    airshape::Configuration configuration = openWithPlugins(path);
    state.ResumeTiming();
    benchmark::DoNotOptimize(configuration.shapes().shapeOf(configuration, uid));
  }
}

const std::string kCpacs = std::string(AIRSHAPE_SHARED_DATA) + "/data/cpacs/";
const std::string kExamples = std::string(AIRSHAPE_SHARED_DATA) + "/data/cpacs-examples/";

}  // namespace

BENCHMARK_CAPTURE(buildComponent, rotor_MainRotor1, kCpacs + "simple_test_rotors.cpacs.xml", "MainRotor1")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(buildComponent, rotor_Propeller, kCpacs + "simple_test_rotors.cpacs.xml", "Propeller")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(buildComponent, pylon, kCpacs + "simpletest-pylon.cpacs.xml", "Pylon")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(buildComponent, nacelle_one_section, kCpacs + "simpletest-simplenacelle.cpacs.xml",
                  "SimpleEnginePositioning")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(buildComponent, nacelle_three_sections, kCpacs + "simpletest-pylon-nacelle.cpacs.xml",
                  "SimpleEnginePositioning")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(buildComponent, nacelle_four_sections, kExamples + "nacelles.xml", "multipleSectionEngine_installed")
    ->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
