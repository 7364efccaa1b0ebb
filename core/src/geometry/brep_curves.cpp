#include "airshape/geometry/brep_curves.h"

#include <cstdio>
#include <filesystem>

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GeomConvert.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "airshape/error.h"

namespace airshape::geometry {

std::vector<Handle(Geom_BSplineCurve)> readBrepCurves(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) throw Error(ErrorCode::FileNotFound, "no such file", path);
  TopoDS_Shape shape;
  BRep_Builder builder;
  if (!BRepTools::Read(shape, path.c_str(), builder) || shape.IsNull())
    throw Error(ErrorCode::NotXml, "is not a readable BREP file", path);
  std::vector<Handle(Geom_BSplineCurve)> curves;
  for (TopExp_Explorer edges(shape, TopAbs_EDGE); edges.More(); edges.Next()) {
    double first = 0.0, last = 0.0;
    Handle(Geom_Curve) curve = BRep_Tool::Curve(TopoDS::Edge(edges.Current()), first, last);
    if (curve.IsNull()) throw Error(ErrorCode::InvalidArgument, "an edge has no 3D curve", path);
    Handle(Geom_BSplineCurve) bspline = Handle(Geom_BSplineCurve)::DownCast(curve);
    const bool whole = !bspline.IsNull() && std::abs(first - bspline->FirstParameter()) < 1e-12 &&
                       std::abs(last - bspline->LastParameter()) < 1e-12;
    if (whole) {
      curves.push_back(Handle(Geom_BSplineCurve)::DownCast(bspline->Copy()));
    } else {
      curves.push_back(GeomConvert::CurveToBSplineCurve(new Geom_TrimmedCurve(curve, first, last)));
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
