#include "cell_skin.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Pln.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/faces_inside.h"
#include "airshape/geometry/parameter_region.h"
#include "airshape/geometry/plane_region.h"
#include "airshape/geometry/ruled_prism.h"
#include "airshape/geometry/ruled_sections.h"
#include "airshape/geometry/skin_section.h"
#include "airshape/geometry/skin_split.h"
#include "airshape/model/placement.h"
#include "contour_cell.h"
#include "named_faces.h"
#include "rib_point.h"
#include "spar_list.h"
#include "structure_frame.h"

namespace airshape::structure {

namespace {

using Surface = wing::WingServices::Surface;

class CellCorners {
 public:
  CellCorners(const Configuration& configuration, const WingCell& cell, const StructureFrame& frame)
      : configuration_(configuration), cell_(cell), frame_(frame) {}

  /// A corner on the chord surface (wing frame): at the inner or outer border, at the leading
  /// or trailing edge.
  gp_Pnt at(bool inner, bool leadingEdge) const {
    const auto& spanwise = inner ? cell_.node->positioningInnerBorder : cell_.node->positioningOuterBorder;
    const auto& chordwise = leadingEdge ? cell_.node->positioningLeadingEdge : cell_.node->positioningTrailingEdge;
    const std::string spanwisePath = cell_.xpath + (inner ? "/positioningInnerBorder" : "/positioningOuterBorder");
    const std::string chordwisePath =
        cell_.xpath + (leadingEdge ? "/positioningLeadingEdge" : "/positioningTrailingEdge");
    if (!spanwise || !chordwise)
      throw Error(ErrorCode::InvalidModel, "the cell has no border positioning", {},
                  !spanwise ? spanwisePath : chordwisePath);
    if (spanwise->ribDefinitionUID) return onRib(*spanwise, *chordwise, inner, spanwisePath, chordwisePath);
    const double csEta = etaAt(*spanwise, leadingEdge, spanwisePath);
    return frame_.chordPoint("", csEta, xsiAt(*chordwise, inner, csEta, chordwisePath));
  }

  /// The normal of the rib's plane a spanwise border lies on; nothing for a border of etas.
  std::optional<gp_Vec> ribNormal(bool inner) const {
    const auto& spanwise = inner ? cell_.node->positioningInnerBorder : cell_.node->positioningOuterBorder;
    if (!spanwise || !spanwise->ribDefinitionUID) return std::nullopt;
    const std::string where = cell_.xpath + (inner ? "/positioningInnerBorder" : "/positioningOuterBorder");
    return gp_Vec(ribPlaneOf(*spanwise->ribDefinitionUID, spanwise->ribNumber.value_or(1), where).Axis().Direction());
  }

  /// Whether the leading (trailing) border is given as the chord's end: xsi 0 (1) at both its
  /// ends, no spar.
  bool atChordEnd(bool leadingEdge) const {
    const auto& chordwise = leadingEdge ? cell_.node->positioningLeadingEdge : cell_.node->positioningTrailingEdge;
    if (!chordwise || !chordwise->xsi1 || !chordwise->xsi2 || chordwise->sparUID) return false;
    const double edge = leadingEdge ? 0.0 : 1.0;
    return std::abs(*chordwise->xsi1 - edge) <= 1e-12 && std::abs(*chordwise->xsi2 - edge) <= 1e-12;
  }

  /// Whether a spar gives the leading (trailing) edge.
  bool onSpar(bool leadingEdge) const {
    const auto& chordwise = leadingEdge ? cell_.node->positioningLeadingEdge : cell_.node->positioningTrailingEdge;
    return chordwise && chordwise->sparUID && !(chordwise->xsi1 && chordwise->xsi2);
  }

