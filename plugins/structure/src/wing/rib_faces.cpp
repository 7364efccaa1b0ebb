#include "rib_faces.h"

#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include <gp_Ax1.hxx>
#include <gp_Pln.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/brep_building.h"
#include "airshape/geometry/faces_inside.h"
#include "airshape/geometry/ruled_face_between_skins.h"
#include "airshape/geometry/skin_section.h"
#include "airshape/model/placement.h"
#include "named_faces.h"
#include "rib_cutter.h"
#include "structure_frame.h"

namespace airshape::structure {

namespace {

constexpr double kDegrees = M_PI / 180.0;
constexpr long long kMostRibs = 10000;

/// The tilt of a rib's cross section: its `ribRotation/x`, 90° (upright) when not given.
double xRotationOf(const RibsDefinition& ribs) {
  const auto& section = ribs.node->ribCrossSection;
  return section && section->ribRotation ? section->ribRotation->x : 90.0;
}

/// The direction of `line` where a rib through `point`, turned by `angle` about `up` from the
/// line's direction there, meets it: the share of the line where the rib's line through
/// `point` passes through the line's point is found by bisection of the side it passes on.
gp_Vec directionOfLineAtAngle(const geometry::Polyline& line, const gp_Pnt& point, const gp_Vec& up, double angle) {
  auto side = [&](double share) {
    gp_Vec rib = line.directionAt(share);
    rib.Rotate(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(up)), angle);
    return gp_Vec(point, line.at(share)).Dot(up.Crossed(rib));
  };
  constexpr int kSamples = 400;
  double low = 0.0, sideLow = side(0.0);
  for (int i = 1; i <= kSamples; ++i) {
    const double high = static_cast<double>(i) / kSamples, sideHigh = side(high);
    if ((sideLow <= 0.0) != (sideHigh <= 0.0)) {
      double a = low, b = high;
      for (int step = 0; step < 60; ++step) {
        const double middle = 0.5 * (a + b);
        ((side(a) <= 0.0) != (side(middle) <= 0.0) ? b : a) = middle;
      }
      return line.directionAt(0.5 * (a + b));
    }
    low = high, sideLow = sideHigh;
  }
  throw Error(ErrorCode::InvalidModel, "no rib at that angle to its rotation reference passes through its point");
}

/// The ribs of one `ribsPositioning`: set along a reference line, worked out in the wing frame.
class RibSet {
 public:
  RibSet(const RibsDefinition& ribs, const RibCutter& cutter)
      : ribs_(ribs),
        positioning_(*ribs.node->ribsPositioning),
        cutter_(cutter),
        frame_(cutter.frame()),
        reference_(cutter.frame().lineNamed(positioning_.ribReference, xpath() + "/ribReference")) {}

  std::vector<RibPlacement> placements() const {
    const bool startsOnSpar = positioning_.startSparPositionUID.has_value();
    const bool endsOnSpar = positioning_.endSparPositionUID.has_value();
    const double start = endShare(true, startsOnSpar);
    const double end = endShare(false, endsOnSpar);
    const int count = numberOfRibs(start, end);
    const double offset = etaOffset(start, end, count);
    std::vector<RibPlacement> placements;
    for (int i = 0; i < count; ++i) {
      const double eta = start + offset * i;
      const bool onSpar = (i == 0 && startsOnSpar) || (std::abs(end - eta) <= 1e-7 && endsOnSpar);
      const gp_Pnt point = reference_.at(eta);
      if (const auto section = endSectionAt(eta)) {
        placements.push_back(sectionPlacement(point, *section));
        continue;
      }
      const auto [direction, up] = ribAxes(point, eta, onSpar);
      placements.push_back({point, direction, up});
    }
    return placements;
  }

