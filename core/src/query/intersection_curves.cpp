#include "intersection_curves.h"

#include <BRepAdaptor_CompCurve.hxx>
#include <BRepAlgoAPI_Section.hxx>
#include <GCPnts_QuasiUniformDeflection.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_HSequenceOfShape.hxx>
#include <TopoDS.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/query/arguments.h"

namespace airshape::query {

namespace {

constexpr double kDefaultDeflection = 1e-3;
constexpr double kChainingTolerance = 1e-6;

/// The section edges chained into wires, each wire one connected piece of the curve.
Handle(TopTools_HSequenceOfShape) connectedPieces(const TopoDS_Shape& section) {
  Handle(TopTools_HSequenceOfShape) edges = new TopTools_HSequenceOfShape;
  for (TopExp_Explorer explorer(section, TopAbs_EDGE); explorer.More(); explorer.Next())
    edges->Append(explorer.Current());
  Handle(TopTools_HSequenceOfShape) wires = new TopTools_HSequenceOfShape;
  if (!edges->IsEmpty()) ShapeAnalysis_FreeBounds::ConnectEdgesToWires(edges, kChainingTolerance, false, wires);
  return wires;
}

Json polyline(const TopoDS_Wire& wire, double deflection) {
  const BRepAdaptor_CompCurve curve(wire);
  GCPnts_QuasiUniformDeflection points(curve, deflection);
  if (!points.IsDone()) throw Error(ErrorCode::InvalidModel, "the intersection curve could not be discretised");
  Json line = Json::array();
  for (int i = 1; i <= points.NbPoints(); ++i) {
    const gp_Pnt p = points.Value(i);
    line.push_back({p.X(), p.Y(), p.Z()});
  }
  return line;
}

}  // namespace

Json intersectionCurves(Configuration& configuration, const Json& query) {
  const ComponentShapes& shapes = configuration.shapes();
  const TopoDS_Shape& first = shapes.shapeOf(configuration, stringArgument(query, "uid"));
  const std::string other = stringArgument(query, "other");
  const bool mirrored = query.contains("other_mirrored") && query.at("other_mirrored").is_boolean() &&
                        query.at("other_mirrored").get<bool>();
  const TopoDS_Shape& second =
      mirrored ? shapes.mirroredShapeOf(configuration, other).shape : shapes.shapeOf(configuration, other);
  const double deflection = query.contains("deflection") ? numberArgument(query, "deflection") : kDefaultDeflection;
  if (!(deflection > 0)) throw Error(ErrorCode::InvalidArgument, "deflection must be positive");

  BRepAlgoAPI_Section section(first, second, false);
  section.Approximation(true);
  section.Build();
  if (!section.IsDone() || section.HasErrors())
    throw Error(ErrorCode::InvalidModel,
                "the intersection of '" + stringArgument(query, "uid") + "' and '" + other + "' could not be computed");
  Json curves = Json::array();
  const Handle(TopTools_HSequenceOfShape) pieces = connectedPieces(section.Shape());
  for (int i = 1; i <= pieces->Length(); ++i) curves.push_back(polyline(TopoDS::Wire(pieces->Value(i)), deflection));
  return curves;
}

}  // namespace airshape::query
