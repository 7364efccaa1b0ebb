#include "scene_mesh.h"

#include <BRepBndLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <IMeshTools_Parameters.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/parallel_for.h"

namespace airshape::exporting {

namespace {

/// 1 % of the volume / area ratio, a thickness: the sagitta this leaves on an airfoil of
/// relative thickness t or a round body loses a few tenths of a percent of volume.
/// Shapes without volume fall back to 0.1 % of their box diagonal.
double automaticDeflection(const TopoDS_Shape& shape) {
  const double volume = geometry::volumeOf(shape);
  const double area = geometry::areaOf(shape);
  if (volume > 0 && area > 0) return 0.01 * volume / area;
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  return box.IsVoid() ? 1e-3 : 1e-3 * std::sqrt(box.SquareExtent());
}

/// Whether every face has a triangulation.
bool isTriangulated(const TopoDS_Shape& shape) {
  for (TopExp_Explorer face(shape, TopAbs_FACE); face.More(); face.Next()) {
    TopLoc_Location location;
    if (BRep_Tool::Triangulation(TopoDS::Face(face.Current()), location).IsNull()) return false;
  }
  return true;
}

/// Whether every edge outside the faces (a stiffener's line) has its polyline.
bool linesDiscretised(const TopoDS_Shape& shape) {
  for (TopExp_Explorer edge(shape, TopAbs_EDGE, TopAbs_FACE); edge.More(); edge.Next()) {
    TopLoc_Location location;
    if (BRep_Tool::Polygon3D(TopoDS::Edge(edge.Current()), location).IsNull()) return false;
  }
  return true;
}

/// Meshes a component again, finer, while the mesher leaves faces without a triangulation:
/// slivers (a rear cap a millimetre thin under a metre wide) defeat a deflection chosen for
/// the whole component. The whole component, so that shared edges stay shared (closed). Where
/// the chosen algorithm fails at every deflection, OCCT's older one (Watson's) tries again.
void triangulateFinerWhereNeeded(const SceneComponent& component, const IMeshTools_Parameters& chosen) {
  for (const IMeshTools_MeshAlgoType algorithm : {chosen.MeshAlgo, IMeshTools_MeshAlgoType_Watson}) {
    IMeshTools_Parameters parameters = chosen;
    parameters.MeshAlgo = algorithm;
    for (int attempt = 0; attempt < 6 && !isTriangulated(component.shape.shape); ++attempt) {
      parameters.Deflection *= 0.3;
      BRepTools::Clean(component.shape.shape);
      BRepMesh_IncrementalMesh mesher(component.shape.shape, parameters);
    }
  }
  if (!isTriangulated(component.shape.shape))
    throw Error(ErrorCode::InvalidModel, "a face of '" + component.name + "' could not be triangulated");
}

}  // namespace

void triangulate(const ExportScene& scene, const ExportOptions& options) {
  // Components on every core as well as their faces: a component of few faces (a revolved
  // six revolved faces) keeps the mesher's own parallel loop on one core, and its mirrored half
  // waits for it. Each component is its own copy (no shared edges), so they mesh apart.
  parallelFor(scene.components.size(), [&](std::size_t index) {
    const SceneComponent& component = scene.components[index];
    // Meshed already by an earlier output of the same scene? (The mesher gives lines outside
    // faces their polylines too.)
    if (isTriangulated(component.shape.shape) && linesDiscretised(component.shape.shape)) return;
    IMeshTools_Parameters parameters;
    parameters.Deflection =
        options.linearDeflection > 0 ? options.linearDeflection : automaticDeflection(component.shape.shape);
    parameters.Angle = options.angularDeflection;
    parameters.InParallel = true;
    // Delabella's first triangulation of a face: a revolved cowl 0.76 s -> 0.14 s
    // by Watson's, crm.xml's STL 6.5 s -> 3.5 s, the same closed meshes (docs/performance.md).
    parameters.MeshAlgo = IMeshTools_MeshAlgoType_Delabella;
    BRepMesh_IncrementalMesh mesher(component.shape.shape, parameters);
    triangulateFinerWhereNeeded(component, parameters);
  });
}

}  // namespace airshape::exporting
