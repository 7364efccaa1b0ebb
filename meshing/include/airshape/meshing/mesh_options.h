#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "airshape/export/export_options.h"

namespace airshape::meshing {

/// The outer boundary of a CFD domain around the aircraft (`airshape mesh --farfield`).
struct Farfield {
  enum class Shape { Box, Sphere };
  Shape shape = Shape::Box;
  /// How far the boundary lies from the aircraft's bounding box, in aircraft lengths (the
  /// box's longest side); `metres` instead when it is set.
  double lengths = 20;
  std::optional<double> metres;
};

/// Prisms grown from the aircraft's walls into the fluid of a CFD domain, layer on layer, under
/// the tetrahedra (`airshape mesh --boundary-layer COUNT,FIRST[,GROWTH]`).
struct BoundaryLayer {
  int count = 0;             ///< layers of prisms
  double firstHeight = 0;    ///< the height of the layer on the wall, metres
  double growth = 1.2;       ///< each layer's height over the one below it
  double thickness() const;  ///< the heights of all layers together
};

/// How far a mesh has come, reported while it is built.
struct MeshProgress {
  double seconds = 0;  ///< since meshing started
  std::string step;    ///< "built W1", "fusing", "meshing surfaces", ...
};

/// What `airshape mesh` meshes and how finely.
struct MeshOptions {
  /// The solids to mesh: `components`, `mirror`, `poses` (--deflect) as for an export; with
  /// `structure` the structural model (spars, ribs, split skins) as a shell mesh for FEM.
  exporting::ExportOptions scene;
  /// Largest element size on the surfaces, metres; 0: the aircraft's length / 50.
  double size = 0;
  /// Smallest element size, metres; 0: size / 50.
  double minSize = 0;
  /// Largest size on the surfaces of given components, by uID (`--size W1=0.05`).
  std::map<std::string, double> componentSizes;
  /// Elements per full turn of the surfaces' curvature (0: sizes ignore curvature).
  double elementsPerCircle = 40;
  /// A CFD domain: the fluid between the aircraft and this boundary, meshed with
  /// tetrahedra. None: the aircraft's surface only.
  std::optional<Farfield> farfield;
  /// The half domain y >= 0 with a symmetry plane (a half model); implies a far field.
  bool symmetry = false;
  /// Prism layers on the aircraft's walls under the fluid's tetrahedra; implies a far field.
  std::optional<BoundaryLayer> boundaryLayer;
  /// Shell elements with 4 nodes (S3/S4) or with mid-side nodes (S6/S8) in FEM meshes.
  int order = 1;
  /// Called as work goes on; may be empty.
  std::function<void(const MeshProgress&)> progress;
};

/// Takes the mesh options out of a command's arguments (`--size 0.5`, `--farfield 20L`, ...:
/// `airshape help mesh`) and leaves the rest in order; the command line, the C API and the
/// Python binding all describe a mesh so. Throws Error(InvalidArgument) on a malformed value.
MeshOptions takeMeshOptions(std::vector<std::string>& arguments);

/// "COUNT,FIRST[,GROWTH]": a whole number of layers, the first one's height in metres, the
/// growth from layer to layer (1.2 when left out; at least 1). Throws Error(InvalidArgument)
/// on anything else.
BoundaryLayer parseBoundaryLayer(const std::string& text);

/// "uID=SIZE" pairs separated by commas, sizes positive numbers in metres. Throws
/// Error(InvalidArgument) on anything else.
std::map<std::string, double> parseComponentSizes(const std::string& list);

/// "[box:|sphere:]N[L]": N aircraft lengths with the suffix L, N metres without. Throws
/// Error(InvalidArgument) on anything else.
Farfield parseFarfield(const std::string& text);

}  // namespace airshape::meshing