  /// The spar's corners between a cell's inner and outer corner on a chordwise border that a
  /// spar gives, from `from` to `to` (none for a border of xsi values).
  std::vector<gp_Pnt> alongSpar(bool leadingEdge, const gp_Pnt& from, const gp_Pnt& to) const {
    if (!onSpar(leadingEdge)) return {};
    const auto& chordwise = leadingEdge ? cell_.node->positioningLeadingEdge : cell_.node->positioningTrailingEdge;
    const geometry::Polyline spar = frame_.sparLine(sparSegmentNamed(configuration_, *chordwise->sparUID));
    return spar.cornersBetween(spar.nearestShare(from), spar.nearestShare(to));
  }

 private:
  /// A corner on a rib border: where the rib's plane crosses the chord surface's line of the
  /// leading (trailing) edge's xsi, or the spar's midplane line.
  gp_Pnt onRib(const schema::CellPositioningSpanwiseType& spanwise,
               const schema::CellPositioningChordwiseType& chordwise, bool inner, const std::string& spanwisePath,
               const std::string& chordwisePath) const {
    const gp_Pln rib = ribPlaneOf(*spanwise.ribDefinitionUID, spanwise.ribNumber.value_or(1), spanwisePath);
    auto side = [&](const gp_Pnt& p) { return gp_Vec(rib.Location(), p).Dot(gp_Vec(rib.Axis().Direction())); };
    if (chordwise.sparUID) {
      const geometry::Polyline spar = frame_.sparLine(sparSegmentNamed(configuration_, *chordwise.sparUID));
      const auto share = spar.crossing(rib.Location(), gp_Vec(rib.Axis().Direction()));
      if (!share)
        throw Error(ErrorCode::InvalidModel, "spar '" + *chordwise.sparUID + "' does not reach the rib", {},
                    chordwisePath);
      return spar.at(*share);
    }
    if (!chordwise.xsi1 || !chordwise.xsi2)
      throw Error(ErrorCode::InvalidModel, "the border gives neither xsi1 and xsi2 nor a spar", {}, chordwisePath);
    const double xsi =
        model::fraction(inner ? *chordwise.xsi1 : *chordwise.xsi2, chordwisePath + (inner ? "/xsi1" : "/xsi2"));
    double low = 0.0, high = 1.0;
    double sideLow = side(frame_.chordPoint("", low, xsi));
    if ((sideLow <= 0.0) == (side(frame_.chordPoint("", high, xsi)) <= 0.0))
      throw Error(ErrorCode::InvalidModel, "the rib does not cross the cell's chordwise border", {}, spanwisePath);
    for (int step = 0; step < 60; ++step) {
      const double middle = 0.5 * (low + high), sideMiddle = side(frame_.chordPoint("", middle, xsi));
      if ((sideMiddle <= 0.0) == (sideLow <= 0.0))
        low = middle, sideLow = sideMiddle;
      else
        high = middle;
    }
    return frame_.chordPoint("", 0.5 * (low + high), xsi);
  }

  /// A rib's plane, placed once for the cell's corners on it (placing a rib places its whole
  /// set).
  gp_Pln ribPlaneOf(const std::string& ribsUid, long long number, const std::string& where) const {
    const auto key = std::make_pair(ribsUid, number);
    auto known = ribPlanes_.find(key);
    if (known == ribPlanes_.end())
      known = ribPlanes_.emplace(key, ribPlane(configuration_, frame_, ribsUid, number, where)).first;
    return known->second;
  }

  /// The component segment eta of a border at the leading edge (eta1) or trailing edge (eta2).
  double etaAt(const schema::CellPositioningSpanwiseType& spanwise, bool leadingEdge, const std::string& where) const {
    const auto& eta = leadingEdge ? spanwise.eta1 : spanwise.eta2;
    if (!eta) throw Error(ErrorCode::InvalidModel, "the border gives neither eta1 and eta2 nor a rib", {}, where);
    const std::string element = where + (leadingEdge ? "/eta1" : "/eta2");
    if (const auto bare = bareNumber(element)) return model::fraction(*bare, element);
    const double value = model::fraction(eta->eta, element + "/eta");
    try {
      return frame_.frameEta(eta->referenceUID, value);
    } catch (const Error& error) {
      throw Error(error.code(), error.message(), {}, where);
    }
  }

