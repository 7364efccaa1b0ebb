// Fuzz target: the inputs of `airshape gordon`, two BREP files of curves, given as one input
// (the profiles, a line "%%", the guides), read as the command reads them and interpolated by a
// Gordon surface. Any input may be refused with an Error; nothing may crash or hang.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include <Bnd_Box.hxx>
#include <Standard_Failure.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_curves.h"
#include "airshape/geometry/gordon_surface.h"

namespace {

std::string written(const std::string& text, const char* name) {
  const std::string path = "/tmp/airshape-fuzz-" + std::to_string(::getpid()) + "-" + name + ".brep";
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

double size(const std::vector<Handle(Geom_BSplineCurve)>& curves) {
  Bnd_Box box;
  for (const auto& curve : curves)
    for (int i = 1; i <= curve->NbPoles(); ++i) box.Add(curve->Pole(i));
  return box.IsVoid() ? 0.0 : std::sqrt(box.SquareExtent());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size_) {
  const std::string input(reinterpret_cast<const char*>(data), size_);
  const std::size_t split = input.find("\n%%\n");
  if (split == std::string::npos) return 0;
  const std::string profilesPath = written(input.substr(0, split), "profiles");
  const std::string guidesPath = written(input.substr(split + 4), "guides");
  try {
    // A short read timeout: the many damaged mutants that hang OCCT's reader would spend the
    // campaign waiting otherwise.
    const std::chrono::milliseconds timeout(500);
    const auto profiles = airshape::geometry::readBrepCurves(profilesPath, timeout);
    const auto guides = airshape::geometry::readBrepCurves(guidesPath, timeout);
    const double extent = std::max(size(profiles), size(guides));
    if (std::isfinite(extent) && extent > 0.0)
      (void)airshape::geometry::buildGordonSurface(profiles, guides, {1e-3 * extent, 1e-5 * extent});
  } catch (const airshape::Error&) {
  } catch (const Standard_Failure&) {  // the command reports these as errors naming the files
  }
  std::remove(profilesPath.c_str());
  std::remove(guidesPath.c_str());
  return 0;
}
