#include "rib_faces.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Section.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Ax1.hxx>
#include <gp_Pln.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "spar_list.h"
#include "structure_frame.h"

namespace airshape::structure {

namespace {

bool sameName(const std::string& a, const char* b) {
  const std::string other(b);
  return a.size() == other.size() && std::equal(a.begin(), a.end(), other.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

bool isWingEdge(const std::string& name) { return sameName(name, "leadingEdge") || sameName(name, "trailingEdge"); }

/// The ribs of one `ribsPositioning`, worked out in the wing's own frame.
class RibSet {
 public:
  RibSet(const Configuration& configuration, const wing::WingServices& wing, const RibsDefinition& ribs)
      : configuration_(configuration),
        wing_(wing),
        ribs_(ribs),
        positioning_(*ribs.node->ribsPositioning),
        frame_(configuration, wing, ribs.componentSegmentUid, ribs.wingUid),
        reach_(frame_.reach()),
        reference_(lineNamed(positioning_.ribReference, xpath() + "/ribReference")) {}

  NamedShape build() const {
    const double start = etaOnReference(endPoint(true), startsOnSparPosition());
    const double end = etaOnReference(endPoint(false), endsOnSparPosition());
    const int count = numberOfRibs(start, end);
    const double offset = etaOffset(start, end, count);
    NamedShape ribs;
    BRep_Builder builder;
    TopoDS_Compound faces;
    builder.MakeCompound(faces);
    for (int i = 0; i < count; ++i) {
      const double eta = start + offset * i;
      const bool onSpar = (i == 0 && startsOnSparPosition()) || (std::abs(end - eta) <= 1e-7 && endsOnSparPosition());
      const std::string name = ribs_.uid + "/rib " + std::to_string(i + 1);
      for (const TopoDS_Face& face : ribAt(reference_.at(eta), eta, onSpar, name)) {
        builder.Add(faces, face);
        ribs.faces.emplace_back(name, face);
      }
    }
    ribs.shape = faces;
    return ribs;
  }

 private:
  std::string xpath() const { return ribs_.xpath + "/ribsPositioning"; }

  bool startsOnSparPosition() const { return positioning_.startSparPositionUID.has_value(); }
  bool endsOnSparPosition() const { return positioning_.endSparPositionUID.has_value(); }

  /// The leading edge, the trailing edge or a spar's midplane line, in the wing frame.
  Polyline lineNamed(const std::string& name, const std::string& where) const {
    if (sameName(name, "leadingEdge")) return frame_.leadingEdge();
    if (sameName(name, "trailingEdge")) return frame_.trailingEdge();
    try {
      return frame_.sparLine(sparSegmentNamed(configuration_, name));
    } catch (const Error& error) {
      if (!error.cpacsPath().empty()) throw;
      throw Error(error.code(), error.message(), {}, where);
    }
  }

  /// The start (or end) point of the ribs, in the wing frame.
  gp_Pnt endPoint(bool start) const {
    const auto& etaXsi = start ? positioning_.startEtaXsiPoint : positioning_.endEtaXsiPoint;
    const auto& curve = start ? positioning_.startCurvePoint : positioning_.endCurvePoint;
    const auto& sparPosition = start ? positioning_.startSparPositionUID : positioning_.endSparPositionUID;
    const std::string where = xpath() + (start ? "/start" : "/end");
    if (etaXsi) return frame_.chordPoint(etaXsi->referenceUID, etaXsi->eta, etaXsi->xsi);
    if (curve) return lineNamed(curve->referenceUID, where + "CurvePoint").at(curve->eta);
    if (sparPosition) return sparPositionPoint(*sparPosition, where + "SparPositionUID");
    throw Error(ErrorCode::InvalidModel, "the ribs have no start or end point", {}, xpath());
  }

  gp_Pnt sparPositionPoint(const std::string& uid, const std::string& where) const {
    const schema::WingComponentSegmentStructureType& structure = *ribs_.structure;
    if (structure.spars && structure.spars->sparPositions)
      for (const auto& position : structure.spars->sparPositions->sparPosition)
        if (position.uID == uid && position.sparPositionEtaXsi)
          return frame_.chordPoint(position.sparPositionEtaXsi->referenceUID, position.sparPositionEtaXsi->eta,
                                   position.sparPositionEtaXsi->xsi);
    throw Error(ErrorCode::InvalidModel, "spar position '" + uid + "' is not one given by eta and xsi", {}, where);
  }

  /// The rib's direction from its start to its end, turned as `ribRotation` says.
  gp_Vec ribDirection() const {
    const double z = (positioning_.ribRotation ? positioning_.ribRotation->z : 90.0) * M_PI / 180.0;
    const std::string reference =
        positioning_.ribRotation ? positioning_.ribRotation->ribRotationReference.value_or("") : "";
    gp_Vec direction;
    if (sameName(reference, "globalY"))
      direction = gp_Vec(0, 1, 0);
    else if (sameName(reference, "globalX"))
      direction = gp_Vec(-1, 0, 0);
    else
      throw Error(ErrorCode::NotImplemented,
                  "ribs turned relative to '" + (reference.empty() ? std::string("the midplane") : reference) +
                      "' are not built yet (globalY and globalX are)",
                  {}, xpath() + "/ribRotation");
    direction.Rotate(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), z);
    return -direction.Normalized();
  }

  double xRotation() const {
    const auto& section = ribs_.node->ribCrossSection;
    return section && section->ribRotation ? section->ribRotation->x : 90.0;
  }

  /// The rib's up direction at a point (wing frame): the midplane normal, or the wing's z
  /// axis at a spar position or a spar's end (as the spars stand).
  gp_Vec upAt(const gp_Pnt& point, double eta, bool onSpar) const {
    const bool sparEnd = !isWingEdge(positioning_.ribReference) && (eta < 1e-7 || eta > 1.0 - 1e-7);
    if (onSpar || sparEnd) return gp_Vec(0, 0, 1);
    return frame_.midplaneNormal(frame_.etaOf(point));
  }

  /// The rib plane's directions at a point: its direction and its tilted up direction.
  std::pair<gp_Vec, gp_Vec> ribAxes(const gp_Pnt& point, double eta, bool onSpar) const {
    gp_Vec up = upAt(point, eta, onSpar);
    const gp_Vec direction = ribDirection();
    up.Rotate(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(direction)), (xRotation() - 90.0) * M_PI / 180.0);
    return {direction, up};
  }

  /// The share of the reference line where the rib through a point crosses it.
  double etaOnReference(const gp_Pnt& point, bool onSpar) const {
    const auto [direction, up] = ribAxes(point, 0.5, onSpar);
    const auto share = reference_.crossing(point, up.Crossed(direction));
    if (!share)
      throw Error(ErrorCode::InvalidModel, "a rib through the start or end point misses the reference line", {},
                  xpath());
    return *share;
  }

  int numberOfRibs(double start, double end) const {
    if (positioning_.numberOfRibs) {
      if (*positioning_.numberOfRibs < 1)
        throw Error(ErrorCode::InvalidModel, "numberOfRibs must be at least 1", {}, xpath() + "/numberOfRibs");
      return static_cast<int>(*positioning_.numberOfRibs);
    }
    if (!positioning_.spacing || !(*positioning_.spacing > 0))
      throw Error(ErrorCode::InvalidModel, "the ribs need a positive spacing or a numberOfRibs", {}, xpath());
    if (std::abs(end - start) <= 1e-7) return 1;
    return static_cast<int>((reference_.length() * std::abs(end - start) + 1e-7) / *positioning_.spacing) + 1;
  }

  double etaOffset(double start, double end, int count) const {
    if (positioning_.numberOfRibs) return count == 1 ? 0.0 : std::abs(end - start) / (count - 1);
    return *positioning_.spacing / reference_.length();
  }

  /// One side of a rib in the global frame, bottom to top along `up`: where the rib plane
  /// meets a spar's web, carried far along up; or, at the wing's leading or trailing edge, a
  /// line far out along the rib.
  std::vector<gp_Pnt> side(const std::string& border, const gp_Pnt& origin, const gp_Vec& outwards, const gp_Vec& up,
                           const gp_Pln& plane, const std::string& where) const {
    const gp_Vec globalUp = frame_.toGlobal(up).Normalized();
    if (isWingEdge(border)) {
      const gp_Pnt far = frame_.toGlobal(origin.Translated(reach_ * outwards));
      return {far.Translated(-reach_ * globalUp), far.Translated(reach_ * globalUp)};
    }
    const TopoDS_Shape* web = nullptr;
    try {
      web = &configuration_.shapes().shapeOf(configuration_, sparSegmentNamed(configuration_, border).uid);
    } catch (const Error& error) {
      throw Error(error.code(), "spar '" + border + "': " + error.message(), {}, where);
    }
    BRepAlgoAPI_Section section(*web, BRepBuilderAPI_MakeFace(plane).Face(), false);
    section.Build();
    std::vector<gp_Pnt> points;
    for (TopExp_Explorer vertex(section.Shape(), TopAbs_VERTEX); vertex.More(); vertex.Next())
      points.push_back(BRep_Tool::Pnt(TopoDS::Vertex(vertex.Current())));
    if (points.size() < 2) throw Error(ErrorCode::InvalidModel, "a rib does not meet spar '" + border + "'", {}, where);
    std::sort(points.begin(), points.end(), [&](const gp_Pnt& a, const gp_Pnt& b) {
      return gp_Vec(a.XYZ()).Dot(globalUp) < gp_Vec(b.XYZ()).Dot(globalUp);
    });
    points.erase(std::unique(points.begin(), points.end(),
                             [](const gp_Pnt& a, const gp_Pnt& b) { return a.Distance(b) < 1e-9; }),
                 points.end());
    points.insert(points.begin(), points.front().Translated(-reach_ * globalUp));
    points.push_back(points.back().Translated(reach_ * globalUp));
    return points;
  }

  /// The faces of one rib through a point of the reference line (wing frame).
  std::vector<TopoDS_Face> ribAt(const gp_Pnt& point, double eta, bool onSpar, const std::string& name) const {
    const auto [direction, up] = ribAxes(point, eta, onSpar);
    const gp_Pnt globalPoint = frame_.toGlobal(point);
    const gp_Vec normal = frame_.toGlobal(direction).Crossed(frame_.toGlobal(up));
    const gp_Pln plane(globalPoint, gp_Dir(normal));
    const std::vector<gp_Pnt> front = side(positioning_.ribStart, point, -direction, up, plane, xpath() + "/ribStart");
    const std::vector<gp_Pnt> back = side(positioning_.ribEnd, point, direction, up, plane, xpath() + "/ribEnd");
    BRepBuilderAPI_MakePolygon outline;
    for (const gp_Pnt& p : front) outline.Add(p);
    for (auto p = back.rbegin(); p != back.rend(); ++p) outline.Add(*p);
    outline.Close();
    BRepBuilderAPI_MakeFace cutFace(plane, outline.Wire(), true);
    if (!cutFace.IsDone())
      throw Error(ErrorCode::InvalidModel, "the outline of " + name + " is not plane", {}, xpath());
    BRepAlgoAPI_Common common(cutFace.Face(), frame_.solid());
    if (!common.IsDone() || common.HasErrors())
      throw Error(ErrorCode::InvalidModel, name + " cannot be cut out of its component segment", {}, xpath());
    std::vector<TopoDS_Face> faces;
    for (TopExp_Explorer face(common.Shape(), TopAbs_FACE); face.More(); face.Next())
      faces.push_back(TopoDS::Face(face.Current()));
    if (faces.empty())
      throw Error(ErrorCode::InvalidModel, name + " does not cross its component segment", {}, xpath());
    return faces;
  }

  const Configuration& configuration_;
  const wing::WingServices& wing_;
  const RibsDefinition& ribs_;
  const schema::WingRibsPositioningType& positioning_;
  StructureFrame frame_;
  double reach_;
  Polyline reference_;
};

}  // namespace

NamedShape ribFaces(const Configuration& configuration, const wing::WingServices& wing, const RibsDefinition& ribs) {
  if (!ribs.node->ribsPositioning)
    throw Error(ErrorCode::NotImplemented, "explicitly positioned ribs are not built yet", {},
                ribs.xpath + "/ribExplicitPositioning");
  return RibSet(configuration, wing, ribs).build();
}

}  // namespace airshape::structure
