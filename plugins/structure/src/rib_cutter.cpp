#include "rib_cutter.h"

#include <algorithm>
#include <cctype>

#include <BRepAlgoAPI_Section.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "faces_inside.h"
#include "spar_list.h"

namespace airshape::structure {

bool sameName(const std::string& a, const char* b) {
  const std::string other(b);
  return a.size() == other.size() && std::equal(a.begin(), a.end(), other.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

bool isWingEdge(const std::string& name) { return sameName(name, "leadingEdge") || sameName(name, "trailingEdge"); }

RibCutter::RibCutter(const Configuration& configuration, const StructureFrame& frame,
                     const schema::WingComponentSegmentStructureType& structure)
    : configuration_(configuration), frame_(frame), structure_(structure), reach_(frame.reach()) {}

Polyline RibCutter::lineNamed(const std::string& name, const std::string& where) const {
  if (sameName(name, "leadingEdge")) return frame_.leadingEdge();
  if (sameName(name, "trailingEdge")) return frame_.trailingEdge();
  try {
    return frame_.sparLine(sparSegmentNamed(configuration_, name));
  } catch (const Error& error) {
    if (!error.cpacsPath().empty()) throw;
    throw Error(error.code(), error.message(), {}, where);
  }
}

gp_Pnt RibCutter::pointOf(const schema::Child<schema::EtaXsiPointType>& etaXsi,
                          const schema::Child<schema::CurvePointType>& curve,
                          const std::optional<std::string>& sparPosition, const std::string& where) const {
  if (etaXsi) return frame_.chordPoint(etaXsi->referenceUID, etaXsi->eta, etaXsi->xsi);
  if (curve) return lineNamed(curve->referenceUID, where + "CurvePoint").at(curve->eta);
  if (sparPosition) {
    if (structure_.spars && structure_.spars->sparPositions)
      for (const auto& position : structure_.spars->sparPositions->sparPosition)
        if (position.uID == *sparPosition && (position.sparPositionEtaXsi || position.sparPositionRib))
          return frame_.positionPoint(sparPositionOf(position));
    throw Error(ErrorCode::InvalidModel,
                "spar position '" + *sparPosition + "' is not one given by eta and xsi or on a rib", {},
                where + "SparPositionUID");
  }
  throw Error(ErrorCode::InvalidModel, "the rib has no start or end point", {}, where);
}

std::vector<gp_Pnt> RibCutter::sparSection(const std::string& spar, const gp_Pln& plane,
                                           const std::string& where) const {
  const TopoDS_Shape* web = nullptr;
  try {
    web = &configuration_.shapes().shapeOf(configuration_, sparSegmentNamed(configuration_, spar).uid);
  } catch (const Error& error) {
    throw Error(error.code(), "spar '" + spar + "': " + error.message(), {}, where);
  }
  BRepAlgoAPI_Section section(*web, BRepBuilderAPI_MakeFace(plane).Face(), false);
  section.Build();
  std::vector<gp_Pnt> points;
  for (TopExp_Explorer vertex(section.Shape(), TopAbs_VERTEX); vertex.More(); vertex.Next())
    points.push_back(BRep_Tool::Pnt(TopoDS::Vertex(vertex.Current())));
  if (points.size() < 2) throw Error(ErrorCode::InvalidModel, "a rib does not meet spar '" + spar + "'", {}, where);
  return points;
}

std::vector<gp_Pnt> RibCutter::side(const std::string& border, const gp_Pnt& origin, const gp_Vec& outwards,
                                    const gp_Vec& up, const gp_Pln& plane, const std::string& where) const {
  const gp_Vec globalUp = frame_.toGlobal(up).Normalized();
  if (isWingEdge(border)) {
    const gp_Pnt far = frame_.toGlobal(origin.Translated(reach_ * outwards));
    return {far.Translated(-reach_ * globalUp), far.Translated(reach_ * globalUp)};
  }
  std::vector<gp_Pnt> points = sparSection(border, plane, where);
  std::sort(points.begin(), points.end(), [&](const gp_Pnt& a, const gp_Pnt& b) {
    return gp_Vec(a.XYZ()).Dot(globalUp) < gp_Vec(b.XYZ()).Dot(globalUp);
  });
  points.erase(
      std::unique(points.begin(), points.end(), [](const gp_Pnt& a, const gp_Pnt& b) { return a.Distance(b) < 1e-9; }),
      points.end());
  points.insert(points.begin(), points.front().Translated(-reach_ * globalUp));
  points.push_back(points.back().Translated(reach_ * globalUp));
  return points;
}

TopoDS_Face RibCutter::outline(const gp_Pnt& point, const gp_Vec& direction, const gp_Vec& up,
                               const std::string& ribStart, const std::string& ribEnd, const std::string& name,
                               const std::string& where) const {
  const gp_Vec normal = frame_.toGlobal(direction).Crossed(frame_.toGlobal(up));
  const gp_Pln plane(frame_.toGlobal(point), gp_Dir(normal));
  const std::vector<gp_Pnt> front = side(ribStart, point, -direction, up, plane, where + "/ribStart");
  const std::vector<gp_Pnt> back = side(ribEnd, point, direction, up, plane, where + "/ribEnd");
  BRepBuilderAPI_MakePolygon polygon;
  for (const gp_Pnt& p : front) polygon.Add(p);
  for (auto p = back.rbegin(); p != back.rend(); ++p) polygon.Add(*p);
  polygon.Close();
  BRepBuilderAPI_MakeFace face(plane, polygon.Wire(), true);
  if (!face.IsDone()) throw Error(ErrorCode::InvalidModel, "the outline of " + name + " is not plane", {}, where);
  return face.Face();
}

std::vector<std::vector<TopoDS_Face>> RibCutter::cutAll(const std::vector<TopoDS_Face>& outlines,
                                                        const std::vector<std::string>& names,
                                                        const std::string& where) const {
  std::vector<std::vector<TopoDS_Face>> ribs;
  try {
    ribs = facesInsideEach(outlines, frame_.solid());
  } catch (const Error&) {
    throw Error(ErrorCode::InvalidModel, "the ribs cannot be cut out of their component segment", {}, where);
  }
  for (std::size_t i = 0; i < ribs.size(); ++i)
    if (ribs[i].empty())
      throw Error(ErrorCode::InvalidModel, names[i] + " does not cross its component segment", {}, where);
  return ribs;
}

std::vector<TopoDS_Face> RibCutter::cut(const gp_Pnt& point, const gp_Vec& direction, const gp_Vec& up,
                                        const std::string& ribStart, const std::string& ribEnd, const std::string& name,
                                        const std::string& where) const {
  return cutAll({outline(point, direction, up, ribStart, ribEnd, name, where)}, {name}, where).front();
}

}  // namespace airshape::structure