  /// An eta written as a bare number (`<eta1>0.5</eta1>`, as older files do) instead of an
  /// `eta` with its `referenceUID`: read as a component segment eta, with a warning.
  std::optional<double> bareNumber(const std::string& element) const {
    try {
      configuration_.value(element + "/eta");
      return std::nullopt;  // the schema's form
    } catch (const Error&) {
    }
    try {
      const std::string text = configuration_.value(element);
      std::size_t used = 0;
      const double value = std::stod(text, &used);
      if (text.find_first_not_of(" \t\r\n", used) != std::string::npos) return std::nullopt;
      configuration_.warnAboutGeometry(
          {Problem::Severity::Warning, element, "eta given as a bare number; read as a component segment eta"});
      return value;
    } catch (const std::exception&) {
      return std::nullopt;
    }
  }

  double xsiAt(const schema::CellPositioningChordwiseType& chordwise, bool inner, double eta,
               const std::string& where) const {
    if (chordwise.xsi1 && chordwise.xsi2)
      return model::fraction(inner ? *chordwise.xsi1 : *chordwise.xsi2, where + (inner ? "/xsi1" : "/xsi2"));
    if (!chordwise.sparUID)
      throw Error(ErrorCode::InvalidModel, "the border gives neither xsi1 and xsi2 nor a spar", {}, where);
    // Where the spar's midplane line crosses the chord at eta.
    const gp_Pnt front = frame_.chordPoint("", eta, 0.0), back = frame_.chordPoint("", eta, 1.0);
    const gp_Vec chord(front, back);
    const geometry::Polyline spar = frame_.sparLine(sparSegmentNamed(configuration_, *chordwise.sparUID));
    const auto share = spar.crossing(front, chord.Crossed(gp_Vec(0, 0, 1)));
    if (!share)
      throw Error(ErrorCode::InvalidModel, "spar '" + *chordwise.sparUID + "' does not reach the cell's border", {},
                  where);
    return gp_Vec(front, spar.at(*share)).Dot(chord) / chord.SquareMagnitude();
  }

