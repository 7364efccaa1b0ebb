#include "wing_shape.h"

#include <BRepCheck_Analyzer.hxx>
#include <BRep_Builder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_MapOfShape.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/geometry/loft_piece.h"
#include "airshape/geometry/ruled_loft.h"

namespace airshape::wing {

namespace {

/// The three (or two) curves of a placed airfoil: upper, lower and the blunt trailing edge.
struct PlacedAirfoil {
  Handle(Geom_BSplineCurve) upper, lower, trailingEdge;
};

PlacedAirfoil placedAirfoil(const SegmentEnd& end) {
  PlacedAirfoil airfoil{geometry::transformed(end.profile->upperCurve(), end.transform),
                        geometry::transformed(end.profile->lowerCurve(), end.transform),
                        {}};
  if (end.profile->bluntTrailingEdge())
    airfoil.trailingEdge = geometry::straightLine(airfoil.upper->EndPoint(), airfoil.lower->EndPoint());
  return airfoil;
}

/// The airfoil as one loop of curves: upper side (LE -> TE), the blunt trailing edge, and
/// the lower side (TE -> LE as the loop runs it).
std::vector<Handle(Geom_BSplineCurve)> airfoilLoop(const PlacedAirfoil& airfoil) {
  if (airfoil.trailingEdge.IsNull()) return {airfoil.upper, airfoil.lower};
  return {airfoil.upper, airfoil.trailingEdge, airfoil.lower};
}

/// An unguided segment: ruled faces between its airfoils' upper sides, lower sides and blunt
/// trailing edges (their parameters are xsi and eta), closed by planar caps: the ruled loft
/// through the two airfoils with shared edges (geometry::ruledLoft), no sewing.
SegmentShape segmentShape(const WingSegment& segment) {
  const PlacedAirfoil inner = placedAirfoil(segment.inner), outer = placedAirfoil(segment.outer);
  if (inner.trailingEdge.IsNull() != outer.trailingEdge.IsNull())
    throw Error(ErrorCode::InvalidModel, "joins a blunt and a sharp trailing edge", {}, segment.xpath);
  SegmentShape shape;
  try {
    const geometry::RuledLoft loft = geometry::ruledLoft(airfoilLoop(inner), airfoilLoop(outer));
    shape.upper = loft.sides.front();
    shape.lower = loft.sides.back();
    if (!inner.trailingEdge.IsNull()) shape.trailingEdge = loft.sides[1];
    shape.innerCap = loft.firstCap;
    shape.outerCap = loft.lastCap;
    shape.solid = loft.solid;
  } catch (const Error& error) {
    throw Error(error.code(), error.message(), {}, segment.xpath);
  }
  return shape;
}

/// A segment of a wing with guide curves: its stretch of the guided skin (one face for
/// both sides), the blunt trailing edge between the skin's ends, and the caps.
/// A guided segment: its skin split at the leading-edge guide into a lower and an upper
/// face (one face, in `upper`, when no guide runs along the leading edge), the strip
/// between blunt trailing edges, and planar caps.
SegmentShape guidedSegmentShape(const WingGeometry& geometry, std::size_t segment) {
  const GuidedWingSkin& skin = *geometry.guidedSkin();
  const Handle(Geom_BSplineSurface)& surface = skin.segmentSurface(segment);
  double u0, u1, v0, v1;
  surface->Bounds(u0, u1, v0, v1);
  const double split = skin.leadingEdgeU();
  const bool closed = !skin.bluntTrailingEdge();
  SegmentShape shape;
  if (split > u0) shape.lower = geometry::surfacePartFace(surface, u0, split, v0, v1);
  shape.upper = geometry::surfacePartFace(surface, split > u0 ? split : u0, u1, v0, v1);
  if (!closed) shape.trailingEdge = geometry::loftClosingFace(surface, v0, v1);
  shape.sewnOnRequest = true;
  try {
    shape.innerCap = geometry::loftCap(surface, v0, closed);
    shape.outerCap = geometry::loftCap(surface, v1, closed);
  } catch (const Error& error) {
    throw Error(error.code(), error.message(), {}, geometry.segments()[segment].xpath);
  }
  return shape;
}

}  // namespace

std::shared_ptr<const WingShape> WingShape::of(const Configuration& configuration, const schema::WingType& wing) {
  return configuration.cache().obtain<WingShape>("wing-shape:" + wing.uID, [&] {
    auto shape = std::make_shared<WingShape>();
    const auto geometry = WingGeometry::of(configuration, wing);
    shape->wingUid_ = wing.uID;
    shape->wingPath_ = wing.xpath;
    shape->segmentDefinitions_ = geometry->segments();
    for (std::size_t k = 0; k < geometry->segments().size(); ++k)
      shape->segments_.push_back(geometry->guidedSkin() ? guidedSegmentShape(*geometry, k)
                                                        : segmentShape(geometry->segments()[k]));
    shape->sewnSolids_.resize(shape->segments_.size());
    return std::shared_ptr<const WingShape>(shape);
  });
}

const TopoDS_Shape& WingShape::segmentSolid(std::size_t segment) const {
  const SegmentShape& shape = segments_[segment];
  if (!shape.sewnOnRequest) return shape.solid;
  const std::lock_guard<std::mutex> lock(sewingSegments_);
  TopoDS_Shape& sewn = sewnSolids_[segment];
  if (sewn.IsNull()) {
    try {
      sewn = geometry::sewnSolid({shape.upper, shape.lower, shape.trailingEdge, shape.innerCap, shape.outerCap});
    } catch (const Error& error) {
      throw Error(error.code(), error.message(), {}, segmentDefinitions_[segment].xpath);
    }
  }
  return sewn;
}

double WingShape::segmentVolume(std::size_t segment) const { return geometry::volumeOf(segmentSolid(segment)); }

double WingShape::segmentSurfaceArea(std::size_t segment) const {
  return geometry::areaOf(segments_[segment].upper) + geometry::areaOf(segments_[segment].lower);
}

double WingShape::volume() const {
  double total = 0.0;
  for (std::size_t k = 0; k < segments_.size(); ++k) total += segmentVolume(k);
  return total;
}

double WingShape::surfaceArea() const {
  if (segments_.empty()) return 0.0;
  double total = geometry::areaOf(segments_.front().innerCap) + geometry::areaOf(segments_.back().outerCap);
  for (std::size_t k = 0; k < segments_.size(); ++k)
    total += segmentSurfaceArea(k) + geometry::areaOf(segments_[k].trailingEdge);
  return total;
}

NamedShape WingShape::solid() const {
  if (segments_.empty()) throw Error(ErrorCode::InvalidModel, "the wing has no segments, so no solid", {}, wingPath_);
  return solidOf(0, segments_.size() - 1);
}

namespace {

/// An unguided segment's own solid (the ruled loft's, whose faces share their edges already)
/// with its faces named: no sewing, and a flat segment (two profiles in one plane) is kept as
/// the loft keeps it.
NamedShape ownSolidOf(const SegmentShape& segment, const std::vector<std::pair<std::string, TopoDS_Face>>& named) {
  NamedShape own{segment.solid, {}};
  for (const auto& face : named)
    if (!face.second.IsNull()) own.faces.push_back(face);
  return own;
}

}  // namespace

NamedShape WingShape::solidOf(std::size_t first, std::size_t last) const {
  const auto capName = [&](std::size_t segment, bool atWingEnd, const char* wingEnd, const char* segmentEnd) {
    return atWingEnd ? wingUid_ + wingEnd : segmentDefinitions_[segment].uid + segmentEnd;
  };
  std::vector<std::pair<std::string, TopoDS_Face>> named = {
      {capName(first, first == 0, "/root", "/inner"), segments_[first].innerCap},
      {capName(last, last + 1 == segments_.size(), "/tip", "/outer"), segments_[last].outerCap}};
  for (std::size_t k = first; k <= last; ++k) {
    const SegmentShape& segment = segments_[k];
    const std::string& uid = segmentDefinitions_[k].uid;
    // A guided skin is one face for both sides.
    named.emplace_back(uid + (segment.lower.IsNull() ? "/skin" : "/upper"), segment.upper);
    named.emplace_back(uid + "/lower", segment.lower);
    named.emplace_back(uid + "/trailingEdge", segment.trailingEdge);
  }
  if (first == last && !segments_[first].sewnOnRequest) return ownSolidOf(segments_[first], named);
  NamedShape solid = sewnNamedSolid(named);
  // A root or tip cap on a profile flattened to a line is a valid face on its own, but a
  // guided skin only approximates that profile, and sewn to it the cap may cross itself or
  // face the wrong way. Such a solid is refused (checked only then: the check is dear).
  for (const auto& [cap, end] : {std::pair(segments_[first].innerCap, &segmentDefinitions_[first]),
                                 std::pair(segments_[last].outerCap, &segmentDefinitions_[last])})
    if (!cap.IsNull() && geometry::enclosesNoArea(cap) && !BRepCheck_Analyzer(solid.shape).IsValid())
      throw geometry::noAreaError(end->xpath);
  return solid;
}

const NamedShape& WingShape::closedSolidOf(std::size_t first, std::size_t last) const {
  {
    const std::lock_guard<std::mutex> lock(keepingSolids_);
    const auto kept = closedSolids_.find({first, last});
    if (kept != closedSolids_.end()) return kept->second;
  }
  NamedShape made = solidOf(first, last);  // built unlocked: another range may be built meanwhile
  const std::lock_guard<std::mutex> lock(keepingSolids_);
  return closedSolids_.emplace(std::make_pair(first, last), std::move(made)).first->second;
}

NamedShape WingShape::componentSegmentShape(std::size_t first, std::size_t last) const {
  const NamedShape& whole = closedSolidOf(first, last);
  // The strips are the faces named after a segment's trailing edge (solidOf's names).
  const std::string strip = "/trailingEdge";
  const auto isStrip = [&](const std::string& name) {
    return name.size() >= strip.size() && name.compare(name.size() - strip.size(), strip.size(), strip) == 0;
  };
  NamedShape open;
  TopTools_MapOfShape strips;
  for (const auto& [name, face] : whole.faces)
    if (isStrip(name))
      strips.Add(face);
    else
      open.faces.emplace_back(name, face);
  // The other faces as the solid holds them (its orientation included), one open shell.
  BRep_Builder builder;
  TopoDS_Shell shell;
  builder.MakeShell(shell);
  for (TopExp_Explorer face(whole.shape, TopAbs_FACE); face.More(); face.Next())
    if (!strips.Contains(face.Current())) builder.Add(shell, face.Current());
  TopoDS_Solid solid;
  builder.MakeSolid(solid);
  builder.Add(solid, shell);
  open.shape = solid;
  return open;
}

}  // namespace airshape::wing
