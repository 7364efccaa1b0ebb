#include "airshape/geometry/brep_curves.h"

#include <cstdio>
#include <filesystem>
#include <sstream>

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GeomConvert.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "airshape/error.h"
#include "airshape/isolated_call.h"

namespace airshape::geometry {

namespace {

/// A timeout in seconds as messages show it: 10, 0.5.
std::string secondsOf(std::chrono::milliseconds timeout) {
  std::ostringstream text;
  text << static_cast<double>(timeout.count()) / 1000.0;
  return text.str();
}

bool readBrep(const std::string& path, TopoDS_Shape& shape) {
  BRep_Builder builder;
  return BRepTools::Read(shape, path.c_str(), builder) && !shape.IsNull();
}

/// Reads a BREP file only after a child process has read it unharmed: OCCT's reader crashes
/// on some damaged files (a trimmed curve around a curve it failed to read) and loops forever
/// on others (a tolerance line missing), and neither can be caught in this process.
TopoDS_Shape readBrepSafely(const std::string& path, std::chrono::milliseconds timeout) {
  std::error_code error;
  const auto megabytes = static_cast<long>(std::filesystem::file_size(path, error) >> 20);
  if (timeout.count() == 0) timeout = std::chrono::seconds(10 + 10 * megabytes);  // sound files read at tens of MB/s
  const IsolatedResult probe = callIsolated(
      [&] {
        TopoDS_Shape shape;
        return readBrep(path, shape);
      },
      timeout);
  if (probe.outcome == IsolatedOutcome::Crashed)
    throw Error(ErrorCode::NotXml,
                "is a damaged BREP file: OCCT's reader crashed on it (signal " + std::to_string(probe.signal) + ")",
                path);
  if (probe.outcome == IsolatedOutcome::TimedOut)
    throw Error(ErrorCode::NotXml,
                "is a damaged BREP file: OCCT's reader did not finish within " + secondsOf(timeout) + " s", path);
  TopoDS_Shape shape;
  try {
    if (probe.outcome == IsolatedOutcome::Succeeded && readBrep(path, shape)) return shape;
  } catch (const Standard_Failure&) {
  }
  throw Error(ErrorCode::NotXml, "is not a readable BREP file", path);
}

}  // namespace

std::vector<Handle(Geom_BSplineCurve)> readBrepCurves(const std::string& path, std::chrono::milliseconds readTimeout) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) throw Error(ErrorCode::FileNotFound, "no such file", path);
  const TopoDS_Shape shape = readBrepSafely(path, readTimeout);
  std::vector<Handle(Geom_BSplineCurve)> curves;
  for (TopExp_Explorer edges(shape, TopAbs_EDGE); edges.More(); edges.Next()) {
    double first = 0.0, last = 0.0;
    Handle(Geom_Curve) curve = BRep_Tool::Curve(TopoDS::Edge(edges.Current()), first, last);
    if (curve.IsNull()) throw Error(ErrorCode::InvalidArgument, "an edge has no 3D curve", path);
    Handle(Geom_BSplineCurve) bspline = Handle(Geom_BSplineCurve)::DownCast(curve);
    const bool whole = !bspline.IsNull() && std::abs(first - bspline->FirstParameter()) < 1e-12 &&
                       std::abs(last - bspline->LastParameter()) < 1e-12;
    try {
      curves.push_back(whole ? Handle(Geom_BSplineCurve)::DownCast(bspline->Copy())
                             : GeomConvert::CurveToBSplineCurve(new Geom_TrimmedCurve(curve, first, last)));
    } catch (const Standard_Failure& failure) {
      throw Error(ErrorCode::InvalidArgument,
                  "edge " + std::to_string(curves.size() + 1) + " cannot be taken as a B-spline curve (" +
                      failure.GetMessageString() + ")",
                  path);
    }
  }
  if (curves.empty()) throw Error(ErrorCode::InvalidArgument, "holds no edges", path);
  return curves;
}

void writeBrep(const TopoDS_Shape& shape, const std::string& path) {
  const std::filesystem::path target(path);
  const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : ".";
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error))
    throw Error(ErrorCode::WriteFailed, "cannot write: folder " + folder.string() + " does not exist", path);
  const std::string temporary = (folder / ("." + target.filename().string() + ".partial")).string();
  if (!BRepTools::Write(shape, temporary.c_str())) {
    std::remove(temporary.c_str());
    throw Error(ErrorCode::WriteFailed, "cannot write", path);
  }
  std::filesystem::rename(temporary, target, error);
  if (error) {
    std::remove(temporary.c_str());
    throw Error(ErrorCode::WriteFailed, "cannot write: " + error.message(), path);
  }
}

}  // namespace airshape::geometry
