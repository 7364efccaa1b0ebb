#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <IntCurvesFace_ShapeIntersector.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Dir.hxx>
#include <gp_Pln.hxx>
#include <gp_Pnt.hxx>

#include "airshape/model/placement.h"
#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::structure {

/// A fuselage as its structure sees it: positions in fuselage coordinates carried to the
/// global frame, its clean solid (the fuselage plugin's component shape) and the geometry the
/// structure elements are placed on.
class FuselageFrame {
 public:
  FuselageFrame(const Configuration& configuration, const schema::FuselageType& fuselage);
  /// Any body structure is positioned in, by its component uID (a fuselage, a tank's vessel):
  /// placed by `toGlobal`, its solid the component's shape; `body` its sections and segments
  /// (null for a vessel of design parameters, which has none to place positions on).
  FuselageFrame(const Configuration& configuration, const std::string& hostUid, const schema::FuselageType* body,
                const model::Transform& toGlobal);

  /// The body a structure element is positioned in: its fuselage, or (with a placement) a
  /// tank's vessel.
  static FuselageFrame ofHost(const Configuration& configuration, const std::string& hostUid,
                              const schema::FuselageType* body, const std::optional<model::Transform>& vesselPlacement);

  gp_Pnt toGlobal(const gp_Pnt& point) const;
  /// A global point in fuselage coordinates.
  gp_Pnt toLocal(const gp_Pnt& point) const;
  /// A direction in fuselage coordinates as a global direction.
  gp_Dir toGlobal(const gp_Dir& direction) const;
  const TopoDS_Shape& solid() const { return solid_; }
  /// The diagonal of the solid's bounding box: longer than any line across the fuselage.
  double reach() const { return reach_; }
  /// The same length measured in fuselage coordinates (however the fuselage is scaled).
  double localReach() const;
  /// The faces of the fuselage's skin (its shape's faces named `.../skin`, no end caps; all the
  /// faces of a body that names none so, as a tank's vessel).
  const std::vector<TopoDS_Face>& skinFaces() const;

  /// A stringer or frame position's station: its positionX, or the x (fuselage coordinates) of
  /// the centre of the section its section element belongs to. Throws Error naming the position
  /// for an element the body does not have, and naming the element for a position number
  /// (positionX, referenceY, referenceZ, referenceAngle) that is not finite.
  double positionX(const schema::StringerFramePositionType& position) const;
  /// The first position of a frame that lies at another station than its first position (a
  /// riffled frame), or null when all share one.
  const schema::StringerFramePositionType* offFirstStation(const schema::FrameType& frame) const;
  /// The station of a frame whose positions all lie at one x (fuselage coordinates); throws Error
  /// naming the frame for a frame without positions and the position for a riffled frame.
  double stationX(const schema::FrameType& frame) const;
  /// The plane x = stationX(frame) (global), through the first position's reference point.
  gp_Pln station(const schema::FrameType& frame) const;
  /// Where the ray from `from` along `direction` (global) first meets the fuselage's skin;
  /// throws Error naming `where` when it meets none.
  gp_Pnt skinAhead(const gp_Pnt& from, const gp_Dir& direction, const std::string& where) const;

  /// The parts of the plane through `origin` with this normal (global) inside the solid.
  std::vector<TopoDS_Face> crossSection(const gp_Pnt& origin, const gp_Dir& normal) const;
  /// The face of the fuselage at a section (an end cap of a segment starting or ending there).
  /// Throws Error naming `where` when no segment of the fuselage meets that section.
  TopoDS_Face sectionFace(const std::string& sectionUid, const std::string& where) const;
  /// Where the line through `point` along the fuselage's x axis meets `shape`, which it must
  /// meet exactly once; otherwise throws Error naming `where`.
  gp_Pnt alongXOnto(const TopoDS_Shape& shape, const gp_Pnt& point, const std::string& where) const;

 private:
  const Configuration& configuration_;
  const schema::FuselageType* body_;
  model::Transform toGlobal_;
  TopoDS_Shape solid_;
  std::vector<TopoDS_Face> skin_;
  double reach_ = 0.0;
  mutable std::shared_ptr<IntCurvesFace_ShapeIntersector> skinIntersector_;  ///< loaded on first use
};

}  // namespace airshape::structure