  NamedShape build() const {
    // All ribs cut at once: one Boolean operation for those the skins do not give directly. A
    // rib whose outline cannot be drawn (it does not meet a spar it is bounded by: the spar
    // ends before it) is left out with a warning, the others built; where no rib's can be
    // drawn, the first one's error is the set's.
    std::vector<RibOutline> outlines;
    std::vector<std::string> names;
    std::vector<std::pair<std::string, Error>> undrawn;
    const std::vector<RibPlacement> placed = placements();
    for (std::size_t i = 0; i < placed.size(); ++i) {
      const RibPlacement& rib = placed[i];
      const std::string name = ribs_.uid + "/rib " + std::to_string(i + 1);
      try {
        outlines.push_back(cutter_.outline(rib.point, rib.direction, rib.up, positioning_.ribStart, positioning_.ribEnd,
                                           name, xpath()));
        names.push_back(name);
      } catch (const Error& error) {
        undrawn.emplace_back(name, error);
      }
    }
    if (outlines.empty() && !undrawn.empty()) throw undrawn.front().second;
    for (const auto& [name, error] : undrawn)
      cutter_.warnLeftOut(error.cpacsPath().empty() ? xpath() : error.cpacsPath(), name + ": " + error.message());
    const std::vector<std::vector<TopoDS_Face>> cut = cutter_.cutAll(outlines, names, xpath());
    NamedFaces ribs;
    for (std::size_t i = 0; i < cut.size(); ++i) ribs.add(names[i], cut[i]);
    return ribs.shape();
  }

 private:
  std::string xpath() const { return ribs_.xpath + "/ribsPositioning"; }

  /// The rib's direction from its start to its end: the wing's y (or x) axis turned by
  /// `ribRotation/z` about the wing's z axis.
  /// Without a rotation reference the rib turns about `up` from the direction in which eta
  /// grows at its point; relative to a line (an edge or a spar), from that line's direction
  /// where the rib meets it.
  gp_Vec ribDirection(const gp_Pnt& point, const gp_Vec& up) const {
    const double z = (positioning_.ribRotation ? positioning_.ribRotation->z : 90.0) * kDegrees;
    const std::string reference =
        positioning_.ribRotation ? positioning_.ribRotation->ribRotationReference.value_or("") : "";
    gp_Vec direction;
    gp_Dir axis(0, 0, 1);
    if (sameName(reference, "globalY")) {
      direction = gp_Vec(0, 1, 0);
    } else if (sameName(reference, "globalX")) {
      direction = gp_Vec(-1, 0, 0);
    } else if (reference.empty()) {
      direction = frame_.etaDirection(frame_.etaOf(point));
      axis = gp_Dir(up);
    } else {
      try {
        direction =
            directionOfLineAtAngle(cutter_.frame().lineNamed(reference, xpath() + "/ribRotation"), point, up, z);
      } catch (const Error& error) {
        if (!error.cpacsPath().empty()) throw;
        throw Error(error.code(), error.message(), {}, xpath() + "/ribRotation");
      }
      axis = gp_Dir(up);
    }
    direction.Rotate(gp_Ax1(gp_Pnt(0, 0, 0), axis), z);
    return -direction.Normalized();
  }

  /// The rib plane's directions at a point: along the rib, and up (the midplane normal, or the
  /// wing's z axis at a spar position or a spar's end, as the spars stand), tilted about the
  /// rib by its cross section's x rotation.
  std::pair<gp_Vec, gp_Vec> ribAxes(const gp_Pnt& point, double eta, bool onSpar) const {
    const bool sparEnd = !isWingEdge(positioning_.ribReference) && (eta < 1e-7 || eta > 1.0 - 1e-7);
    const double pointEta = frame_.etaOf(point);
    gp_Vec up = onSpar || sparEnd ? frame_.uprightAtSparPosition(pointEta) : frame_.midplaneNormal(pointEta);
    const gp_Vec direction = ribDirection(point, up);
    up.Rotate(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(direction)), (xRotationOf(ribs_) - 90.0) * kDegrees);
    return {direction, up};
  }

