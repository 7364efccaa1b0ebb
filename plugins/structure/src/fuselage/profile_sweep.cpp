#include "profile_sweep.h"

#include <cmath>
#include <vector>

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_UniformAbscissa.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <GeomFill.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Geom_BSplineCurve.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_HArray1OfPnt.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "fuselage_frame.h"
#include "fuselage_structure_list.h"
#include "named_faces.h"
#include "skin_lines.h"
#include "structural_profile.h"

namespace airshape::structure {

namespace {

constexpr double kDegrees = M_PI / 180.0;
/// Points along each piece of the line at which the profile is placed, evenly by length; the
/// sheets' edges are cubics through them.
constexpr int kStations = 48;

/// Where along a line the profile stands: a point of the line and the profile plane's axes
/// (local y and z), after the alignment.
struct Station {
  double parameter = 0.0;
  gp_Pnt point;
  gp_Vec y, z;

  gp_Pnt at(const gp_Pnt2d& profilePoint) const {
    return point.Translated(profilePoint.X() * y + profilePoint.Y() * z);
  }
};

/// How a position places the profile: rotationLocX (degrees), translationLocY and Z.
struct Alignment {
  double rotation = 0.0, y = 0.0, z = 0.0;

  explicit Alignment(const schema::StringerFramePositionType& position) {
    if (!position.alignment) return;
    rotation = position.alignment->rotationLocX.value_or(0.0) * kDegrees;
    y = position.alignment->translationLocY.value_or(0.0);
    z = position.alignment->translationLocZ.value_or(0.0);
  }
};

/// Whether the surface normal of the face points into the body: a point a little along it lies
/// in the body's solid (and one a little against it does not).
bool normalPointsInto(const FuselageFrame& body, const gp_Pnt& point, const gp_Vec& normal) {
  const double step = 1e-4 * body.reach();
  const auto state = [&](double side) {
    BRepClass3d_SolidClassifier classifier(body.solid(), point.Translated(side * step * normal), 1e-9 * body.reach());
    return classifier.State();
  };
  return state(1.0) == TopAbs_IN || state(-1.0) == TopAbs_OUT;
}

/// The stations of one piece of the line. `alongAxis`: the line runs along the body's axis (a
/// stringer; local x along +axis) or round it (a frame; local y along +axis).
std::vector<Station> stationsOf(const SkinEdge& piece, const FuselageFrame& body, const gp_Dir& axis, bool alongAxis,
                                const Alignment& alignment, const std::string& where) {
  if (piece.face.IsNull()) throw Error(ErrorCode::InvalidModel, "a piece of the line lies on no skin face", {}, where);
  BRepAdaptor_Curve curve(piece.edge);
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(piece.face);
  ShapeAnalysis_Surface projector(surface);
  std::vector<Station> stations;
  double inwards = 0.0;  // +1 or -1: the sign that turns the surface normal into the body
  GCPnts_UniformAbscissa even(curve, kStations + 1, curve.FirstParameter(), curve.LastParameter(), 1e-9);
  if (!even.IsDone() || even.NbPoints() < 2)
    throw Error(ErrorCode::InvalidModel, "a piece of the line cannot be divided evenly", {}, where);
  for (int i = 1; i <= even.NbPoints(); ++i) {
    Station station;
    station.parameter = even.Parameter(i);
    gp_Vec tangent;
    curve.D1(station.parameter, station.point, tangent);
    const gp_Pnt2d uv = projector.ValueOfUV(station.point, 1e-9 * body.reach());
    GeomLProp_SLProps properties(surface, uv.X(), uv.Y(), 1, 1e-12);
    if (!properties.IsNormalDefined() || tangent.Magnitude() < 1e-12)
      throw Error(ErrorCode::InvalidModel, "the skin has no normal where the line runs", {}, where);
    const gp_Vec normal(properties.Normal());
    if (inwards == 0.0) inwards = normalPointsInto(body, station.point, normal) ? 1.0 : -1.0;
    // The line's direction taken in the skin's tangent plane, so that the profile stands square
    // to the skin: a section edge's own small wobble off the skin does not tilt it.
    const gp_Vec z = (inwards * normal).Normalized();
    gp_Vec x = tangent - tangent.Dot(z) * z;
    if (x.Magnitude() < 1e-12) throw Error(ErrorCode::InvalidModel, "the line runs square to the skin", {}, where);
    x.Normalize();
    if (alongAxis ? x.Dot(gp_Vec(axis)) < 0.0 : z.Crossed(x).Dot(gp_Vec(axis)) < 0.0) x.Reverse();
    const gp_Vec y = z.Crossed(x);
    const gp_Vec turnedY = std::cos(alignment.rotation) * y + std::sin(alignment.rotation) * z;
    const gp_Vec turnedZ = -std::sin(alignment.rotation) * y + std::cos(alignment.rotation) * z;
    station.point.Translate(alignment.y * y + alignment.z * z);
    station.y = turnedY;
    station.z = turnedZ;
    stations.push_back(station);
  }
  return stations;
}

/// The cubic through a profile point placed at each station, parametrised as the line.
Handle(Geom_BSplineCurve) edgeOfSheet(const std::vector<Station>& stations, const gp_Pnt2d& profilePoint) {
  const int count = static_cast<int>(stations.size());
  Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, count);
  Handle(TColStd_HArray1OfReal) parameters = new TColStd_HArray1OfReal(1, count);
  for (int i = 0; i < count; ++i) {
    points->SetValue(i + 1, stations[i].at(profilePoint));
    parameters->SetValue(i + 1, stations[i].parameter);
  }
  GeomAPI_Interpolate interpolation(points, parameters, false, 1e-12);
  interpolation.Perform();
  return interpolation.IsDone() ? interpolation.Curve() : nullptr;
}

/// Each sheet swept along each piece of the line: the ruled surface between the cubics of its
/// two points.
NamedShape swept(const std::string& uid, const std::vector<SkinEdge>& line, const FuselageFrame& body, bool alongAxis,
                 const schema::StringerFramePositionType& position, const Configuration& configuration,
                 const std::string& where) {
  const std::vector<ProfileSheet> sheets =
      structuralProfileSheets(configuration, position.structuralElementUID, position.xpath + "/structuralElementUID");
  const gp_Dir axis = body.toGlobal(gp_Dir(1, 0, 0));
  const Alignment alignment(position);
  NamedFaces faces;
  for (const SkinEdge& piece : line) {
    if (BRep_Tool::Degenerated(piece.edge)) continue;
    const std::vector<Station> stations = stationsOf(piece, body, axis, alongAxis, alignment, where);
    for (const ProfileSheet& sheet : sheets) {
      const Handle(Geom_BSplineCurve) from = edgeOfSheet(stations, sheet.from), to = edgeOfSheet(stations, sheet.to);
      if (from.IsNull() || to.IsNull())
        throw Error(ErrorCode::InvalidModel, "sheet '" + sheet.uid + "' cannot be swept along the line", {}, where);
      BRepBuilderAPI_MakeFace face(GeomFill::Surface(from, to), 1e-7);
      if (!face.IsDone())
        throw Error(ErrorCode::InvalidModel, "sheet '" + sheet.uid + "' sweeps no surface", {}, where);
      faces.add(uid + "/" + sheet.uid, {face.Face()});
    }
  }
  if (faces.empty()) throw Error(ErrorCode::InvalidModel, "the line has no length to sweep along", {}, where);
  return faces.shape();
}

}  // namespace

