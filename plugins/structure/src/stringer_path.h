#pragma once

#include <string>
#include <vector>

#include <TopoDS_Face.hxx>
#include <gp_Dir.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape::structure {

class FuselageFrame;

/// Where a fuselage stringer runs: at each of its positions a ray in the plane x = positionX
/// from the reference point (referenceY, referenceZ) at the reference angle about the x axis
/// (0° up, 90° towards −y) meets the skin; between two positions the rays sweep the ruled
/// surface between them, and the stringer is where that surface meets the skin. Before its first
/// and after its last position the stringer runs on along x with the ray of that position.
class StringerPath {
 public:
  /// Throws Error naming the position for positions placed by a section element (not built
  /// yet) and for a stringer without positions.
  explicit StringerPath(const schema::StringerType& stringer);

  /// A ray of the swept surface, in fuselage coordinates.
  struct Ray {
    gp_Pnt origin;
    gp_Vec direction;  ///< unit length at the positions, blended linearly between them
  };
  /// The ray at station x (fuselage coordinates).
  Ray rayAt(double x) const;
  /// The swept surface from station `fromX` to `toX`, in the global frame, its rays `length` long.
  std::vector<TopoDS_Face> surface(const FuselageFrame& fuselage, double fromX, double toX, double length) const;
  const std::string& uid() const { return uid_; }

 private:
  std::string uid_;
  std::vector<Ray> positions_;  ///< sorted by x
};

}  // namespace airshape::structure