  const Configuration& configuration_;
  const WingCell& cell_;
  const StructureFrame& frame_;
  mutable std::map<std::pair<std::string, long long>, gp_Pln> ribPlanes_;
};

/// The skin's faces inside the prism, by a Boolean common.
std::vector<TopoDS_Face> cutByPrism(const TopoDS_Shape& skin, const TopoDS_Shape& prism, const std::string& xpath) {
  try {
    return geometry::facesInside(skin, prism);
  } catch (const Error&) {
    throw Error(ErrorCode::InvalidModel, "the cell cannot be cut out of its skin", {}, xpath);
  }
}

/// Whether two faces lie on one surface: the same, or B-spline surfaces with the same degrees,
/// knots and poles (a Boolean result may hold a copy).
bool sameSurface(const Handle(Geom_Surface) & a, const Handle(Geom_Surface) & b) {
  if (a == b) return true;
  const Handle(Geom_BSplineSurface) p = Handle(Geom_BSplineSurface)::DownCast(a);
  const Handle(Geom_BSplineSurface) q = Handle(Geom_BSplineSurface)::DownCast(b);
  if (p.IsNull() || q.IsNull() || p->UDegree() != q->UDegree() || p->VDegree() != q->VDegree() ||
      p->NbUPoles() != q->NbUPoles() || p->NbVPoles() != q->NbVPoles() || p->NbUKnots() != q->NbUKnots() ||
      p->NbVKnots() != q->NbVKnots())
    return false;
  for (int i = 1; i <= p->NbUKnots(); ++i)
    if (p->UKnot(i) != q->UKnot(i)) return false;
  for (int j = 1; j <= p->NbVKnots(); ++j)
    if (p->VKnot(j) != q->VKnot(j)) return false;
  for (int i = 1; i <= p->NbUPoles(); ++i)
    for (int j = 1; j <= p->NbVPoles(); ++j)
      if (p->Pole(i, j).Distance(q->Pole(i, j)) > 1e-12 * (1.0 + gp_Vec(p->Pole(i, j).XYZ()).Magnitude())) return false;
  return true;
}

/// A device's cell without a Boolean operation: the cell's pieces of the wing's untrimmed skin
/// (split directly along its loop) in common with the device's own faces on the same surfaces,
/// in the surfaces' parameter planes (the device's faces are trimmed pieces of the skin, which
/// the split does not take). Nothing where that does not apply (then the Boolean cut of the
/// device's faces by the prism).
std::optional<std::vector<TopoDS_Face>> fromDeviceFaces(const StructureFrame& frame, bool upper,
                                                        const geometry::RuledLoop& ruled,
                                                        const std::function<bool(const gp_Pnt&)>& keep,
                                                        double tolerance) {
  const std::optional<std::vector<TopoDS_Face>> pieces =
      geometry::skinPiecesWhere(frame.componentSegmentSkin(upper), ruled, keep, tolerance);
  if (!pieces) return std::nullopt;
  std::vector<TopoDS_Face> cell;
  for (TopExp_Explorer explorer(frame.skin(upper), TopAbs_FACE); explorer.More(); explorer.Next()) {
    const TopoDS_Face& device = TopoDS::Face(explorer.Current());
    const Handle(Geom_Surface) surface = BRep_Tool::Surface(device);
    double u0 = 0.0, u1 = 0.0, v0 = 0.0, v1 = 0.0;
    surface->Bounds(u0, u1, v0, v1);
    const double parameterTolerance = 1e-9 * std::max(u1 - u0, v1 - v0);
    std::optional<geometry::PlaneRegion> deviceRegion;
    for (const TopoDS_Face& piece : *pieces) {
      if (!sameSurface(BRep_Tool::Surface(piece), surface)) continue;
      if (!deviceRegion && !(deviceRegion = geometry::parameterRegionOf(device))) return std::nullopt;
      const std::optional<geometry::PlaneRegion> pieceRegion = geometry::parameterRegionOf(piece);
      if (!pieceRegion) return std::nullopt;
      const auto common =
          geometry::commonOf(geometry::kParameterPlane, *deviceRegion, *pieceRegion, parameterTolerance);
      if (!common) return std::nullopt;
      for (const TopoDS_Face& inParameters : *common) {
        const std::optional<TopoDS_Face> face = geometry::faceOnSurface(surface, inParameters, device);
        if (!face) return std::nullopt;
        cell.push_back(*face);
      }
    }
  }
  if (cell.empty()) return std::nullopt;
  return cell;
}

/// Moves a corner of a cell's outline along the side from `neighbour` to it, past the farthest
/// of the skin's box corners (`skinCorners`, the loop's frame) that way and a thousandth of the
/// side further: the side's line then misses the skin.
void prolongPastSkin(std::vector<gp_Pnt>& loop, std::size_t corner, std::size_t neighbour,
                     const std::vector<gp_Pnt>& skinCorners) {
  const gp_Vec side(loop[neighbour], loop[corner]);
  const gp_Dir along(side);
  double past = 0.0;
  for (const gp_Pnt& skinCorner : skinCorners)
    past = std::max(past, gp_Vec(loop[corner], skinCorner).Dot(gp_Vec(along)));
  loop[corner].Translate(gp_Vec(along) * (past + 1e-3 * side.Magnitude()));
}

/// Moves a border on the component segment's root or tip beyond the skin's end. It lies on the
/// skin's own edge there, which a section leaning outwards carries past the border's lines: they
/// would meet the skin short of its edge, or (an upright one) just at its bound, found on it or
/// off it by rounding. Beyond the skin they miss it, which then ends the cell with its own edge.
/// `outerFront` indexes the outer border's first corner in the loop (the outer border runs from
/// it to the next corner, the inner from the last corner to the first); `skinCorners` are the
/// corners of a box round the skin (the loop's frame).
void beyondSkinEnds(std::vector<gp_Pnt>& loop, const std::vector<double>& etas, std::size_t outerFront,
                    const std::vector<gp_Pnt>& skinCorners) {
  const std::size_t last = loop.size() - 1, outerBack = outerFront + 1;
  if (etas[outerFront] >= 1.0 - 1e-9 && etas[outerBack] >= 1.0 - 1e-9) {
    prolongPastSkin(loop, outerFront, outerFront - 1, skinCorners);
    prolongPastSkin(loop, outerBack, outerBack == last ? 0 : outerBack + 1, skinCorners);
  }
  if (etas.front() <= 1e-9 && etas.back() <= 1e-9) {
    prolongPastSkin(loop, 0, 1, skinCorners);
    prolongPastSkin(loop, last, last - 1, skinCorners);
  }
}

/// Moves a chordwise border that lies on the wing's own leading (trailing) edge beyond the skin's
/// end there: the border is the skin's edge. A side through the corners along the component
/// segment's one cell direction would lean across a twisted wing's rounded nose and cut off the
/// skin ahead of it (D150's cell_us_le lost 2 cm of its nose). The corners move along the
/// spanwise borders, which keeps those borders' planes.
void beyondWingEdges(std::vector<gp_Pnt>& loop, std::size_t outerFront, bool leadingEdge, bool trailingEdge,
                     const std::vector<gp_Pnt>& skinCorners) {
  const std::size_t last = loop.size() - 1, outerBack = outerFront + 1;
  if (leadingEdge) {
    prolongPastSkin(loop, 0, last, skinCorners);
    prolongPastSkin(loop, outerFront, outerBack, skinCorners);
  }
  if (trailingEdge) {
    prolongPastSkin(loop, outerBack, outerFront, skinCorners);
    prolongPastSkin(loop, last, 0, skinCorners);
  }
}

/// Whether a point lies on a shape, within `tolerance`.
bool onSkin(const gp_Pnt& point, const TopoDS_Shape& skin, double tolerance) {
  BRepExtrema_DistShapeShape distance(BRepBuilderAPI_MakeVertex(point).Vertex(), skin);
  return distance.IsDone() && distance.Value() <= tolerance;
}

/// The corners of a box round the shape, in the frame's wing coordinates.
std::vector<gp_Pnt> boxCorners(const TopoDS_Shape& shape, const StructureFrame& frame) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box, false);
  double x[2], y[2], z[2];
  box.Get(x[0], y[0], z[0], x[1], y[1], z[1]);
  std::vector<gp_Pnt> corners;
  for (int corner = 0; corner < 8; ++corner)
    corners.push_back(frame.toWing(gp_Pnt(x[corner & 1], y[(corner >> 1) & 1], z[(corner >> 2) & 1])));
  return corners;
}