NamedShape frameProfile(const Configuration& configuration, const tank::TankServices* tanks, const std::string& uid) {
  const auto frame = frameElementNamed(configuration, uid, tanks);
  const FuselageFrame body = FuselageFrame::ofHost(configuration, frame.hostUid, frame.fuselage, frame.vesselPlacement);
  if (frame.node->framePosition.empty())
    throw Error(ErrorCode::InvalidModel, "the frame has no positions", {}, frame.node->xpath);
  return swept(uid, frameOnSkin(configuration, tanks, uid), body, false, frame.node->framePosition[0], configuration,
               frame.node->xpath);
}

NamedShape stringerProfile(const Configuration& configuration, const tank::TankServices* tanks,
                           const std::string& uid) {
  const auto stringer = stringerElementNamed(configuration, uid, tanks);
  const FuselageFrame body =
      FuselageFrame::ofHost(configuration, stringer.hostUid, stringer.fuselage, stringer.vesselPlacement);
  if (stringer.node->stringerPosition.empty())
    throw Error(ErrorCode::InvalidModel, "the stringer has no positions", {}, stringer.node->xpath);
  return swept(uid, stringerOnSkin(configuration, tanks, uid), body, true, stringer.node->stringerPosition[0],
               configuration, stringer.node->xpath);
}

}  // namespace airshape::structure
