#pragma once

#include <string>
#include <utility>
#include <vector>

#include <TopoDS_Face.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape::structure {

class FuselageFrame;

/// A ray of a stringer or frame position, in fuselage coordinates: from the reference point
/// (station, referenceY, referenceZ; the station as FuselageFrame::positionX) at the reference angle about the x axis
/// (0° up, 90° towards −y). Where it meets the skin is where the stringer or frame passes.
struct PositionRay {
  gp_Pnt origin;
  gp_Vec direction;  ///< unit length at a position, blended linearly between positions

  /// Throws Error naming the position when its station cannot be found.
  static PositionRay of(const FuselageFrame& fuselage, const schema::StringerFramePositionType& position);
  /// The ray `share` of the way from `a` to `b`: origins and directions blended linearly, so
  /// that the rays between two positions sweep the ruled surface between theirs.
  static PositionRay between(const PositionRay& a, const PositionRay& b, double share);
};

/// Two rays the surface between which a stringer or frame sweeps.
using RaySpan = std::pair<PositionRay, PositionRay>;

/// The ruled surface between two rays, `length` long (fuselage coordinates), in the global frame.
TopoDS_Face ruledBetween(const FuselageFrame& fuselage, const PositionRay& a, const PositionRay& b, double length);

/// Where a fuselage stringer runs: between two positions the rays sweep the ruled surface between
/// theirs (a plane when their angles agree), and the stringer is where that surface meets the
/// skin. Before its first and after its last position it runs on along x with that position's ray.
class StringerPath {
 public:
  /// Throws Error naming the CPACS path for a stringer without positions or with a position
  /// whose station cannot be found.
  StringerPath(const FuselageFrame& fuselage, const schema::StringerType& stringer);

  /// The ray at station x (fuselage coordinates).
  PositionRay rayAt(double x) const;
  /// The pairs of rays the surface from station `fromX` to `toX` runs between: the ends and
  /// the positions between them.
  std::vector<RaySpan> spans(double fromX, double toX) const;
  /// The swept surface from station `fromX` to `toX`, in the global frame, its rays `length`
  /// long (fuselage coordinates).
  std::vector<TopoDS_Face> surface(const FuselageFrame& fuselage, double fromX, double toX, double length) const;
  double firstX() const { return positions_.front().origin.X(); }
  double lastX() const { return positions_.back().origin.X(); }

 private:
  std::vector<PositionRay> positions_;  ///< sorted by x
};

/// The surface a frame of several positions sweeps: the ruled surfaces between the rays of
/// consecutive positions, in the order written (a fan in the plane x = positionX when all
/// positions share it, corrugated for a riffled frame), in the global frame.
std::vector<TopoDS_Face> frameSweep(const FuselageFrame& fuselage, const schema::FrameType& frame, double length);

/// The pairs of rays of consecutive positions of a frame, that frameSweep runs between; for a
/// riffled frame riffledFrameSpans.
std::vector<RaySpan> frameSpans(const FuselageFrame& fuselage, const schema::FrameType& frame);

/// Where a riffled frame (positions at several stations) runs between two positions: the
/// schema does not say, so as the reference library draws it. The two positions' rays and the
/// ray from their reference points' middle at their mean angle meet the skin at three points;
/// the frame runs from the first to the middle one along the skin's section by the plane through
/// them and the point three quarters of the way from the first reference point to the second,
/// then on to the last one along the section by the plane through them and the point a quarter
/// of the way (each half the skin's conic projection of a chord from that point). Two spans of
/// rays per pair of positions, each sharing one origin. Throws Error naming the position whose
/// ray misses the skin.
std::vector<RaySpan> riffledFrameSpans(const FuselageFrame& fuselage, const schema::FrameType& frame);

/// The rays all round a frame of one position in its station plane, from its reference point:
/// four quarter turns.
std::vector<RaySpan> ringSpans(const FuselageFrame& fuselage, const schema::FrameType& frame);

}  // namespace airshape::structure