/// The lines across the wing through the points of a cell's outline (wing frame, unit, towards
/// the upper skin), so that each side of the prism they sweep lies on its own surface, as the
/// reference library bounds its cells: a border of etas or a chordwise border of xsi values on
/// the plane through its chord points along the component segment's one cell direction
/// (StructureFrame::cellDirection), a border on a rib on the rib's plane, a chordwise border on
/// a spar on the spar's web (its line at each of the spar's corners the web's up direction
/// there). Where two sides meet, the line is where their surfaces meet. On a cell of etas and
/// xsi values every line runs along the cell direction. `outerFront` indexes the outer border's
/// first corner in the loop.
std::vector<gp_Vec> sideLines(const std::vector<gp_Pnt>& loop, const std::vector<double>& etas, std::size_t outerFront,
                              const CellCorners& corners, const StructureFrame& frame) {
  const gp_Vec across = frame.cellDirection();
  const std::size_t count = loop.size(), last = count - 1;
  const bool leadingSpar = corners.onSpar(true), trailingSpar = corners.onSpar(false);
  const auto upright = [&](std::size_t k) { return frame.uprightAtSparPosition(etas[k]); };
  // The normal of the surface of the side from point k to point k + 1, at point `at` (one of
  // its ends).
  const auto sideNormal = [&](std::size_t k, std::size_t at) {
    const std::size_t next = (k + 1) % count;
    const gp_Vec along(loop[k], loop[next]);
    const bool leadingSide = k < outerFront;
    const bool trailingSide = k > outerFront && k < last;
    if (k == outerFront || k == last) {
      if (const std::optional<gp_Vec> rib = corners.ribNormal(k == last)) return *rib;
    } else if ((leadingSide && leadingSpar) || (trailingSide && trailingSpar)) {
      return along.Crossed(upright(at));
    }
    return along.Crossed(across);
  };
  std::vector<gp_Vec> lines;
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t before = (k + count - 1) % count;
    const bool sparKink = (k > 0 && k < outerFront && leadingSpar) || (k > outerFront + 1 && k < last && trailingSpar);
    gp_Vec line;
    if (sparKink) {
      line = upright(k);
    } else {
      const gp_Vec first = sideNormal(before, k), second = sideNormal(k, k);
      line = first.Crossed(second);
      if (line.Magnitude() < 1e-9 * first.Magnitude() * second.Magnitude()) line = across;  // sides in one plane
    }
    line.Normalize();
    if (line.Dot(across) < 0.0) line.Reverse();
    lines.push_back(line);
  }
  return lines;
}

}  // namespace

