#include "spar_web.h"

#include <cmath>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepFill.hxx>
#include <BRep_Builder.hxx>
#include <Bnd_Box.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/model/placement.h"
#include "faces_inside.h"

namespace airshape::structure {

namespace {

using Surface = wing::WingServices::Surface;

/// The wing's up direction in the global frame: the z axis of its own frame.
gp_Vec upDirectionOf(const Configuration& configuration, const std::string& wingUid) {
  const model::Transform toGlobal = model::componentTransform(configuration, wingUid);
  const gp_Vec up(model::apply(toGlobal, gp_Pnt(0, 0, 0)), model::apply(toGlobal, gp_Pnt(0, 0, 1)));
  return up.Normalized();
}

/// A spar position's point on the chord surface and its component segment eta.
struct PlacedPosition {
  gp_Pnt point;
  double eta = 0.0;
};

PlacedPosition placed(const Configuration& configuration, const wing::WingServices& wing, const SparSegment& spar,
                      const SparPosition& position) {
  if (position.kind != SparPosition::Kind::EtaXsi)
    throw Error(ErrorCode::NotImplemented, "spar positions on ribs or curves are not built yet", {}, position.xpath);
  try {
    return {wing.pointRelativeTo(configuration, spar.componentSegmentUid, position.referenceUid, position.eta,
                                 position.xsi, Surface::Chord),
            wing.componentSegmentEta(configuration, spar.componentSegmentUid, position.referenceUid, position.eta)};
  } catch (const Error& error) {
    throw Error(error.code(), error.message(), {}, position.xpath + "/sparPositionEtaXsi");
  }
}

/// The ruled face between the lines along `up` through two spar points, reaching `reach`
/// above and below them, carried `reach` beyond an end of the component segment.
TopoDS_Face cutFace(const PlacedPosition& inner, const PlacedPosition& outer, const gp_Vec& up, double reach) {
  gp_Pnt innerPoint = inner.point, outerPoint = outer.point;
  const gp_Vec along(inner.point, outer.point);
  if (inner.eta <= 1e-7) innerPoint.Translate(-reach * along.Normalized());
  if (outer.eta >= 1.0 - 1e-7) outerPoint.Translate(reach * along.Normalized());
  const TopoDS_Edge innerLine =
      BRepBuilderAPI_MakeEdge(innerPoint.Translated(reach * up), innerPoint.Translated(-reach * up)).Edge();
  const TopoDS_Edge outerLine =
      BRepBuilderAPI_MakeEdge(outerPoint.Translated(reach * up), outerPoint.Translated(-reach * up)).Edge();
  return BRepFill::Face(innerLine, outerLine);
}

}  // namespace

NamedShape sparWeb(const Configuration& configuration, const wing::WingServices& wing, const SparSegment& spar) {
  if (spar.positions.size() < 2)
    throw Error(ErrorCode::InvalidModel, "a spar segment needs at least two spar positions", {},
                spar.xpath + "/sparPositionUIDs");
  const TopoDS_Shape& solid = configuration.shapes().shapeOf(configuration, spar.componentSegmentUid);
  Bnd_Box box;
  BRepBndLib::Add(solid, box);
  const double reach = std::sqrt(box.SquareExtent());
  const gp_Vec up = upDirectionOf(configuration, spar.wingUid);

  NamedShape web;
  BRep_Builder builder;
  TopoDS_Compound faces;
  builder.MakeCompound(faces);
  PlacedPosition inner = placed(configuration, wing, spar, spar.positions.front());
  for (std::size_t i = 1; i < spar.positions.size(); ++i) {
    const PlacedPosition outer = placed(configuration, wing, spar, spar.positions[i]);
    if (inner.point.Distance(outer.point) < 1e-9)
      throw Error(ErrorCode::InvalidModel,
                  "spar positions '" + spar.positions[i - 1].uid + "' and '" + spar.positions[i].uid + "' coincide", {},
                  spar.xpath);
    std::vector<TopoDS_Face> inside;
    try {
      inside = facesInside(cutFace(inner, outer, up, reach), solid);
    } catch (const Error& error) {
      throw Error(error.code(), "the spar cannot be cut out of its component segment", {}, spar.xpath);
    }
    for (const TopoDS_Face& face : inside) {
      builder.Add(faces, face);
      web.faces.emplace_back(spar.uid + "/web", face);
    }
    inner = outer;
  }
  if (web.faces.empty())
    throw Error(ErrorCode::InvalidModel, "the spar does not cross its component segment", {}, spar.xpath);
  web.shape = faces;
  return web;
}

}  // namespace airshape::structure
