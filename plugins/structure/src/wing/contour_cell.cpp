#include "contour_cell.h"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Surface.hxx>
#include <Precision.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/skin_parameters.h"
#include "airshape/model/placement.h"
#include "named_faces.h"

namespace airshape::structure {

namespace {

using Surface = wing::WingServices::Surface;

/// A range of contour coordinates, in [0, 1].
struct Range {
  double from = 0.0, to = 1.0;
};

/// One face of the skin and where its parameters run: `leadingEdgeAtUMin` says which end of
/// its u range is the leading edge, `innerAtVMin` which end of its v range is the inner end.
struct SkinFace {
  TopoDS_Face face;
  double uMin = 0, uMax = 0, vMin = 0, vMax = 0;
  bool leadingEdgeAtUMin = true, innerAtVMin = true;
  Range span;  ///< the spanwise contour coordinates it covers
};

/// The parameter in [low, high] at contour coordinate `share` in [0, 1] counted from `low`
/// (or from `high` when `fromLow` is false).
double parameterAt(double share, double low, double high, bool fromLow) {
  return fromLow ? low + share * (high - low) : high - share * (high - low);
}

gp_Pnt pointOf(const TopoDS_Face& face, double u, double v) { return BRep_Tool::Surface(face)->Value(u, v); }

/// The skin faces in spanwise order with their spanwise shares and parameter directions.
std::vector<SkinFace> skinFaces(const Configuration& configuration, const wing::WingServices& wing,
                                const WingCell& cell) {
  const TopoDS_Shape skin =
      wing.componentSegmentSkin(configuration, cell.componentSegmentUid, cell.upper ? Surface::Upper : Surface::Lower);
  const TopoDS_Shape otherSkin =
      wing.componentSegmentSkin(configuration, cell.componentSegmentUid, cell.upper ? Surface::Lower : Surface::Upper);
  const std::vector<std::string> segments = wing.componentSegmentSegmentUids(configuration, cell.componentSegmentUid);
  std::vector<SkinFace> faces;
  for (TopExp_Explorer it(skin, TopAbs_FACE); it.More(); it.Next()) {
    SkinFace face;
    face.face = TopoDS::Face(it.Current());
    BRepTools::UVBounds(face.face, face.uMin, face.uMax, face.vMin, face.vMax);
    faces.push_back(face);
  }
  if (faces.size() != segments.size() || skin.IsSame(otherSkin))
    throw Error(ErrorCode::NotImplemented,
                "contour coordinates need one upper and one lower skin face per wing segment; guide curves make "
                "other skins",
                {}, cell.xpath);

  // The reference's loft takes the spanwise parameters of both skins from the lower sides (the
  // first edge of its airfoil wires), so that the skins meet along the leading edge.
  const wing::WingServices::AirfoilSides lowerSides =
      wing.airfoilSides(configuration, cell.componentSegmentUid, Surface::Lower);
  const std::vector<double> parameters = geometry::skinParameters(lowerSides.sides);
  // The skin parameter at the inner (offset 0) or outer (offset 1) end of a segment.
  auto parameterAtInnerEnd = [&](const std::string& segmentUid, int offset) {
    const auto at = std::find(lowerSides.segmentUids.begin(), lowerSides.segmentUids.end(), segmentUid);
    return parameters[static_cast<std::size_t>(at - lowerSides.segmentUids.begin() + offset)];
  };
  const double first = parameterAtInnerEnd(segments.front(), 0), last = parameterAtInnerEnd(segments.back(), 1);
  for (std::size_t k = 0; k < faces.size(); ++k) {
    SkinFace& face = faces[k];
    const double uMid = 0.5 * (face.uMin + face.uMax), vMid = 0.5 * (face.vMin + face.vMax);
    const gp_Pnt leadingEdge =
        wing.pointRelativeTo(configuration, cell.componentSegmentUid, segments[k], 0.5, 0.0, Surface::Chord);
    face.leadingEdgeAtUMin = pointOf(face.face, face.uMin, vMid).SquareDistance(leadingEdge) <
                             pointOf(face.face, face.uMax, vMid).SquareDistance(leadingEdge);
    const gp_Pnt innerEnd =
        wing.pointRelativeTo(configuration, cell.componentSegmentUid, segments[k], 0.0, 0.5, Surface::Chord);
    face.innerAtVMin = pointOf(face.face, uMid, face.vMin).SquareDistance(innerEnd) <
                       pointOf(face.face, uMid, face.vMax).SquareDistance(innerEnd);
    face.span = {(parameterAtInnerEnd(segments[k], 0) - first) / (last - first),
                 (parameterAtInnerEnd(segments[k], 1) - first) / (last - first)};
  }
  faces.back().span.to = 1.0;
  return faces;
}

/// A spanwise border closer than this share of a face's span to the face's end is taken at
/// that end, so that no sliver faces arise (as the reference library does).
constexpr double kSliver = 1e-2;

/// The part of a skin face inside the spanwise range `span` and the chordwise range `chord`,
/// or a null face when the face lies outside the span range.
TopoDS_Face trimmed(const SkinFace& face, const Range& span, const Range& chord) {
  if (std::min(span.to, face.span.to) - std::max(span.from, face.span.from) <= Precision::PConfusion()) return {};
  const double width = face.span.to - face.span.from;
  double from = std::max(0.0, (span.from - face.span.from) / width),
         to = std::min(1.0, (span.to - face.span.from) / width);
  if (from < kSliver) from = 0.0;
  if (to > 1.0 - kSliver) to = 1.0;
  const double v1 = parameterAt(from, face.vMin, face.vMax, face.innerAtVMin);
  const double v2 = parameterAt(to, face.vMin, face.vMax, face.innerAtVMin);
  const double u1 = parameterAt(chord.from, face.uMin, face.uMax, face.leadingEdgeAtUMin);
  const double u2 = parameterAt(chord.to, face.uMin, face.uMax, face.leadingEdgeAtUMin);
  BRepBuilderAPI_MakeFace make(BRep_Tool::Surface(face.face), std::min(u1, u2), std::max(u1, u2), std::min(v1, v2),
                               std::max(v1, v2), Precision::Confusion());
  if (!make.IsDone()) return {};
  TopoDS_Face patch = make.Face();
  patch.Orientation(face.face.Orientation());
  return patch;
}

/// A border's contour coordinate, which must lie in [0, 1].
double contourCoordinate(const std::optional<double>& value, const std::string& where) {
  return model::fraction(*value, where + "/contourCoordinate");
}

/// The span coordinate of a component segment eta: in the face of the wing segment that holds
/// it, the share of that segment's eta (exact at the sections between segments, where the
/// faces meet).
double spanAtEta(const Configuration& configuration, const wing::WingServices& wing, const WingCell& cell,
                 const std::vector<SkinFace>& faces, double eta, const std::string& where) {
  const std::vector<std::string> segments = wing.componentSegmentSegmentUids(configuration, cell.componentSegmentUid);
  const auto csEta = [&](std::size_t k, double segmentEta) {
    return wing.componentSegmentEta(configuration, cell.componentSegmentUid, segments[k], segmentEta);
  };
  for (std::size_t k = 0; k < segments.size() && k < faces.size(); ++k) {
    if (eta < csEta(k, 0.0) - 1e-12 || eta > csEta(k, 1.0) + 1e-12) continue;
    double low = 0.0, high = 1.0;
    for (int step = 0; step < 60; ++step) {
      const double middle = 0.5 * (low + high);
      (csEta(k, middle) < eta ? low : high) = middle;
    }
    const double share = 0.5 * (low + high);
    return faces[k].span.from + share * (faces[k].span.to - faces[k].span.from);
  }
  throw Error(ErrorCode::InvalidModel, "eta " + std::to_string(eta) + " lies outside the component segment", {}, where);
}

/// A spanwise border's span coordinate: its contour coordinate, or that of its one eta.
double spanwiseCoordinate(const Configuration& configuration, const wing::WingServices& wing, const WingCell& cell,
                          const std::vector<SkinFace>& faces, const schema::CellPositioningSpanwiseType& border,
                          const std::string& where) {
  if (border.contourCoordinate) return contourCoordinate(border.contourCoordinate, where);
  const double given = model::fraction(border.eta1->eta, where + "/eta1/eta");
  double eta = 0.0;
  try {
    eta = wing.componentSegmentEta(configuration, cell.componentSegmentUid, border.eta1->referenceUID, given);
  } catch (const Error& error) {
    throw Error(error.code(), error.message(), {}, where + "/eta1");
  }
  return spanAtEta(configuration, wing, cell, faces, eta, where + "/eta1");
}

}  // namespace

bool boundedByContourCoordinates(const WingCell& cell) {
  const auto& node = *cell.node;
  const bool chordwise = node.positioningLeadingEdge && node.positioningLeadingEdge->contourCoordinate &&
                         node.positioningTrailingEdge && node.positioningTrailingEdge->contourCoordinate;
  const int count = (node.positioningInnerBorder && node.positioningInnerBorder->contourCoordinate) +
                    (node.positioningOuterBorder && node.positioningOuterBorder->contourCoordinate) +
                    (node.positioningLeadingEdge && node.positioningLeadingEdge->contourCoordinate) +
                    (node.positioningTrailingEdge && node.positioningTrailingEdge->contourCoordinate);
  if (count == 0) return false;
  if (count == 4) return true;
  // Chordwise contour coordinates between spanwise borders at one eta each: the span coordinate
  // of that eta bounds the cell (spanwiseRange).
  const auto atOneEta = [](const auto& border) {
    return border && !border->contourCoordinate && border->eta1 && border->eta2 &&
           border->eta1->eta == border->eta2->eta && border->eta1->referenceUID == border->eta2->referenceUID;
  };
  const auto spanwiseUsable = [&](const auto& border) {
    return (border && border->contourCoordinate) || atOneEta(border);
  };
  if (chordwise && spanwiseUsable(node.positioningInnerBorder) && spanwiseUsable(node.positioningOuterBorder))
    return true;
  throw Error(ErrorCode::InvalidModel,
              "a cell bounded by contour coordinates needs them on all four borders, or on its leading and trailing "
              "edge with spanwise borders at one eta each; this one has " +
                  std::to_string(count),
              {}, cell.xpath);
}

NamedShape contourCellSkin(const Configuration& configuration, const wing::WingServices& wing, const WingCell& cell) {
  const auto& node = *cell.node;
  const std::vector<SkinFace> faces = skinFaces(configuration, wing, cell);
  const Range span{spanwiseCoordinate(configuration, wing, cell, faces, *node.positioningInnerBorder,
                                      cell.xpath + "/positioningInnerBorder"),
                   spanwiseCoordinate(configuration, wing, cell, faces, *node.positioningOuterBorder,
                                      cell.xpath + "/positioningOuterBorder")};
  const Range chord{
      contourCoordinate(node.positioningLeadingEdge->contourCoordinate, cell.xpath + "/positioningLeadingEdge"),
      contourCoordinate(node.positioningTrailingEdge->contourCoordinate, cell.xpath + "/positioningTrailingEdge")};
  if (span.to <= span.from || chord.to <= chord.from)
    throw Error(ErrorCode::InvalidModel,
                "the cell's outer border must lie outboard of its inner border and its trailing edge aft of its "
                "leading edge",
                {}, cell.xpath);
  std::vector<TopoDS_Face> patches;
  for (const SkinFace& face : faces)
    if (const TopoDS_Face patch = trimmed(face, span, chord); !patch.IsNull()) patches.push_back(patch);
  NamedFaces patch;
  patch.add(cell.uid + "/skin", patches);
  if (patch.empty()) throw Error(ErrorCode::InvalidModel, "the cell covers no skin", {}, cell.xpath);
  return patch.shape();
}

}  // namespace airshape::structure
