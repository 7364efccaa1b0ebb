#pragma once

#include <vector>

#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>

#include "airshape/export/export_scene.h"

namespace airshape::exporting {

/// Whether a scene holds lines: edges outside faces (stiffeners, beams).
bool hasLines(const ExportScene& scene);

/// Whether a shape has faces (not lines alone), and whether any component of a scene has.
bool hasFaces(const TopoDS_Shape& shape);
bool hasFaces(const ExportScene& scene);

/// A shape's lines as the mesher left them (triangulate() gives each edge outside the faces
/// its polyline): one list of points per edge, placed.
std::vector<std::vector<gp_Pnt>> polylinesOf(const TopoDS_Shape& shape);

}  // namespace airshape::exporting
