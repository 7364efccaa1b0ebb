#include "pylon_loft.h"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GeomConvert.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <TopoDS.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/compatibility.h"
#include "airshape/geometry/loft_piece.h"
#include "airshape/geometry/skinning.h"
#include "airshape/model/placed_elements.h"
#include "airshape/model/segment_chain.h"

namespace airshape::nacelle {

namespace {

/// Every engine pylon of every aircraft model.
std::vector<const schema::EnginePylonType*> everyPylon(const Configuration& configuration) {
  std::vector<const schema::EnginePylonType*> pylons;
  const auto& vehicles = configuration.cpacs().vehicles;
  if (vehicles && vehicles->aircraft)
    for (const auto& model : vehicles->aircraft->model)
      if (model.enginePylons)
        for (const auto& pylon : model.enginePylons->enginePylon) pylons.push_back(&pylon);
  return pylons;
}

const schema::EnginePylonType& pylonNamed(const Configuration& configuration, const std::string& uid) {
  for (const schema::EnginePylonType* pylon : everyPylon(configuration))
    if (pylon->uID == uid) return *pylon;
  throw Error(ErrorCode::InvalidArgument, "no engine pylon with uID '" + uid + "'");
}

/// The edges of an airfoil's outline wire as B-splines, in wire order, moved by `transform`.
std::vector<Handle(Geom_BSplineCurve)> placedOutline(const TopoDS_Wire& wire, const model::Transform& transform) {
  std::vector<Handle(Geom_BSplineCurve)> curves;
  for (BRepTools_WireExplorer edge(wire); edge.More(); edge.Next()) {
    double first = 0.0, last = 0.0;
    const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge.Current(), first, last);
    Handle(Geom_BSplineCurve) spline = GeomConvert::CurveToBSplineCurve(new Geom_TrimmedCurve(curve, first, last));
    if (edge.Current().Orientation() == TopAbs_REVERSED) spline->Reverse();
    curves.push_back(geometry::transformed(spline, transform));
  }
  return curves;
}

/// The plane face an outline encloses; null where the outline is a point (a section scaled to
/// nothing: the pylon ends in a point there).
TopoDS_Face capOf(const std::vector<Handle(Geom_BSplineCurve)>& outline, const std::string& where) {
  Bnd_Box box;
  for (const auto& curve : outline)
    for (int i = 1; i <= curve->NbPoles(); ++i) box.Add(curve->Pole(i));
  if (box.IsVoid() || box.SquareExtent() < 1e-20) return {};
  BRepBuilderAPI_MakeWire wire;
  for (const auto& curve : outline) wire.Add(BRepBuilderAPI_MakeEdge(curve).Edge());
  if (!wire.IsDone()) throw Error(ErrorCode::InvalidModel, "the airfoil outline does not close", {}, where);
  BRepBuilderAPI_MakeFace face(wire.Wire(), true);
  if (!face.IsDone()) throw Error(ErrorCode::InvalidModel, "the airfoil outline is not plane", {}, where);
  return face.Face();
}

}  // namespace

std::string pylonHoldingSegment(const Configuration& configuration, const std::string& segmentUid) {
  for (const schema::EnginePylonType* pylon : everyPylon(configuration))
    if (pylon->segments)
      for (const auto& segment : pylon->segments->segment)
        if (segment.uID == segmentUid) return pylon->uID;
  return {};
}

std::shared_ptr<const PylonLoft> PylonLoft::of(const Configuration& configuration, const wing::WingServices& wing,
                                               const std::string& pylonUid) {
  return configuration.cache().obtain<PylonLoft>("pylon-loft:" + pylonUid, [&] {
    const schema::EnginePylonType& pylon = pylonNamed(configuration, pylonUid);
    auto loft = std::make_shared<PylonLoft>();
    loft->uid_ = pylon.uID;
    loft->xpath_ = pylon.xpath;
    if (!pylon.segments || pylon.segments->segment.empty())
      throw NoShape("the pylon has no segments: no shape", pylon.xpath);
    const auto placed = model::placedElements(configuration, pylon);
    std::vector<model::SegmentEnds> chain;
    for (const auto& segment : pylon.segments->segment) chain.push_back({segment.fromElementUID, segment.toElementUID});
    // The outline of each section along the chain: each segment's inner airfoil, then the last outer one.
    std::vector<std::vector<Handle(Geom_BSplineCurve)>> outlines;
    auto addOutline = [&](const std::string& elementUid, const std::string& where) {
      const auto element = placed.find(elementUid);
      if (element == placed.end())
        throw Error(ErrorCode::InvalidModel, "'" + elementUid + "' names no element of this pylon", {}, where);
      outlines.push_back(placedOutline(wing.airfoilWire(configuration, element->second.element->airfoilUID),
                                       element->second.transform));
      loft->caps_.push_back(capOf(outlines.back(), element->second.element->xpath));
    };
    const std::vector<std::size_t> order = model::chainOrder(chain);
    for (std::size_t index : order) {
      const schema::WingSegmentType& segment = pylon.segments->segment[index];
      loft->segmentUids_.push_back(segment.uID);
      addOutline(segment.fromElementUID, segment.xpath + "/fromElementUID");
    }
    const schema::WingSegmentType& last = pylon.segments->segment[order.back()];
    addOutline(last.toElementUID, last.xpath + "/toElementUID");

    const std::size_t edges = outlines.front().size();
    for (const auto& outline : outlines)
      if (outline.size() != edges)
        throw Error(ErrorCode::InvalidModel,
                    "the pylon's airfoils differ in kind (blunt and sharp trailing edges, or point lists and CST "
                    "airfoils): their outlines cannot be lofted edge by edge",
                    {}, pylon.xpath + "/segments");
    for (std::size_t e = 0; e < edges; ++e) {
      std::vector<Handle(Geom_BSplineCurve)> curves;
      for (const auto& outline : outlines) curves.push_back(outline[e]);
      geometry::makeCompatible(curves);
      if (e == 0) loft->parameters_ = geometry::averagedSectionParameters(curves);
      const geometry::KnotVector space = geometry::skinningSpace(loft->parameters_, 3, false);
      loft->skins_.push_back(geometry::skinCurves(curves, loft->parameters_, space));
    }
    return std::shared_ptr<const PylonLoft>(loft);
  });
}

NamedShape PylonLoft::piece(std::size_t from, std::size_t to, const std::string& name) const {
  std::vector<std::pair<std::string, TopoDS_Face>> faces;
  for (const auto& skin : skins_) {
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
    skin->Bounds(u0, u1, v0, v1);
    faces.emplace_back(name + "/skin", geometry::surfacePartFace(skin, u0, u1, parameters_[from], parameters_[to]));
  }
  faces.emplace_back(name + "/inner cap", caps_[from]);
  faces.emplace_back(name + "/outer cap", caps_[to]);
  try {
    return sewnNamedSolid(faces);
  } catch (const Error& error) {
    throw Error(error.code(), error.message(), {}, xpath_);
  }
}

NamedShape PylonLoft::solid() const { return piece(0, parameters_.size() - 1, uid_); }

NamedShape PylonLoft::segmentSolid(const std::string& segmentUid) const {
  for (std::size_t k = 0; k < segmentUids_.size(); ++k)
    if (segmentUids_[k] == segmentUid) return piece(k, k + 1, segmentUid);
  throw Error(ErrorCode::InvalidArgument, "pylon '" + uid_ + "' has no segment '" + segmentUid + "'");
}

}  // namespace airshape::nacelle
