#include "airshape/geometry/tangent_contact.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <BRepAdaptor_Curve.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <ElSLib.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pln.hxx>

#include "airshape/geometry/bspline_patch.h"
#include "rectangular_patch.h"

namespace airshape::geometry {

namespace {

/// Per knot span: samples for the side test and the first guesses across.
constexpr int kSamplesPerSpan = 4;
/// Per knot span: the points along a line of contact.
constexpr int kStationsPerSpan = 8;
/// Samples along a parameter of few knot spans.
constexpr int kLeastSamples = 32;
/// Samples skipped in the first pass of the side test.
constexpr std::size_t kCoarseStride = 8;
/// Steps to find where a line of contact leaves the face.
constexpr int kBisections = 40;
/// One less the cosine between the normals of touching faces, at most.
constexpr double kLevel = 1e-6;
/// The least bending away from the plane, times the patch's size: a face lying in the plane
/// does not touch it.
constexpr double kLeastBending = 1e-6;
/// Of the plane face's size: an end of a line this close to the face's edge lies on it.
constexpr double kBoundaryBand = 1e-4;
/// In tolerances: how close a section edge lies to both faces where it runs along a contact.
constexpr double kOnBothFaces = 100.0;

/// Parameters through [low, high], `perSpan` in each knot span and at least kLeastSamples.
std::vector<double> sampleParameters(const TColStd_Array1OfReal& knots, double low, double high, int perSpan) {
  const std::vector<double> breaks = knotBreaks(knots, low, high);
  const int pieces = static_cast<int>(breaks.size()) - 1;
  const int perPiece = std::max(perSpan, kLeastSamples / pieces + 1);
  std::vector<double> parameters;
  for (int piece = 0; piece < pieces; ++piece)
    for (int k = 0; k < perPiece; ++k)
      parameters.push_back(breaks[piece] + (breaks[piece + 1] - breaks[piece]) * k / perPiece);
  parameters.push_back(high);
  return parameters;
}

/// A patch seen from a plane: its height above the plane, turned so that the patch lies below
/// (a contact is a highest point, of height 0). Its curves across the stations are the v-curves
/// at u = station where `stationsInU`, else the u-curves.
struct PatchBelowPlane {
  const Patch& patch;
  gp_Pln plane;
  double sign = 1;
  bool stationsInU = true;
  double extent = 1;  // the patch's size

  double height(const gp_Pnt& point) const { return gp_Vec(plane.Location(), point).Dot(up()); }
  double low() const { return stationsInU ? patch.v0 : patch.u0; }
  double high() const { return stationsInU ? patch.v1 : patch.u1; }
  gp_Pnt at(double station, double across) const {
    return stationsInU ? patch.surface->Value(station, across) : patch.surface->Value(across, station);
  }
  gp_Vec up() const { return sign * gp_Vec(plane.Axis().Direction()); }

  /// The patch's point at (station, across), its derivatives along and across, and its second
  /// derivative across.
  struct Local {
    gp_Pnt point;
    gp_Vec along, across, acrossTwice;
  };
  Local localAt(double station, double across) const {
    gp_Pnt point;
    gp_Vec du, dv, duu, dvv, duv;
    if (stationsInU) {
      patch.surface->D2(station, across, point, du, dv, duu, dvv, duv);
      return {point, du, dv, dvv};
    }
    patch.surface->D2(across, station, point, du, dv, duu, dvv, duv);
    return {point, dv, du, duu};
  }

  /// Whether the patch touches the plane at (station, across) rather than ending on it or lying
  /// in it: its normal is the plane's (either way), and it curves away from the plane across.
  bool touchesAt(double station, double across) const {
    const Local local = localAt(station, across);
    const gp_Vec normal = local.along.Crossed(local.across);
    const double size = normal.Magnitude(), speedSquared = local.across.SquareMagnitude();
    if (!(size > 0 && speedSquared > 0) || std::abs(normal.Dot(up())) < (1.0 - kLevel) * size) return false;
    const double bending = -local.acrossTwice.Dot(up()) / speedSquared;  // 1 / radius, away from the plane
    return bending * extent > kLeastBending;
  }
};

/// The highest point of the patch across one station.
struct Summit {
  double station = 0, across = 0, height = -std::numeric_limits<double>::infinity();
  gp_Pnt point;
  bool tangent = false;  // PatchBelowPlane::touchesAt

