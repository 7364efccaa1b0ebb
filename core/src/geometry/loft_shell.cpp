#include "airshape/geometry/loft_shell.h"

#include <cmath>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRep_Builder.hxx>
#include <Geom2d_Line.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/loft_piece.h"
#include "airshape/geometry/surface_split.h"

namespace airshape::geometry {

namespace {

/// A stretch ending within this of its surface's v range covers the whole surface.
constexpr double kSameParameter = 1e-12;

/// The parameter line v = const of a face, running with u.
Handle(Geom2d_Line) lineAtV(double v) { return new Geom2d_Line(gp_Pnt2d(0.0, v), gp_Dir2d(1.0, 0.0)); }
/// The parameter line u = const of a face, running with v.
Handle(Geom2d_Line) lineAtU(double u) { return new Geom2d_Line(gp_Pnt2d(u, 0.0), gp_Dir2d(0.0, 1.0)); }

/// The profile edge at one site: the loft's iso-curve from and back to `vertex`, or a
/// degenerated edge where the profile has shrunk to a point.
TopoDS_Edge profileEdge(const Handle(Geom_BSplineSurface) & loft, double v, const TopoDS_Vertex& vertex, double u0,
                        double u1, bool& degenerated) {
  const auto profile = Handle(Geom_BSplineCurve)::DownCast(loft->VIso(v));
  degenerated = isPointCurve(*profile);
  if (!degenerated) return BRepBuilderAPI_MakeEdge(profile, vertex, vertex, u0, u1).Edge();
  BRep_Builder builder;
  TopoDS_Edge edge;
  builder.MakeEdge(edge);
  builder.Add(edge, vertex.Oriented(TopAbs_FORWARD));
  builder.Add(edge, vertex.Oriented(TopAbs_REVERSED));
  builder.Range(edge, u0, u1);
  builder.Degenerated(edge, true);
  return edge;
}

/// How an edge is used by a face as the face lies in its shell (the edge's orientation in the
/// face's wire composed with the face's).
TopAbs_Orientation usedAs(const TopoDS_Face& face, const TopoDS_Edge& edge) {
  for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next())
    if (it.Current().IsSame(edge)) return it.Current().Orientation();
  return TopAbs_EXTERNAL;
}

/// The planar cap on a profile edge, turned so that it uses the edge the other way round
/// from the skin face beside it (so the shell is oriented consistently).
TopoDS_Face capOn(const TopoDS_Edge& profile, const TopoDS_Face& skin) {
  TopoDS_Face cap = planarFace(BRepBuilderAPI_MakeWire(profile).Wire());
  if (usedAs(cap, profile) == usedAs(skin, profile)) cap.Reverse();
  return cap;
}

/// Consecutive stretches must meet with the same parameters: the end profile of one is the
/// start profile of the next at every u (one edge serves both), over the same u range.
void checkStretchesMeet(const std::vector<LoftStretch>& stretches, double u0, double u1) {
  constexpr int kSamples = 64;
  for (std::size_t k = 0; k + 1 < stretches.size(); ++k) {
    const LoftStretch &before = stretches[k], &after = stretches[k + 1];
    double a0, a1, b0, b1;
    after.surface->Bounds(a0, a1, b0, b1);
    if (std::abs(a0 - u0) > 1e-12 || std::abs(a1 - u1) > 1e-12)
      throw Error(ErrorCode::InvalidModel, "the stretches of the loft differ in their u range");
    for (int i = 0; i <= kSamples; ++i) {
      const double u = u0 + (u1 - u0) * i / kSamples;
      if (before.surface->Value(u, before.vEnd).Distance(after.surface->Value(u, after.vStart)) > kBrepTolerance)
        throw Error(ErrorCode::InvalidModel, "stretches of the loft do not meet at the same parameters");
    }
  }
}

/// The solid of stretches that meet (checked by the caller, or parts of one surface).
TopoDS_Solid solidOfMeetingStretches(const std::vector<LoftStretch>& stretches, std::vector<TopoDS_Face>& faces) {
  double u0, u1, v0, v1;
  stretches.front().surface->Bounds(u0, u1, v0, v1);
  // The profiles where the stretches meet, and at both ends: one edge each.
  BRep_Builder builder;
  std::vector<TopoDS_Edge> profiles;
  std::vector<bool> degenerated;
  std::vector<TopoDS_Vertex> corners;
  auto addProfile = [&](const Handle(Geom_BSplineSurface) & surface, double v) {
    corners.push_back(BRepBuilderAPI_MakeVertex(surface->Value(u0, v)).Vertex());
    bool point = false;
    profiles.push_back(profileEdge(surface, v, corners.back(), u0, u1, point));
    degenerated.push_back(point);
  };
  for (const LoftStretch& stretch : stretches) addProfile(stretch.surface, stretch.vStart);
  addProfile(stretches.back().surface, stretches.back().vEnd);

  std::vector<TopoDS_Face> skins;
  for (std::size_t k = 0; k < stretches.size(); ++k) {
    const LoftStretch& stretch = stretches[k];
    const double vStart = stretch.vStart, vEnd = stretch.vEnd;
    stretch.surface->Bounds(u0, u1, v0, v1);
    // The face carries its stretch of the surface only (Segment keeps the parameters).
    const bool part = vStart > v0 + kSameParameter || vEnd < v1 - kSameParameter;
    Handle(Geom_BSplineSurface) piece = stretch.surface;
    if (part) {
      piece = Handle(Geom_BSplineSurface)::DownCast(stretch.surface->Copy());
      piece->Segment(u0, u1, vStart, vEnd);
    }
    TopoDS_Face face;
    builder.MakeFace(face, piece, kBrepTolerance);
    // The seam's curve is the piece's line at u0: its stretch only (a file carries its poles).
    const Handle(Geom_Curve) seamCurve = piece->UIso(u0);
    const TopoDS_Edge seam = BRepBuilderAPI_MakeEdge(seamCurve, corners[k], corners[k + 1], vStart, vEnd).Edge();
    builder.UpdateEdge(seam, lineAtU(u1), lineAtU(u0), face, kBrepTolerance);  // forward: the side at u1
    builder.UpdateEdge(profiles[k], lineAtV(vStart), face, kBrepTolerance);
    builder.UpdateEdge(profiles[k + 1], lineAtV(vEnd), face, kBrepTolerance);
    // A parameter line has no ends of its own: the profile runs over the whole u range (which
    // a degenerated edge, having no curve in space, learns only here).
    builder.Range(profiles[k], face, u0, u1);
    builder.Range(profiles[k + 1], face, u0, u1);
    // Anticlockwise in (u, v): along the start profile, up the seam at u1, back along the end
    // profile, down the seam at u0.
    TopoDS_Wire wire;
    builder.MakeWire(wire);
    builder.Add(wire, profiles[k].Oriented(TopAbs_FORWARD));
    builder.Add(wire, seam.Oriented(TopAbs_FORWARD));
    builder.Add(wire, profiles[k + 1].Oriented(TopAbs_REVERSED));
    builder.Add(wire, seam.Oriented(TopAbs_REVERSED));
    wire.Closed(true);
    builder.Add(face, wire);
    skins.push_back(face);
  }
  faces.clear();
  faces.push_back(degenerated.front() ? TopoDS_Face() : capOn(profiles.front(), skins.front()));
  faces.insert(faces.end(), skins.begin(), skins.end());
  faces.push_back(degenerated.back() ? TopoDS_Face() : capOn(profiles.back(), skins.back()));

  TopoDS_Shell shell;
  builder.MakeShell(shell);
  for (const TopoDS_Face& face : faces)
    if (!face.IsNull()) builder.Add(shell, face);
  shell.Closed(true);
  TopoDS_Solid solid;
  builder.MakeSolid(solid);
  builder.Add(solid, shell);
  return outwards(solid);
}

}  // namespace

TopoDS_Solid closedLoftSolid(const std::vector<LoftStretch>& stretches, std::vector<TopoDS_Face>& faces) {
  if (stretches.empty()) throw Error(ErrorCode::InvalidModel, "a loft needs at least one stretch");
  double u0, u1, v0, v1;
  stretches.front().surface->Bounds(u0, u1, v0, v1);
  checkStretchesMeet(stretches, u0, u1);
  return solidOfMeetingStretches(stretches, faces);
}

TopoDS_Solid closedLoftSolid(const Handle(Geom_BSplineSurface) & loft, const std::vector<double>& sites,
                             std::vector<TopoDS_Face>& faces) {
  if (sites.size() < 2) throw Error(ErrorCode::InvalidModel, "a loft needs at least one stretch");
  // Parts of one surface meet by construction; each carries only its own poles.
  const std::vector<Handle(Geom_BSplineSurface)> parts = splitAlongV(*loft, sites);
  std::vector<LoftStretch> stretches;
  for (std::size_t k = 0; k < parts.size(); ++k) stretches.push_back({parts[k], sites[k], sites[k + 1]});
  return solidOfMeetingStretches(stretches, faces);
}

}  // namespace airshape::geometry
