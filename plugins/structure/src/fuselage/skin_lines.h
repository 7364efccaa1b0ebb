#pragma once

#include <optional>
#include <string>
#include <vector>

#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include "airshape/named_shape.h"
#include "airshape/tank/tank_services.h"
#include "position_rays.h"

namespace airshape {
class Configuration;
}

namespace airshape::structure {

class FuselageFrame;

/// A piece of a line on a body's skin: an edge and the skin face it lies on.
struct SkinEdge {
  TopoDS_Edge edge;
  TopoDS_Face face;
};

/// A frame of a fuselage (or of a tank's vessel, found through `tanks` when given) as the pieces of
/// the line it runs along on the skin: all round the fuselage in the plane x = positionX for a
/// frame of one position, otherwise where the surface its positions sweep (position_rays.h) meets
/// the skin. Throws Error naming the CPACS path when it cannot be built.
std::vector<SkinEdge> frameOnSkin(const Configuration& configuration, const tank::TankServices* tanks,
                                  const std::string& uid);

/// A fuselage stringer as the pieces of the line it runs along on the skin from its first to its
/// last position (position_rays.h). Throws Error naming the CPACS path when it cannot be built.
std::vector<SkinEdge> stringerOnSkin(const Configuration& configuration, const tank::TankServices* tanks,
                                     const std::string& uid);

/// Where the rays of the spans (position_rays.h) meet the fuselage's skin, drawn straight from
/// it: each ray met with the skin's faces by Newton's method as a half-line from its origin, the
/// line a curve in each face's own parameters that follows the crossing within 1e-8 of the
/// fuselage's size; consecutive edges share their vertices, and a line that comes back to where
/// it began closes. Nothing where the skin does not allow that (trimmed faces, a ray that misses
/// the skin or meets it twice); the caller then sections the skin.
std::optional<std::vector<SkinEdge>> raysOnSkin(const FuselageFrame& fuselage, const std::vector<RaySpan>& spans);

/// A frame (frameOnSkin) as its line: edges, no faces.
NamedShape frameLine(const Configuration& configuration, const tank::TankServices* tanks, const std::string& uid);

/// A stringer (stringerOnSkin) as its line: edges, no faces.
NamedShape stringerLine(const Configuration& configuration, const tank::TankServices* tanks, const std::string& uid);

}  // namespace airshape::structure
