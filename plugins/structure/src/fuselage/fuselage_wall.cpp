#include "fuselage_wall.h"

#include <optional>
#include <vector>

#include <BRepAlgoAPI_Splitter.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GeomLib_IsPlanarSurface.hxx>
#include <Geom_Plane.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Lin.hxx>
#include <gp_Pln.hxx>

#include "airshape/configuration.h"
#include "airshape/construction_guard.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/faces_inside.h"
#include "airshape/geometry/ruled_side.h"
#include "compounds.h"
#include "fuselage_frame.h"
#include "fuselage_structure_list.h"
#include "named_faces.h"

namespace airshape::structure {

namespace {

/// A wall position placed: its base point (global) and the element it lies on, if any.
struct BasePoint {
  gp_Pnt point;
  TopoDS_Shape element;  ///< null where x is given
  std::string xpath;
};

/// A fuselage section named by `sectionUID` (as older files write fuselageSectionUID), read
/// with a warning; none when the position has no such element.
std::optional<std::string> olderSectionUid(const Configuration& configuration,
                                           const schema::WallPositionType& position) {
  try {
    const std::string uid = configuration.value(position.xpath + "/sectionUID");
    configuration.warnAboutGeometry(
        {Problem::Severity::Warning, position.xpath + "/sectionUID", "sectionUID read as fuselageSectionUID"});
    return uid;
  } catch (const Error&) {
    return std::nullopt;
  }
}

BasePoint basePointOf(const Configuration& configuration, const FuselageFrame& fuselage,
                      const schema::WallPositionType& position) {
  BasePoint base{fuselage.toGlobal(gp_Pnt(position.x.value_or(0.0), position.y, position.z)), {}, position.xpath};
  if (position.x) return base;
  std::string where = position.xpath;
  // The shape of the element of this uID, or Error naming where the uID is given.
  auto shapeOf = [&](const std::string& uid) {
    try {
      return configuration.shapes().namedShapeOf(configuration, uid).shape;
    } catch (const Error& error) {
      throw Error(error.code(), error.message(), {}, where);
    }
  };
  if (position.bulkheadUID) {
    where += "/bulkheadUID";
    base.element = shapeOf(*position.bulkheadUID);
  } else if (position.wallSegmentUID) {
    where += "/wallSegmentUID";
    base.element = shapeOf(*position.wallSegmentUID);
  } else if (position.fuselageSectionUID) {
    where += "/fuselageSectionUID";
    base.element = fuselage.sectionFace(*position.fuselageSectionUID, where);
  } else if (const std::optional<std::string> section = olderSectionUid(configuration, position)) {
    where += "/sectionUID";
    base.element = fuselage.sectionFace(*section, where);
  } else {
    throw Error(ErrorCode::InvalidModel, "the wall position gives neither x nor an element to place it on", {},
                position.xpath);
  }
  base.point = fuselage.alongXOnto(base.element, base.point, where);
  return base;
}

/// The plane of the element a base point lies on, through the base point.
gp_Pln planeOf(const BasePoint& base) {
  for (TopExp_Explorer face(base.element, TopAbs_FACE); face.More(); face.Next()) {
    GeomLib_IsPlanarSurface planar(BRep_Tool::Surface(TopoDS::Face(face.Current())));
    if (planar.IsPlanar()) return gp_Pln(base.point, planar.Plan().Axis().Direction());
    break;
  }
  throw Error(ErrorCode::InvalidModel, "a flush connection needs a plane element at the wall position", {}, base.xpath);
}

/// Where the line through `point` along `direction` meets `plane`.
gp_Pnt ontoPlane(const gp_Pln& plane, const gp_Pnt& point, const gp_Vec& direction, const std::string& where) {
  const double along = gp_Vec(plane.Axis().Direction()).Dot(direction);
  if (std::abs(along) < 1e-12 * direction.Magnitude())
    throw Error(ErrorCode::InvalidModel, "the wall runs parallel to the element it is to be flush with", {}, where);
  const double t = gp_Vec(point, plane.Location()).Dot(gp_Vec(plane.Axis().Direction())) / along;
  return point.Translated(t * direction);
}

/// The face through four corners: plane where they are (a strip of a wall always is unless a
/// flush connection turns an edge), else ruled between the edges lower–upper and next ones.
TopoDS_Face quad(const gp_Pnt& lower, const gp_Pnt& lowerNext, const gp_Pnt& upper, const gp_Pnt& upperNext) {
  BRepBuilderAPI_MakePolygon polygon(lower, lowerNext, upperNext, upper, true);
  BRepBuilderAPI_MakeFace plane(polygon.Wire(), true);
  if (plane.IsDone()) return plane.Face();
  return geometry::ruledFace(geometry::straightLine(lower, upper), geometry::straightLine(lowerNext, upperNext));
}

/// A strip of a wall by its corners: its lines run from `lower` to `upper` at one base point and
/// from `lowerNext` to `upperNext` at the next; the base points lie on them at the share
/// `baseShare` of the way up (0, or a half for a wall extruded both ways).
struct StripCorners {
  gp_Pnt lower, lowerNext, upper, upperNext;
  double baseShare = 0.0;
};

/// A wall before trimming: its base points, its strips (as faces and by their corners) and the
/// faces that cut walls it bounds (its strips, the first and the last stretched along the wall
/// beyond its ends).
struct WallLayout {
  std::vector<gp_Pnt> basePoints;
  std::vector<TopoDS_Face> strips, cutters;
  std::vector<StripCorners> corners;
};

WallLayout layoutOf(const Configuration& configuration, const FuselageElement<schema::WallSegmentType>& wall) {
  const schema::WallSegmentType& node = *wall.node;
  const FuselageFrame fuselage =
      FuselageFrame::ofHost(configuration, wall.hostUid, wall.fuselage, wall.vesselPlacement);
  const std::string positionsPath = node.xpath + "/wallPositionUIDs";
  std::vector<BasePoint> bases;
  if (node.wallPositionUIDs)
    for (const std::string& uid : node.wallPositionUIDs->wallPositionUID)
      bases.push_back(basePointOf(configuration, fuselage, wallPositionNamed(*wall.structure, uid, positionsPath)));
  if (bases.size() < 2)
    throw Error(ErrorCode::InvalidModel, "a wall needs at least two wall positions", {}, positionsPath);

  const double phi = node.phi * M_PI / 180.0;
  const gp_Vec up(fuselage.toGlobal(gp_Dir(0.0, -std::sin(phi), std::cos(phi))));
  const double reach = fuselage.reach();
  const double below = node.doubleSidedExtrusion.value_or(false) ? -reach : 0.0;
  std::vector<gp_Pnt> lower, upper;
  for (const BasePoint& base : bases) {
    lower.push_back(base.point.Translated(below * up));
    upper.push_back(base.point.Translated(reach * up));
  }
  auto flush = [&](std::size_t end, std::size_t neighbour) {
    const gp_Vec along(bases[neighbour].point, bases[end].point);
    const gp_Pln plane = planeOf(bases[end]);
    lower[end] = ontoPlane(plane, lower[end], along, node.xpath);
    upper[end] = ontoPlane(plane, upper[end], along, node.xpath);
  };
  if (node.flushConnectionStart.value_or(false)) flush(0, 1);
  if (node.flushConnectionEnd.value_or(false)) flush(bases.size() - 1, bases.size() - 2);

  WallLayout layout;
  for (const BasePoint& base : bases) layout.basePoints.push_back(base.point);
  const std::size_t last = bases.size() - 1;
  for (std::size_t k = 0; k < last; ++k) {
    layout.strips.push_back(quad(lower[k], lower[k + 1], upper[k], upper[k + 1]));
    layout.corners.push_back({lower[k], lower[k + 1], upper[k], upper[k + 1], below < 0.0 ? 0.5 : 0.0});
    const gp_Vec stretch = gp_Vec(bases[k].point, bases[k + 1].point).Normalized() * reach;
    const gp_Vec before = k == 0 ? -stretch : gp_Vec(0, 0, 0), after = k + 1 == last ? stretch : gp_Vec(0, 0, 0);
    layout.cutters.push_back(quad(lower[k].Translated(before), lower[k + 1].Translated(after),
                                  upper[k].Translated(before), upper[k + 1].Translated(after)));
  }
  return layout;
}

/// How closely a strip's part follows the fuselage's skin, as a share of the fuselage's size:
/// looser than the wings' traces (structure's kTraceTolerance), because the cut-back at bounding
/// walls (OCCT's splitter) slows with the poles of the curves it meets.
constexpr double kStripTolerance = 1e-7;

/// A strip's part inside the fuselage made from where its lines meet the skin, without a Boolean
/// operation: rays from the base points' line up to the skin (and down, for a wall extruded both
/// ways), each meeting it once. The part of a plane strip (`strip` is its face) is a face of its
/// plane. Nothing where rays miss the skin (leaving through an end cap) or meet it more than
/// once; the caller then takes the Boolean common.
std::optional<std::vector<TopoDS_Face>> stripInside(const TopoDS_Face& strip, const StripCorners& corners,
                                                    const TopoDS_Shape& skin, double tolerance) {
  const geometry::RuledSide side =
      geometry::ruledSide(corners.lower, corners.upper, corners.lowerNext, corners.upperNext);
  using Bound = geometry::SideBound;
  const Bound up{Bound::Kind::Skin, &skin, corners.baseShare, +1};
  const Bound down =
      corners.baseShare > 0.0 ? Bound{Bound::Kind::Skin, &skin, corners.baseShare, -1} : Bound{Bound::Kind::Start};
  const std::optional<TopoDS_Face> part = geometry::sidePart(side, down, up, tolerance);
  if (!part || part->IsNull()) return std::nullopt;
  const Handle(Geom_Plane) plane = Handle(Geom_Plane)::DownCast(BRep_Tool::Surface(strip));
  if (plane.IsNull()) return std::vector<TopoDS_Face>{*part};  // a strip a flush connection turns
  BRepBuilderAPI_MakeFace onPlane(plane->Pln(), BRepTools::OuterWire(*part), true);
  if (!onPlane.IsDone()) return std::nullopt;
  return std::vector<TopoDS_Face>{onPlane.Face()};
}

bool touches(const TopoDS_Face& face, const gp_Pnt& point) {
  BRepExtrema_DistShapeShape distance(BRepBuilderAPI_MakeVertex(point).Vertex(), face);
  return distance.IsDone() && distance.Value() < 1e-6;
}

/// The pieces of `faces` split by `cutters` that hold one of the base points.
std::vector<TopoDS_Face> cutBack(const std::vector<TopoDS_Face>& faces, const std::vector<TopoDS_Face>& cutters,
                                 const std::vector<gp_Pnt>& basePoints, const std::string& where) {
  TopTools_ListOfShape arguments, tools;
  for (const TopoDS_Face& face : faces) arguments.Append(face);
  for (const TopoDS_Face& cutter : cutters) tools.Append(cutter);
  BRepAlgoAPI_Splitter splitter;
  splitter.SetArguments(arguments);
  splitter.SetTools(tools);
  splitter.SetRunParallel(true);
  splitter.Build();
  if (!splitter.IsDone() || splitter.HasErrors())
    throw Error(ErrorCode::InvalidModel, "the wall cannot be cut at its bounding element", {}, where);
  std::vector<TopoDS_Face> kept;
  for (TopExp_Explorer it(splitter.Shape(), TopAbs_FACE); it.More(); it.Next()) {
    const TopoDS_Face piece = TopoDS::Face(it.Current());
    for (const gp_Pnt& point : basePoints)
      if (touches(piece, point)) {
        kept.push_back(piece);
        break;
      }
  }
  return kept;
}

/// What bounds a wall: another wall's surface carried beyond its ends, or the faces of any other
/// component with a shape (a generic geometry component, a floor where a plugin builds one).
std::vector<TopoDS_Face> boundingFaces(const Configuration& configuration, const tank::TankServices* tanks,
                                       const std::string& bounding, const std::string& where) {
  std::optional<FuselageElement<schema::WallSegmentType>> wall;
  try {
    wall = wallSegmentNamed(configuration, bounding, tanks);
  } catch (const Error&) {
    // not a wall: another component
  }
  if (wall) return layoutOf(configuration, *wall).cutters;
  if (configuration.components().find(bounding) < 0)
    throw Error(ErrorCode::InvalidModel, "bounding element '" + bounding + "' names no component", {}, where);
  std::vector<TopoDS_Face> faces;
  try {
    const TopoDS_Shape& shape = configuration.shapes().shapeOf(configuration, bounding);
    for (TopExp_Explorer face(shape, TopAbs_FACE); face.More(); face.Next())
      faces.push_back(TopoDS::Face(face.Current()));
  } catch (const Error& error) {
    throw Error(error.code(), "bounding element '" + bounding + "': " + error.message(), {}, where);
  }
  if (faces.empty())
    throw Error(ErrorCode::InvalidModel, "bounding element '" + bounding + "' has no faces", {}, where);
  return faces;
}

}  // namespace

NamedShape fuselageWall(const Configuration& configuration, const tank::TankServices* tanks, const std::string& uid) {
  const auto wall = wallSegmentNamed(configuration, uid, tanks);
  // A wall placed on a wall that is placed on it again would never finish.
  const ConstructionGuard guard("wall", uid, "wall '" + uid + "' depends on itself through its wall positions",
                                wall.node->xpath);
  const WallLayout layout = layoutOf(configuration, wall);
  const FuselageFrame fuselage =
      FuselageFrame::ofHost(configuration, wall.hostUid, wall.fuselage, wall.vesselPlacement);
  const TopoDS_Compound skin = compoundOf(fuselage.skinFaces());
  const double tolerance = kStripTolerance * fuselage.reach();
  std::vector<TopoDS_Face> faces;
  try {
    const auto solid = [&]() -> const TopoDS_Shape& { return fuselage.solid(); };
    const auto direct = [&](std::size_t k) {
      return stripInside(layout.strips[k], layout.corners[k], skin, tolerance);
    };
    for (const std::vector<TopoDS_Face>& parts : geometry::facesInsideEach(layout.strips, solid, direct))
      faces.insert(faces.end(), parts.begin(), parts.end());
  } catch (const Error&) {
    throw Error(ErrorCode::InvalidModel, "the wall cannot be cut at the fuselage's skin", {}, wall.node->xpath);
  }
  if (wall.node->boundingElementUIDs) {
    const std::string where = wall.node->xpath + "/boundingElementUIDs";
    for (const std::string& bounding : wall.node->boundingElementUIDs->boundingElementUID)
      faces = cutBack(faces, boundingFaces(configuration, tanks, bounding, where), layout.basePoints, where);
  }
  NamedFaces shape;
  shape.add(uid + "/wall", faces);
  if (shape.empty()) throw Error(ErrorCode::InvalidModel, "the wall lies outside the fuselage", {}, wall.node->xpath);
  return shape.shape();
}

}  // namespace airshape::structure