  /// The component segment's root (eta 0) or tip (1) when a rib at `share` of its reference
  /// line lies in it: at an end of the line that lies in that section (a wing edge's, or a
  /// spar's that starts or ends there). Such a rib is the section between its borders whatever
  /// its rotation, as the reference library builds it (the guided D150 files' tail ribs at
  /// their spars' roots are turned so that their planes would run along the spars).
  std::optional<double> endSectionAt(double share) const {
    constexpr double kAtEnd = 1e-7, kInSection = 1e-6;
    if (frame_.inDevice() || (share > kAtEnd && share < 1.0 - kAtEnd)) return std::nullopt;
    const double eta = frame_.etaOf(reference_.at(share < kAtEnd ? 0.0 : 1.0));
    if (std::abs(eta) < kInSection) return 0.0;
    if (std::abs(eta - 1.0) < kInSection) return 1.0;
    return std::nullopt;
  }

  /// A rib in the root or tip section: its plane the section's, along the chord from its start
  /// towards its end (forwards only from the trailing edge or to the leading edge).
  RibPlacement sectionPlacement(const gp_Pnt& point, double section) const {
    gp_Vec direction(frame_.chordPoint("", section, 0.0), frame_.chordPoint("", section, 1.0));
    const bool forwards = (isWingEdge(positioning_.ribStart) && !isLeadingEdge(positioning_.ribStart)) ||
                          (isWingEdge(positioning_.ribEnd) && isLeadingEdge(positioning_.ribEnd));
    if (forwards) direction.Reverse();
    return {point, direction.Normalized(), frame_.thicknessDirection(section, 0.5).Normalized()};
  }

  /// The first (`start`) or the last rib's point as the schema gives it, or, in older files,
  /// where the reference line reaches the component segment eta `etaStart` or `etaEnd`.
  gp_Pnt endPoint(bool start) const {
    const auto& etaXsi = start ? positioning_.startEtaXsiPoint : positioning_.endEtaXsiPoint;
    const auto& curve = start ? positioning_.startCurvePoint : positioning_.endCurvePoint;
    const auto& sparPosition = start ? positioning_.startSparPositionUID : positioning_.endSparPositionUID;
    if (!etaXsi && !curve && !sparPosition)
      if (const auto point = olderEndPoint(start ? "etaStart" : "etaEnd")) return *point;
    return cutter_.pointOf(etaXsi, curve, sparPosition, xpath() + (start ? "/start" : "/end"));
  }

  /// Where the reference line crosses the eta line that an older file's `etaStart` or `etaEnd`
  /// (eta and referenceUID, as CPACS 3.0 files of some tools write it) names, with a warning;
  /// nothing when the element is not there.
  std::optional<gp_Pnt> olderEndPoint(const std::string& element) const {
    const Configuration& configuration = cutter_.configuration();
    const std::string where = xpath() + "/" + element;
    double eta = 0.0;
    std::string referenceUid;
    try {
      eta = std::stod(configuration.value(where + "/eta"));
    } catch (const std::exception&) {
      return std::nullopt;
    }
    try {
      referenceUid = configuration.value(where + "/referenceUID");
    } catch (const Error&) {  // a component segment eta
    }
    configuration.warnAboutGeometry({Problem::Severity::Warning, where,
                                     "a rib start or end in an older form; read as the reference line's point "
                                     "at that eta"});
    const double csEta = frame_.frameEta(referenceUid, eta);
    const gp_Pnt front = frame_.chordPoint("", csEta, 0.0), back = frame_.chordPoint("", csEta, 1.0);
    const auto share = reference_.crossing(front, gp_Vec(front, back).Crossed(frame_.midplaneNormal(csEta)));
    if (!share)
      throw Error(ErrorCode::InvalidModel, "the reference line does not reach eta " + std::to_string(eta), {}, where);
    return reference_.at(*share);
  }

