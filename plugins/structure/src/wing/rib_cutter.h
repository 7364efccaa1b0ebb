#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <TopoDS_Face.hxx>
#include <gp_Pln.hxx>

#include "airshape/geometry/polyline.h"
#include "airshape/geometry/skin_trace.h"
#include "airshape/schema/generated/cpacs_model.h"
#include "spar_web.h"
#include "structure_frame.h"

namespace airshape::structure {

/// Whether a rib's start, end or reference is the wing's leading or trailing edge (not a spar):
/// `leadingEdge` or `trailingEdge`, or as some files shorten them (D150's flap ribs), `le` or
/// `te`.
bool isWingEdge(const std::string& name);
/// Whether such a name is the leading edge's.
bool isLeadingEdge(const std::string& name);
/// CPACS names compared as the reference library compares them: ignoring case.
bool sameName(const std::string& a, const char* b);

/// A rib's plane between its start and end border: the plane face reaching beyond the wing
/// (global frame) that a Boolean cut trims to the component segment, and the lines along the
/// rib's up direction with its borders (where the rib meets a spar's web, or open where it
/// runs to the leading or trailing edge), from which the rib is made straight from the skins
/// where they allow it.
struct RibOutline {
  TopoDS_Face face;
  geometry::CrossingLines lines;
  geometry::CrossingEnd start, end;
};

/// What rib definitions of one component segment share: their reference lines, their start
/// and end points, and cutting a rib out of the component segment between its borders.
class RibCutter {
 public:
  RibCutter(const Configuration& configuration, const StructureFrame& frame,
            const schema::WingComponentSegmentStructureType& structure);

  /// A rib's start or end point (wing frame) given by eta and xsi, on a line, or at a spar position.
  gp_Pnt pointOf(const schema::Child<schema::EtaXsiPointType>& etaXsi,
                 const schema::Child<schema::CurvePointType>& curve, const std::optional<std::string>& sparPosition,
                 const std::string& where) const;

  /// Where the plane (global frame) meets a spar's web: two points of that line, the lower
  /// first, each `reach` away from where it crosses the spar's line (global frame). Throws
  /// Error naming `where` when it does not meet it.
  std::vector<gp_Pnt> sparSection(const std::string& spar, const gp_Pln& plane, const std::string& where) const;

  /// The faces of the rib in the plane through `point` along `direction` (from its start to
  /// its end) and `up` (all wing frame): the part inside the component segment's solid
  /// between its start and end border (the wing's edges, or spar webs, carried along `up`).
  std::vector<TopoDS_Face> cut(const gp_Pnt& point, const gp_Vec& direction, const gp_Vec& up,
                               const std::string& ribStart, const std::string& ribEnd, const std::string& name,
                               const std::string& where) const;

  /// A rib's plane between its start and end border (global frame): what `cut` cuts out of
  /// the component segment's solid.
  RibOutline outline(const gp_Pnt& point, const gp_Vec& direction, const gp_Vec& up, const std::string& ribStart,
                     const std::string& ribEnd, const std::string& name, const std::string& where) const;

  /// Several ribs' outlines cut out of the component segment's (or device's) solid, named
  /// `names` (for the errors of ribs that do not cross it): those the skins give directly made
  /// from them (in a device: the wing's section in common with the device's cutter, in the
  /// rib's plane), the others by one Boolean common.
  std::vector<std::vector<TopoDS_Face>> cutAll(const std::vector<RibOutline>& outlines,
                                               const std::vector<std::string>& names, const std::string& where) const;

  /// Warns at `where` that a rib of a set is left out (`why`: which rib and why), the set's
  /// other ribs built.
  void warnLeftOut(const std::string& where, const std::string& why) const;

  const StructureFrame& frame() const { return frame_; }
  const Configuration& configuration() const { return configuration_; }

 private:
  std::vector<gp_Pnt> side(const std::string& border, const gp_Pnt& origin, const gp_Vec& outwards, const gp_Vec& up,
                           const gp_Pln& plane, const std::string& where) const;
  const std::pair<TopoDS_Shape, TopoDS_Shape>& skins() const;
  /// A rib's face straight from two skins where they allow it.
  std::optional<TopoDS_Face> sectionOf(const RibOutline& outline, const TopoDS_Shape& upper,
                                       const TopoDS_Shape& lower) const;
  /// A rib's faces where its plane is a section's plane of the skins (the profile there between
  /// its borders), made without a Boolean operation.
  std::optional<std::vector<TopoDS_Face>> inSection(const RibOutline& outline, const TopoDS_Shape& upper,
                                                    const TopoDS_Shape& lower) const;
  /// A rib's start or end as the end of a trace: the line where its plane meets a spar's web,
  /// or open at the wing's leading or trailing edge.
  geometry::CrossingEnd border(const std::string& name, const gp_Pln& plane, const std::string& where) const;

  const Configuration& configuration_;
  const StructureFrame& frame_;
  /// The walls of the spars ribs have met, by spar uID: placed once for a whole rib set.
  mutable std::map<std::string, SparWall> walls_;
  /// The component segment's upper and lower skin, fetched for the first rib made from them.
  mutable std::optional<std::pair<TopoDS_Shape, TopoDS_Shape>> skins_;
  const schema::WingComponentSegmentStructureType& structure_;
  double reach_;
};

}  // namespace airshape::structure