  bool touches(double tolerance) const { return tangent && std::abs(height) <= tolerance; }
};

/// The highest point across `station`, from the highest of `guesses`, refined by Newton's
/// method on the height's slope while the height curves downwards.
Summit summitAt(const PatchBelowPlane& seen, double station, const std::vector<double>& guesses) {
  Summit best;
  best.station = station;
  for (double across : guesses) {
    const gp_Pnt point = seen.at(station, across);
    const double height = seen.height(point);
    if (height > best.height) best = {station, across, height, point};
  }
  double across = best.across;
  const double span = seen.high() - seen.low();
  for (int iteration = 0; iteration < 30; ++iteration) {
    const PatchBelowPlane::Local local = seen.localAt(station, across);
    const double slope = local.across.Dot(seen.up()), curvature = local.acrossTwice.Dot(seen.up());
    if (!(curvature < 0)) break;
    const double next = std::clamp(across - slope / curvature, seen.low(), seen.high());
    const bool settled = std::abs(next - across) <= 1e-14 * span;
    across = next;
    if (settled) break;
  }
  const gp_Pnt point = seen.at(station, across);
  const double height = seen.height(point);
  if (height > best.height) best = {station, across, height, point};
  best.tangent = seen.touchesAt(best.station, best.across);
  return best;
}

/// A point's parameters on a plane (those of a plane face's curves on it).
gp_Pnt2d planeParameters(const gp_Pln& plane, const gp_Pnt& point) {
  double u = 0, v = 0;
  ElSLib::Parameters(plane, point, u, v);
  return {u, v};
}

/// Whether a point on the face's plane lies inside the face.
bool inFace(const TopoDS_Face& face, const gp_Pln& plane, const gp_Pnt& point, double tolerance) {
  return BRepClass_FaceClassifier(face, planeParameters(plane, point), tolerance).State() == TopAbs_IN;
}

/// The sign that turns the patch below the plane; nothing where its samples lie on both sides
/// (it crosses the plane, which a section finds) or all poles lie below by more than the
/// tolerance (the surface, inside their hull, cannot reach the plane).
std::optional<double> sideBelow(const Patch& patch, const gp_Pln& plane, double tolerance) {
  const gp_Vec normal(plane.Axis().Direction());
  auto signedDistance = [&](const gp_Pnt& point) { return gp_Vec(plane.Location(), point).Dot(normal); };
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  const std::vector<double> us = sampleParameters(patch.surface->UKnots(), patch.u0, patch.u1, kSamplesPerSpan);
  const std::vector<double> vs = sampleParameters(patch.surface->VKnots(), patch.v0, patch.v1, kSamplesPerSpan);
  // A coarse pass first: a patch that crosses the plane (the usual case) shows it early.
  for (std::size_t stride : {kCoarseStride, std::size_t{1}})
    for (std::size_t i = 0; i < us.size(); i += stride)
      for (std::size_t j = 0; j < vs.size(); j += stride) {
        const double distance = signedDistance(patch.surface->Value(us[i], vs[j]));
        lowest = std::min(lowest, distance);
        highest = std::max(highest, distance);
        if (highest > tolerance && lowest < -tolerance) return std::nullopt;
      }
  const double sign = highest <= tolerance ? 1.0 : -1.0;
  const TColgp_Array2OfPnt& poles = patch.surface->Poles();
  double highestPole = -std::numeric_limits<double>::infinity();
  for (int i = poles.LowerRow(); i <= poles.UpperRow(); ++i)
    for (int j = poles.LowerCol(); j <= poles.UpperCol(); ++j)
      highestPole = std::max(highestPole, sign * signedDistance(poles(i, j)));
  if (highestPole < -tolerance) return std::nullopt;
  return sign;
}

/// The edge through the points of a line of contact, near repeats dropped.
std::optional<TopoDS_Edge> edgeThrough(const std::vector<gp_Pnt>& points, double tolerance) {
  std::vector<gp_Pnt> kept;
  for (const gp_Pnt& point : points)
    if (kept.empty() || kept.back().Distance(point) > 10.0 * tolerance) kept.push_back(point);
  if (kept.size() < 2) return std::nullopt;
  if (kept.size() == 2) return BRepBuilderAPI_MakeEdge(kept.front(), kept.back()).Edge();
  Handle(TColgp_HArray1OfPnt) held = new TColgp_HArray1OfPnt(1, static_cast<int>(kept.size()));
  for (std::size_t i = 0; i < kept.size(); ++i) held->SetValue(static_cast<int>(i) + 1, kept[i]);
  GeomAPI_Interpolate interpolation(held, false, tolerance);
  interpolation.Perform();
  if (!interpolation.IsDone()) return std::nullopt;
  return BRepBuilderAPI_MakeEdge(interpolation.Curve()).Edge();
}

/// The end of a line of contact moved onto the face's boundary where it lies close to it: the
/// classification leaves a band along the boundary undecided, so the last point found inside
/// stops short of the edge the line ends on. A corner within reach is taken first (a line
/// ending at a sharp trailing edge runs into its corner, which the thin face's sides pass close by).
gp_Pnt ontoBoundary(const TopoDS_Face& face, const gp_Pnt& end) {
  Bnd_Box box;
  BRepBndLib::Add(face, box, false);
  const double reach = kBoundaryBand * std::sqrt(box.SquareExtent());
  for (TopExp_Explorer corner(face, TopAbs_VERTEX); corner.More(); corner.Next()) {
    const gp_Pnt point = BRep_Tool::Pnt(TopoDS::Vertex(corner.Current()));
    if (point.Distance(end) <= reach) return point;
  }
  BRepExtrema_DistShapeShape distance(BRepBuilderAPI_MakeVertex(end).Vertex(), BRepTools::OuterWire(face));
  if (distance.IsDone() && distance.NbSolution() > 0 && distance.Value() <= reach) return distance.PointOnShape2(1);
  return end;
}

/// Where the line of contact leaves the face (or stops touching) between the station of `inside`
/// and `outside`, by bisection.
Summit lastTouching(const PatchBelowPlane& seen, const TopoDS_Face& face, Summit inside, double outside,
                    double tolerance) {
  for (int step = 0; step < kBisections; ++step) {
    const double middle = 0.5 * (inside.station + outside);
    const Summit summit = summitAt(seen, middle, {inside.across});
    if (summit.touches(tolerance) && inFace(face, seen.plane, summit.point, tolerance))
      inside = summit;
    else
      outside = middle;
  }
  return inside;
}

/// The lines of contact of the patch with the face along stations one way (see PatchBelowPlane),
/// and how many stations touched inside the face; nothing where the patch rises above the plane.
std::optional<std::vector<TopoDS_Edge>> contactsAlong(const PatchBelowPlane& seen, const TopoDS_Face& face,
                                                      double tolerance, int& touching) {
  const Handle(Geom_BSplineSurface)& surface = seen.patch.surface;
  const std::vector<double> stations =
      seen.stationsInU ? sampleParameters(surface->UKnots(), seen.patch.u0, seen.patch.u1, kStationsPerSpan)
                       : sampleParameters(surface->VKnots(), seen.patch.v0, seen.patch.v1, kStationsPerSpan);
  const std::vector<double> guesses =
      seen.stationsInU ? sampleParameters(surface->VKnots(), seen.patch.v0, seen.patch.v1, kSamplesPerSpan)
                       : sampleParameters(surface->UKnots(), seen.patch.u0, seen.patch.u1, kSamplesPerSpan);
  std::vector<Summit> summits;
  std::vector<bool> touches;
  for (double station : stations) {
    summits.push_back(summitAt(seen, station, guesses));
    if (summits.back().height > tolerance) return std::nullopt;
    touches.push_back(summits.back().touches(tolerance) && inFace(face, seen.plane, summits.back().point, tolerance));
  }
  touching = static_cast<int>(std::count(touches.begin(), touches.end(), true));
  std::vector<TopoDS_Edge> edges;
  for (std::size_t first = 0; first < stations.size(); ++first) {
    if (!touches[first]) continue;
    std::size_t last = first;
    while (last + 1 < stations.size() && touches[last + 1]) ++last;
    std::vector<gp_Pnt> points;
    if (first > 0)
      points.push_back(
          ontoBoundary(face, lastTouching(seen, face, summits[first], stations[first - 1], tolerance).point));
    for (std::size_t i = first; i <= last; ++i) points.push_back(summits[i].point);
    if (last + 1 < stations.size())
      points.push_back(
          ontoBoundary(face, lastTouching(seen, face, summits[last], stations[last + 1], tolerance).point));
    if (const std::optional<TopoDS_Edge> edge = edgeThrough(points, tolerance)) edges.push_back(*edge);
    first = last;
  }
  return edges;
}

/// The lines of contact of one patch with one plane face: taken with stations across the line
/// (each station touching once), that is the way round in which more stations touch.
std::vector<TopoDS_Edge> contactsOf(const Patch& patch, const TopoDS_Face& face, const gp_Pln& plane,
                                    double tolerance) {
  const std::optional<double> sign = sideBelow(patch, plane, tolerance);
  if (!sign) return {};
  const double extent = std::sqrt(poleBox(patch).SquareExtent());
  std::vector<TopoDS_Edge> best;
  int mostTouching = 0;
  for (bool stationsInU : {true, false}) {
    int touching = 0;
    const std::optional<std::vector<TopoDS_Edge>> edges =
        contactsAlong(PatchBelowPlane{patch, plane, *sign, stationsInU, extent}, face, tolerance, touching);
    if (!edges) return {};
    if (touching > mostTouching) {
      mostTouching = touching;
      best = *edges;
    }
  }
  return best;
}

/// A plane face and a patch that touch along lines.
struct Touch {
  TopoDS_Face face;
  gp_Pln plane;
  Patch patch;
};

/// Adds the lines where `planes`' plane faces touch `curved`'s patches, and each pair that does.
void addContacts(const TopoDS_Shape& planes, const TopoDS_Shape& curved, double tolerance,
                 std::vector<TopoDS_Edge>& edges, std::vector<Touch>& touches) {
  std::vector<Patch> patches;
  for (TopExp_Explorer explorer(curved, TopAbs_FACE); explorer.More(); explorer.Next())
    if (const std::optional<Patch> patch = patchOf(TopoDS::Face(explorer.Current()))) patches.push_back(*patch);
  for (TopExp_Explorer explorer(planes, TopAbs_FACE); explorer.More(); explorer.Next()) {
    const TopoDS_Face& face = TopoDS::Face(explorer.Current());
    const GeomAdaptor_Surface surface(BRep_Tool::Surface(face));
    if (surface.GetType() != GeomAbs_Plane) continue;
    Bnd_Box faceBox;
    BRepBndLib::Add(face, faceBox, false);
    faceBox.Enlarge(tolerance);
    for (const Patch& patch : patches) {
      if (poleBox(patch).IsOut(faceBox)) continue;
      const std::vector<TopoDS_Edge> found = contactsOf(patch, face, surface.Plane(), tolerance);
      if (found.empty()) continue;
      edges.insert(edges.end(), found.begin(), found.end());
      touches.push_back({face, surface.Plane(), patch});
    }
  }
}

/// Whether the edge lies where a plane face touches a patch: on the face and on the patch.
bool inTouch(const TopoDS_Edge& edge, const std::vector<Touch>& touches, double tolerance) {
  const double near = kOnBothFaces * tolerance;
  const BRepAdaptor_Curve curve(edge);
  for (const Touch& touch : touches) {
    bool onBoth = true;
    for (double share : {0.0, 0.5, 1.0}) {
      const gp_Pnt point =
          curve.Value(curve.FirstParameter() + share * (curve.LastParameter() - curve.FirstParameter()));
      GeomAPI_ProjectPointOnSurf onPatch(point, touch.patch.surface);
      onBoth = touch.plane.Distance(point) <= near && onPatch.NbPoints() > 0 && onPatch.LowerDistance() <= near &&
               BRepClass_FaceClassifier(touch.face, planeParameters(touch.plane, point), near).State() != TopAbs_OUT;
      if (!onBoth) break;
    }
    if (onBoth) return true;
  }
  return false;
}

}  // namespace

std::optional<std::vector<TopoDS_Edge>> withTangentContacts(const std::vector<TopoDS_Edge>& edges,
                                                            const TopoDS_Shape& first, const TopoDS_Shape& second,
                                                            double tolerance) {
  std::vector<TopoDS_Edge> contacts;
  std::vector<Touch> touches;
  addContacts(first, second, tolerance, contacts, touches);
  addContacts(second, first, tolerance, contacts, touches);
  if (contacts.empty()) return std::nullopt;
  for (const TopoDS_Edge& edge : edges)
    if (!inTouch(edge, touches, tolerance)) contacts.push_back(edge);
  return contacts;
}

}  // namespace airshape::geometry