  /// The share of the reference line the first (`start`) or the last rib sits at: a point
  /// given on the reference line itself is its own share (a rib through it may run along the
  /// line); any other point gives the share where the rib through it crosses the line.
  double endShare(bool start, bool onSpar) const {
    const auto& curve = start ? positioning_.startCurvePoint : positioning_.endCurvePoint;
    if (curve && curve->referenceUID == positioning_.ribReference)
      return model::fraction(curve->eta, xpath() + (start ? "/startCurvePoint/eta" : "/endCurvePoint/eta"));
    return etaOnReference(endPoint(start), onSpar);
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

  /// How many ribs the set has: as many as written, or as the spacing fits between its ends.
  /// More than kMostRibs is refused: no wing has so many in one set, and building them would
  /// take hours (a spacing of 1e-300 written by mistake asks for more ribs than there are numbers).
  int numberOfRibs(double start, double end) const {
    if (positioning_.numberOfRibs) {
      const auto count = *positioning_.numberOfRibs;
      if (count < 1)
        throw Error(ErrorCode::InvalidModel, "numberOfRibs must be at least 1", {}, xpath() + "/numberOfRibs");
      if (count > kMostRibs) throw tooMany(static_cast<double>(count), xpath() + "/numberOfRibs");
      return static_cast<int>(count);
    }
    if (!positioning_.spacing || !(*positioning_.spacing > 0))
      throw Error(ErrorCode::InvalidModel, "the ribs need a positive spacing or a numberOfRibs", {}, xpath());
    if (std::abs(end - start) <= 1e-7) return 1;
    const double count = std::floor((reference_.length() * std::abs(end - start) + 1e-7) / *positioning_.spacing) + 1;
    if (!(count <= kMostRibs)) throw tooMany(count, xpath() + "/spacing");
    return static_cast<int>(count);
  }

  static Error tooMany(double count, const std::string& where) {
    std::ostringstream text;
    text << "asks for " << count << " ribs in one set, more than " << kMostRibs << "; refused";
    return Error(ErrorCode::InvalidModel, text.str(), {}, where);
  }

  double etaOffset(double start, double end, int count) const {
    if (positioning_.numberOfRibs) return count == 1 ? 0.0 : std::abs(end - start) / (count - 1);
    return *positioning_.spacing / reference_.length();
  }

  const RibsDefinition& ribs_;
  const schema::WingRibsPositioningType& positioning_;
  const RibCutter& cutter_;
  const StructureFrame& frame_;
  geometry::Polyline reference_;
};

/// The one rib of a `ribExplicitPositioning`: from its start point to its end point.
class ExplicitRib {
 public:
  ExplicitRib(const RibsDefinition& ribs, const RibCutter& cutter)
      : ribs_(ribs), positioning_(*ribs.node->ribExplicitPositioning), cutter_(cutter), frame_(cutter.frame()) {}

  /// Where the rib lies as one plane (the start point, its direction, up); a rib between spars
  /// standing at different angles is no plane and bounds no tank or cell.
  RibPlacement placement() const {
    const Lines lines = endLines();
    if (lines.twisted())
      throw Error(ErrorCode::NotImplemented,
                  "a rib between spars standing at different angles is no plane; it bounds nothing yet", {}, xpath());
    return {lines.startPoint, gp_Vec(lines.startPoint, lines.endPoint).Normalized(), lines.start.up};
  }

  NamedShape build() const {
    const std::string name = ribs_.uid + "/rib 1";
    const Lines lines = endLines();
    NamedFaces ribs;
    if (lines.twisted()) {
      ribs.add(name, twistedRib(lines));
    } else {
      const RibPlacement rib = placement();
      ribs.add(name, cutter_.cut(rib.point, rib.direction, rib.up, positioning_.ribStart, positioning_.ribEnd, name,
                                 xpath()));
    }
    return ribs.shape();
  }

 private:
  /// A line the rib passes through at one of its ends (wing frame): through a point, along up
  /// (zero at a wing edge, which gives no direction).
  struct EndLine {
    gp_Pnt through;
    gp_Vec up;
  };
  /// The rib's start and end point and its lines there.
  struct Lines {
    gp_Pnt startPoint, endPoint;
    EndLine start, end;
    bool twisted() const { return start.up.Crossed(end.up).Magnitude() > 1e-9; }
  };

  std::string xpath() const { return ribs_.xpath + "/ribExplicitPositioning"; }

