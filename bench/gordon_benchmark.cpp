// Time to build the Gordon surface of every curve network in ../shared/data/curve-networks,
// with the time split into its stages and the surface's pole counts as counters.
// Run: build/bin/airshape_bench_gordon
#include <algorithm>
#include <filesystem>
#include <string>

#include <benchmark/benchmark.h>
#include <Bnd_Box.hxx>
#include <cmath>

#include "airshape/geometry/brep_curves.h"
#include "airshape/geometry/gordon_surface.h"

namespace {

namespace fs = std::filesystem;
using airshape::geometry::GordonSurface;

void buildNetwork(benchmark::State& state, const fs::path& folder) {
  const auto profiles = airshape::geometry::readBrepCurves((folder / "profiles.brep").string());
  const auto guides = airshape::geometry::readBrepCurves((folder / "guides.brep").string());
  // The same tolerances as `airshape gordon`, relative to the network's size.
  Bnd_Box box;
  for (const auto* family : {&profiles, &guides})
    for (const auto& curve : *family)
      for (int i = 0; i <= 50; ++i)
        box.Add(curve->Value(curve->FirstParameter() + (curve->LastParameter() - curve->FirstParameter()) * i / 50));
  const double diagonal = std::sqrt(box.SquareExtent());
  GordonSurface last;
  for (auto _ : state)
    last = airshape::geometry::buildGordonSurface(profiles, guides, {1e-3 * diagonal, 1e-5 * diagonal});
  state.counters["intersection_ms"] = 1e3 * last.timings.intersection;
  state.counters["reparametrisation_ms"] = 1e3 * last.timings.reparametrisation;
  state.counters["skinning_ms"] = 1e3 * last.timings.skinning;
  state.counters["combination_ms"] = 1e3 * last.timings.combination;
  state.counters["poles_u"] = last.surface->NbUPoles();
  state.counters["poles_v"] = last.surface->NbVPoles();
}

}  // namespace

int main(int argc, char** argv) {
  const fs::path networks = fs::path(AIRSHAPE_SHARED_DATA) / "data" / "curve-networks";
  std::vector<fs::path> folders;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(networks, error))
    if (fs::exists(entry.path() / "profiles.brep")) folders.push_back(entry.path());
  std::sort(folders.begin(), folders.end());
  for (const fs::path& folder : folders)
    benchmark::RegisterBenchmark(("gordon/" + folder.filename().string()).c_str(), buildNetwork, folder)
        ->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