NamedShape cellSkin(const Configuration& configuration, const StructureServices& services, const WingCell& cell) {
  if (boundedByContourCoordinates(cell)) {
    if (!cell.deviceUid.empty())
      throw Error(ErrorCode::NotImplemented, "a control device's cell bounded by contour coordinates is not built", {},
                  cell.xpath);
    return contourCellSkin(configuration, services.wing, cell);
  }
  const StructureFrame frame(configuration, services, cell.componentSegmentUid, cell.wingUid, cell.deviceUid);
  const CellCorners corners(configuration, cell, frame);
  // The outline: the four corners, following a spar's kinks between them where a spar gives
  // the leading or trailing edge.
  const gp_Pnt innerFront = corners.at(true, true), outerFront = corners.at(false, true);
  const gp_Pnt outerBack = corners.at(false, false), innerBack = corners.at(true, false);
  std::vector<gp_Pnt> loop{innerFront};
  for (const gp_Pnt& kink : corners.alongSpar(true, innerFront, outerFront)) loop.push_back(kink);
  const std::size_t outerFrontIndex = loop.size();
  loop.push_back(outerFront);
  loop.push_back(outerBack);
  for (const gp_Pnt& kink : corners.alongSpar(false, outerBack, innerBack)) loop.push_back(kink);
  loop.push_back(innerBack);
  // Through each point of the outline a line across the wing (sideLines); these lines sweep a
  // prism reaching across the wing.
  std::vector<double> etas;
  for (const gp_Pnt& point : loop) etas.push_back(frame.etaOf(point));
  const TopoDS_Shape skin = frame.skin(cell.upper);
  if (!frame.inDevice()) {
    const std::vector<gp_Pnt> skinCorners = boxCorners(skin, frame);
    // The edges first: the ends then move the corners along the moved chordwise sides. A border
    // at the chord's end is the wing's edge where its corners lie on the skin: the chord's ends
    // are the skin's edge on a wing lofted through its airfoils, not on a guided wing whose
    // leading edge bulges ahead of them, nor at a blunt trailing edge.
    const auto onSkinEdge = [&](bool leadingEdge) {
      if (!corners.atChordEnd(leadingEdge)) return false;
      const std::size_t inner = leadingEdge ? 0 : loop.size() - 1;
      const std::size_t outer = leadingEdge ? outerFrontIndex : outerFrontIndex + 1;
      return onSkin(frame.toGlobal(loop[inner]), skin, geometry::kTraceTolerance * frame.reach()) &&
             onSkin(frame.toGlobal(loop[outer]), skin, geometry::kTraceTolerance * frame.reach());
    };
    beyondWingEdges(loop, outerFrontIndex, onSkinEdge(true), onSkinEdge(false), skinCorners);
    beyondSkinEnds(loop, etas, outerFrontIndex, skinCorners);
  }
  const std::vector<gp_Vec> lines = sideLines(loop, etas, outerFrontIndex, corners, frame);
  const double reach = frame.reach();
  auto level = [&](double side) {
    BRepBuilderAPI_MakePolygon polygon;
    for (std::size_t k = 0; k < loop.size(); ++k)
      polygon.Add(frame.toGlobal(loop[k].Translated(side * reach * lines[k])));
    polygon.Close();
    return polygon.Wire();
  };
  const geometry::RuledSections prism = geometry::ruledThroughSections({level(-1.0), level(1.0)});
  if (prism.solid.IsNull()) throw Error(ErrorCode::InvalidModel, "the cell's corners enclose nothing", {}, cell.xpath);

  // The skin split along where the prism's sides meet it (no surfaces intersected), or, where
  // that does not apply, cut by the prism in a Boolean common.
  geometry::RuledLoop ruled;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    ruled.points.push_back(frame.toGlobal(loop[k]));
    ruled.directions.push_back(frame.toGlobal(lines[k]));
  }
  const double tolerance = geometry::kTraceTolerance * reach;
  // Inside the prism: in closed form from its sides, or by OCCT's classification where the
  // closed form cannot tell.
  const geometry::RuledPrism sides(ruled.points, ruled.directions, reach);
  std::optional<BRepClass3d_SolidClassifier> inPrism;  // loaded only when first needed
  const auto keep = [&](const gp_Pnt& point) {
    if (const std::optional<bool> inside = sides.contains(point)) return *inside;
    if (!inPrism) inPrism.emplace(prism.solid);
    inPrism->Perform(point, tolerance);
    return inPrism->State() == TopAbs_IN;
  };
  std::optional<std::vector<TopoDS_Face>> inside = frame.inDevice()
                                                       ? fromDeviceFaces(frame, cell.upper, ruled, keep, tolerance)
                                                       : geometry::skinPiecesWhere(skin, ruled, keep, tolerance);
  if (!inside) inside = cutByPrism(skin, prism.solid, cell.xpath);
  // A wing that folds back over itself (a joined or box wing) can bring skin of other segments
  // into the prism: only pieces within the cell's span count.
  const double low = *std::min_element(etas.begin(), etas.end()), high = *std::max_element(etas.begin(), etas.end());
  std::vector<TopoDS_Face> withinSpan;
  for (const TopoDS_Face& face : *inside) {
    // Where a piece lies: the middle of its corners (integrating its centre of mass cost a
    // third of a large cell's time).
    gp_XYZ sum(0, 0, 0);
    int count = 0;
    for (TopExp_Explorer vertex(face, TopAbs_VERTEX); vertex.More(); vertex.Next(), ++count)
      sum += BRep_Tool::Pnt(TopoDS::Vertex(vertex.Current())).XYZ();
    if (count == 0) continue;
    const double eta = frame.etaOf(frame.toWing(gp_Pnt(sum / count)));
    if (eta > low - 1e-6 && eta < high + 1e-6) withinSpan.push_back(face);
  }
  NamedFaces patch;
  patch.add(cell.uid + "/skin", withinSpan);
  if (patch.empty()) throw Error(ErrorCode::InvalidModel, "the cell covers no skin", {}, cell.xpath);
  return patch.shape();
}

}  // namespace airshape::structure