  /// The rib's lines at its start and end, both with their up direction (where an end gives
  /// none, the other's), tilted by the cross section's x rotation about the wing's x axis, so
  /// that neighbouring ribs stay connected.
  Lines endLines() const {
    const gp_Pnt start = cutter_.pointOf(positioning_.startEtaXsiPoint, positioning_.startCurvePoint,
                                         positioning_.startSparPositionUID, xpath() + "/start");
    const gp_Pnt end = cutter_.pointOf(positioning_.endEtaXsiPoint, positioning_.endCurvePoint,
                                       positioning_.endSparPositionUID, xpath() + "/end");
    if (start.Distance(end) < 1e-9)
      throw Error(ErrorCode::InvalidModel, "the rib's start and end point coincide", {}, xpath());
    Lines lines{start, end, lineAt(start, end, true), lineAt(start, end, false)};
    gp_Vec &upStart = lines.start.up, &upEnd = lines.end.up;
    if (upStart.SquareMagnitude() == 0.0 && upEnd.SquareMagnitude() == 0.0)
      upStart = upEnd = upBetweenEdges(start, end);
    else if (upStart.SquareMagnitude() == 0.0)
      upStart = upEnd;
    else if (upEnd.SquareMagnitude() == 0.0)
      upEnd = upStart;
    for (gp_Vec* up : {&upStart, &upEnd}) {
      up->Normalize();
      up->Rotate(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)), -(xRotationOf(ribs_) - 90.0) * kDegrees);
    }
    return lines;
  }

  /// A rib between spars standing at different angles: the ruled surface between its lines,
  /// the part inside the component segment's solid.
  std::vector<TopoDS_Face> twistedRib(const Lines& lines) const {
    const double reach = frame_.reach();
    // Straight from the skins where they allow it, else by a Boolean common.
    const geometry::RuledLines ruled{frame_.toGlobal(lines.start.through), frame_.toGlobal(lines.end.through),
                                     frame_.toGlobal(lines.start.up), frame_.toGlobal(lines.end.up)};
    if (const auto face = geometry::ruledSectionBetweenSkins(frame_.skin(true), frame_.skin(false), ruled,
                                                             geometry::kTraceTolerance * reach))
      return {*face};
    auto line = [&](const EndLine& end) {
      return geometry::straightLine(frame_.toGlobal(end.through.Translated(-reach * end.up)),
                                    frame_.toGlobal(end.through.Translated(reach * end.up)));
    };
    std::vector<TopoDS_Face> inside;
    try {
      inside = geometry::facesInside(geometry::ruledFace(line(lines.start), line(lines.end)), frame_.solid());
    } catch (const Error&) {
      throw Error(ErrorCode::InvalidModel, std::string("the rib cannot be cut out of ") + frame_.hostName(), {},
                  xpath());
    }
    if (inside.empty())
      throw Error(ErrorCode::InvalidModel, std::string("the rib does not cross ") + frame_.hostName(), {}, xpath());
    return inside;
  }

  /// The up direction of a rib from edge to edge: in the plane of the section both its ends lie
  /// in (the component segment's root or tip, or a section between its segments), otherwise
  /// the mid-plane's normal at its start.
  gp_Vec upBetweenEdges(const gp_Pnt& start, const gp_Pnt& end) const {
    const double eta = frame_.etaOf(start);
    if (std::abs(frame_.etaOf(end) - eta) < 1e-9)
      for (const double section : frame_.sectionEtas())
        if (std::abs(section - eta) < 1e-9) return frame_.thicknessDirection(section, 0.5);
    return frame_.midplaneNormal(eta);
  }

  /// The line a spar gives at the rib's start (or end): where the plane across the rib
  /// (through the midplane normal) meets the spar's web, through the spar's midplane line; how
  /// the spar stands at a spar position (StructureFrame::uprightAtSparPosition); no direction
  /// at the wing's edges.
  EndLine lineAt(const gp_Pnt& start, const gp_Pnt& end, bool atStart) const {
    const auto& sparPosition = atStart ? positioning_.startSparPositionUID : positioning_.endSparPositionUID;
    const gp_Pnt at = atStart ? start : end;
    if (sparPosition) return {at, frame_.uprightAtSparPosition(frame_.etaOf(at))};
    const std::string& spar = atStart ? positioning_.ribStart : positioning_.ribEnd;
    if (isWingEdge(spar)) return {at, gp_Vec(0, 0, 0)};
    const gp_Vec across = frame_.midplaneNormal(frame_.etaOf(at)).Crossed(gp_Vec(start, end));
    const gp_Pln plane(frame_.toGlobal(at), gp_Dir(frame_.toGlobal(across)));
    std::vector<gp_Pnt> points = cutter_.sparSection(spar, plane, xpath() + (atStart ? "/ribStart" : "/ribEnd"));
    gp_Pnt low = frame_.toWing(points.front()), high = low;
    for (const gp_Pnt& global : points) {
      const gp_Pnt p = frame_.toWing(global);
      if (p.Z() < low.Z()) low = p;
      if (p.Z() > high.Z()) high = p;
    }
    return {gp_Pnt(0.5 * (low.XYZ() + high.XYZ())), gp_Vec(low, high)};
  }

  const RibsDefinition& ribs_;
  const schema::WingRibExplicitPositioningType& positioning_;
  const RibCutter& cutter_;
  const StructureFrame& frame_;
};

}  // namespace

