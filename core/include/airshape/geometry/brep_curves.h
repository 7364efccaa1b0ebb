#pragma once

#include <chrono>
#include <string>
#include <vector>

#include <Geom_BSplineCurve.hxx>
#include <TopoDS_Shape.hxx>

namespace airshape::geometry {

/// The curves of every edge of a BREP file, in file order, as B-splines (trimmed to their
/// edges). Throws Error naming the file when it cannot be read or holds no edges. A child
/// process reads the file first (OCCT's reader crashes or loops forever on some damaged
/// files); it gets `readTimeout`, or when that is zero 10 s and 10 s more per MiB.
std::vector<Handle(Geom_BSplineCurve)> readBrepCurves(const std::string& path,
                                                      std::chrono::milliseconds readTimeout = {});

/// Writes one shape to a BREP file atomically. Throws Error(WriteFailed).
void writeBrep(const TopoDS_Shape& shape, const std::string& path);

}  // namespace airshape::geometry
