#include "labelled_shape.h"

#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include "airshape/error.h"
#include "airshape/export/export_scene.h"
#include "airshape/fused_shape.h"

namespace airshape::meshing {

namespace {

constexpr char kSeparator = '\x1f';
const std::string kMirrored = " (mirrored)";

/// A name without the " (mirrored)" that mirrored halves add: both halves are one component
/// for the mesh's groups.
std::string unmirrored(const std::string& name) {
  const std::size_t at = name.size() >= kMirrored.size() ? name.size() - kMirrored.size() : std::string::npos;
  return at != std::string::npos && name.compare(at, kMirrored.size(), kMirrored) == 0 ? name.substr(0, at) : name;
}

/// The solids of a shape, each on its own: the union of compounds that hold one solid each
/// loses some of them in OCCT 7.6 (the example airliner's wing), the union of the solids does not.
std::vector<TopoDS_Shape> solidsOf(const TopoDS_Shape& shape) {
  std::vector<TopoDS_Shape> solids;
  for (TopExp_Explorer solid(shape, TopAbs_SOLID); solid.More(); solid.Next()) solids.push_back(solid.Current());
  return solids;
}

}  // namespace

NamedShape labelledFaces(const TopoDS_Shape& shape, const std::string& component,
                         const std::vector<std::pair<std::string, TopoDS_Face>>& names) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  std::vector<std::string> faceNames(static_cast<std::size_t>(faces.Extent()));
  for (const auto& [name, face] : names)
    if (const int index = faces.FindIndex(face); index > 0) faceNames[static_cast<std::size_t>(index - 1)] = name;
  NamedShape labelled{shape, {}};
  for (int index = 1; index <= faces.Extent(); ++index)
    labelled.faces.emplace_back(
        unmirrored(component) + kSeparator + unmirrored(faceNames[static_cast<std::size_t>(index - 1)]),
        TopoDS::Face(faces(index)));
  return labelled;
}

std::vector<FaceLabel> faceLabels(const NamedShape& labelled) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(labelled.shape, TopAbs_FACE, faces);
  std::vector<FaceLabel> labels(static_cast<std::size_t>(faces.Extent()));
  for (const auto& [name, face] : labelled.faces) {
    const int index = faces.FindIndex(face);
    if (index <= 0) continue;
    const std::size_t separator = name.find(kSeparator);
    labels[static_cast<std::size_t>(index - 1)] =
        separator == std::string::npos ? FaceLabel{name, ""}
                                       : FaceLabel{name.substr(0, separator), name.substr(separator + 1)};
  }
  return labels;
}

NamedShape fusedAircraft(const exporting::ExportScene& scene, std::vector<std::string>& notes) {
  std::vector<NamedShape> solids;
  for (const exporting::SceneComponent& component : scene.components) {
    const std::vector<TopoDS_Shape> ofComponent = solidsOf(component.shape.shape);
    if (ofComponent.empty()) notes.push_back(component.name + ": not meshed: it has no solid (lines or sheets only)");
    for (const TopoDS_Shape& solid : ofComponent)
      solids.push_back(labelledFaces(solid, component.name, component.shape.faces));
  }
  if (solids.empty()) throw Error(ErrorCode::InvalidArgument, "no component with a solid to mesh");
  std::vector<const NamedShape*> inputs;
  for (const NamedShape& solid : solids) inputs.push_back(&solid);
  return fuseNamedShapes(inputs);
}

}  // namespace airshape::meshing