RibPlacement ribPlacement(const Configuration& configuration, const RibsDefinition& ribs, const StructureFrame& frame,
                          long long number) {
  // Cached: the cells, spars and tanks bounded by ribs of one set each ask for them.
  const auto placed = configuration.cache().obtain<std::vector<RibPlacement>>("rib-placements:" + ribs.uid, [&] {
    const RibCutter cutter(configuration, frame, *ribs.structure);
    auto all = std::make_shared<std::vector<RibPlacement>>();
    if (ribs.node->ribsPositioning)
      *all = RibSet(ribs, cutter).placements();
    else if (ribs.node->ribExplicitPositioning)
      *all = {ExplicitRib(ribs, cutter).placement()};
    return std::shared_ptr<const std::vector<RibPlacement>>(all);
  });
  const std::vector<RibPlacement>& all = *placed;
  if (number < 1 || number > static_cast<long long>(all.size()))
    throw Error(ErrorCode::InvalidModel, "the ribs definition '" + ribs.uid + "' has no rib " + std::to_string(number) +
                                             " (it has " + std::to_string(all.size()) + ")");
  return all[static_cast<std::size_t>(number - 1)];
}

namespace {

/// Says in a warning where a rib's start, end or reference names an edge by its short form.
void warnAboutShortEdgeNames(const Configuration& configuration, const RibsDefinition& ribs) {
  const auto check = [&](const std::string& name, const std::string& where) {
    if (sameName(name, "le") || sameName(name, "te"))
      configuration.warnAboutGeometry(
          {Problem::Severity::Warning, where,
           "'" + name + "' read as " + (isLeadingEdge(name) ? "leadingEdge" : "trailingEdge")});
  };
  if (const auto& set = ribs.node->ribsPositioning) {
    const std::string where = ribs.xpath + "/ribsPositioning";
    check(set->ribReference, where + "/ribReference");
    check(set->ribStart, where + "/ribStart");
    check(set->ribEnd, where + "/ribEnd");
  } else if (const auto& rib = ribs.node->ribExplicitPositioning) {
    const std::string where = ribs.xpath + "/ribExplicitPositioning";
    check(rib->ribStart, where + "/ribStart");
    check(rib->ribEnd, where + "/ribEnd");
  }
}

}  // namespace

NamedShape ribFaces(const Configuration& configuration, const StructureServices& services, const RibsDefinition& ribs) {
  warnAboutShortEdgeNames(configuration, ribs);
  const StructureFrame frame(configuration, services, ribs.componentSegmentUid, ribs.wingUid, ribs.deviceUid);
  const RibCutter cutter(configuration, frame, *ribs.structure);
  if (ribs.node->ribsPositioning) return RibSet(ribs, cutter).build();
  if (ribs.node->ribExplicitPositioning) return ExplicitRib(ribs, cutter).build();
  throw Error(ErrorCode::InvalidModel, "the ribs definition has neither ribsPositioning nor ribExplicitPositioning", {},
              ribs.xpath);
}

}  // namespace airshape::structure
