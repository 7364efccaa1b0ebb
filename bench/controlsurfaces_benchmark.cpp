// Control devices through the plugin, as a user meets them: every device of a wing built at
// rest (the wing already built), the wing exported with every device deflected and its
// cut-outs, the same wing exported again at other deflections, and one further deflection of
// a built device (its motion and the measure of the moved shape).
// Run: build/bin/airshape_bench_controlsurfaces (needs ../shared/data/cpacs).
#include <filesystem>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "airshape/configuration.h"
#include "airshape/export/export_scene.h"
#include "airshape/query/query_service.h"
#include "bench_support.h"

namespace {

using airshape::bench::host;
using airshape::bench::openWithPlugins;
using airshape::bench::sharedCpacs;
using airshape::query::Json;

/// The uIDs of every device (spoilers too) of the first wing.
std::vector<std::string> devicesOfFirstWing(airshape::Configuration& configuration) {
  std::vector<std::string> uids;
  for (const char* kind : {"control_surface", "spoiler"}) {
    const Json count = host().queries().find(std::string(kind) + "_count")->handler(configuration, {{"wing", 1}});
    for (int i = 1; i <= count.get<int>(); ++i)
      uids.push_back(
          host().queries().find(std::string(kind) + "_uid")->handler(configuration, {{"wing", 1}, {"index", i}}));
  }
  return uids;
}

/// The file opened with its first wing built (outside the timing).
airshape::Configuration withFirstWingBuilt(const std::string& path) {
  airshape::Configuration configuration = openWithPlugins(path);
  airshape::query::answer(configuration, host().queries(), R"({"op":"wing_volume","wing":1})");
  return configuration;
}

void everyDeviceAtRest(benchmark::State& state, const std::string& name) {
  const std::string path = sharedCpacs(name);
  if (!std::filesystem::exists(path)) return state.SkipWithError((path + " is absent").c_str());
  for (auto _ : state) {
    state.PauseTiming();
    airshape::Configuration configuration = withFirstWingBuilt(path);
    const std::vector<std::string> devices = devicesOfFirstWing(configuration);
    state.ResumeTiming();
    for (const std::string& uid : devices) benchmark::DoNotOptimize(configuration.shapes().shapeOf(configuration, uid));
  }
}

/// The uIDs of the first `count` wings (every wing for -1).
std::vector<std::string> wingUids(airshape::Configuration& configuration, int count) {
  if (count < 0) count = airshape::query::answer(configuration, host().queries(), R"({"op":"wing_count"})").at("ok");
  std::vector<std::string> uids;
  for (int wing = 1; wing <= count; ++wing) {
    const std::string query = R"({"op":"wing_uid","wing":)" + std::to_string(wing) + "}";
    uids.push_back(airshape::query::answer(configuration, host().queries(), query).at("ok").get<std::string>());
  }
  return uids;
}

/// What `airshape export --deflect all=max --components <wings>` builds (the first `wings` of
/// the file, -1 for all): every device of those wings at rest, each moved to its largest
/// control parameter, and each wing with all its devices' cut-outs.
void deflectedWingsWithCutOuts(benchmark::State& state, const std::string& name, int wings) {
  const std::string path = sharedCpacs(name);
  if (!std::filesystem::exists(path)) return state.SkipWithError((path + " is absent").c_str());
  for (auto _ : state) {
    state.PauseTiming();
    airshape::Configuration configuration = withFirstWingBuilt(path);
    airshape::exporting::ExportOptions options;
    options.components = wingUids(configuration, wings);
    options.poses = airshape::exporting::parsePoses("all=max");
    state.ResumeTiming();
    benchmark::DoNotOptimize(airshape::exporting::buildScene(configuration, options));
  }
}

/// The main wing.
void deflectedWingWithCutOuts(benchmark::State& state, const std::string& name) {
  deflectedWingsWithCutOuts(state, name, 1);
}

/// Every device of the file and every wing's cut (the aim of issue 18 is 0.3 s for this on the
/// flaps file).
void everyWingDeflectedWithCutOuts(benchmark::State& state, const std::string& name) {
  deflectedWingsWithCutOuts(state, name, -1);
}

/// The same wing exported again at other deflections, after a first deflected export: the
/// devices move, the wing's cut (made once for any deflections) is reused.
void furtherDeflectedWing(benchmark::State& state, const std::string& name) {
  const std::string path = sharedCpacs(name);
  if (!std::filesystem::exists(path)) return state.SkipWithError((path + " is absent").c_str());
  airshape::Configuration configuration = withFirstWingBuilt(path);
  airshape::exporting::ExportOptions options;
  options.components = wingUids(configuration, 1);
  options.poses = airshape::exporting::parsePoses("all=max");
  airshape::exporting::buildScene(configuration, options);
  options.poses = airshape::exporting::parsePoses("all=min");
  for (auto _ : state) benchmark::DoNotOptimize(airshape::exporting::buildScene(configuration, options));
}

void furtherDeflection(benchmark::State& state, const std::string& name) {
  const std::string path = sharedCpacs(name);
  if (!std::filesystem::exists(path)) return state.SkipWithError((path + " is absent").c_str());
  airshape::Configuration configuration = openWithPlugins(path);
  const std::string uid = devicesOfFirstWing(configuration).front();
  const auto* op = host().queries().find("control_surface_deflection");
  const Json query = {{"op", "control_surface_deflection"}, {"uid", uid}, {"control_parameter", 0.5}};
  op->handler(configuration, query);  // builds the device once
  for (auto _ : state) benchmark::DoNotOptimize(op->handler(configuration, query));
}

BENCHMARK_CAPTURE(everyDeviceAtRest, aircraft_flaps, std::string("CPACS_30_aircraft_flaps.xml"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(deflectedWingWithCutOuts, aircraft_flaps, std::string("CPACS_30_aircraft_flaps.xml"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(everyWingDeflectedWithCutOuts, aircraft_flaps, std::string("CPACS_30_aircraft_flaps.xml"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(furtherDeflectedWing, aircraft_flaps, std::string("CPACS_30_aircraft_flaps.xml"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(furtherDeflection, aircraft_flaps, std::string("CPACS_30_aircraft_flaps.xml"))
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
