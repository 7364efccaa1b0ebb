#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Geom_BSplineCurve.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape::model {

/// Where a guide curve meets a profile: at a relative circumference, or, with the reference
/// library's own fromParameter/toParameter (outside the schema), at a parameter of the
/// profile curve itself.
struct ProfilePosition {
  double value = 0.0;
  bool isCurveParameter = false;
};

/// What a lofted component (one with sections and segments) tells the guide-curve builder about its sections,
/// in chain order (section k starts segment k; the last one ends the last segment).
struct GuideCurveSections {
  std::size_t count = 0;
  /// The global point of section k's profile at a position.
  std::function<gp_Pnt(std::size_t section, const ProfilePosition& position)> pointAt;
  /// The length by which a guide profile's alpha and gamma are scaled at section k.
  std::function<double(std::size_t section)> scale;
  /// The section's centre; guides pass the sections at centripetal parameters of these.
  std::function<gp_Pnt(std::size_t section)> centre;
  /// The direction of a guide profile's alpha where the curve gives no rXDirection.
  gp_Vec defaultXDirection;
};

/// One guide curve running through every segment: its first piece's uID, and the curve,
/// which passes section k at parameter sectionParameters[k], where it is at positions[k]
/// on the section's profile.
struct GuideCurve {
  std::string rootUid;
  Handle(Geom_BSplineCurve) curve;
  std::vector<double> sectionParameters;
  std::vector<ProfilePosition> positions;
  /// Per section: whether the curve counts as C2 there, as the reference counts it: inside
  /// one interpolated part, and where a piece joins with "C2 from/to previous" (although
  /// only the first derivative is matched there); false at its ends and at C0 and C1 joins.
  std::vector<bool> smoothAt;
};

/// Builds the guide curves of a component from its segments' <guideCurves> (chain order;
/// null where a segment has none) and the document's guide curve profiles:
/// - each piece's points are [P0, Q_1 .. Q_m, P1] with P0, P1 at the relative
///   circumferences on the two sections and Q = lerp(P0, P1, beta) + s(beta)(alpha x + gamma z),
///   x the rXDirection, z = x × (P1 − P0) normalised, s the sections' scale blended by beta;
/// - a piece continues the one named by fromGuideCurveUID, starting where it ended; each
///   root must run through exactly one piece per segment;
/// - pieces are interpolated together (cubic, pieces at centripetal section parameters)
///   until a piece with a <continuity> starts a new part; "C1/C2 from previous" gives a
///   part the end tangent of the one before, "to previous" the other way round, the parts
///   are interpolated in the order these dependencies need (a topological sort), and the
///   parts are joined into one curve per root.
/// Returns the curves in document order of their roots. Throws Error naming the CPACS path
/// of the offending guide curve.
std::vector<GuideCurve> buildGuideCurves(const schema::CpacsType& cpacs,
                                         const std::vector<const schema::GuideCurvesType*>& perSegment,
                                         const GuideCurveSections& sections);

/// Whether any segment has guide curves.
bool hasGuideCurves(const std::vector<const schema::GuideCurvesType*>& perSegment);

}  // namespace airshape::model
