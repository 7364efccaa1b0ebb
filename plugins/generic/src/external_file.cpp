#include "external_file.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <mutex>

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"

namespace airshape::generic {

namespace {

std::string lowerCase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

/// Reads with a STEP or IGES reader into metres. OCCT's unit of the session is a global
/// setting: it is set for the read (before and after constructing the reader, whose
/// constructor initialises it) and restored after, under a lock.
template <class Reader>
TopoDS_Shape readInMetres(const std::string& path) {
  static std::mutex settings;
  const std::lock_guard<std::mutex> lock(settings);
  const std::string before = Interface_Static::CVal("xstep.cascade.unit");
  Interface_Static::SetCVal("xstep.cascade.unit", "M");
  Reader reader;
  Interface_Static::SetCVal("xstep.cascade.unit", "M");
  const bool read = reader.ReadFile(path.c_str()) == IFSelect_RetDone;
  if (read) reader.TransferRoots();
  Interface_Static::SetCVal("xstep.cascade.unit", before.c_str());
  return read ? reader.OneShape() : TopoDS_Shape();
}

}  // namespace

TopoDS_Shape readExternalFile(const Configuration& configuration, const std::string& link, const std::string& format,
                              const std::string& xpath) {
  if (format.empty()) throw Error(ErrorCode::InvalidModel, "the linked file's format is not given", {}, xpath);
  const std::string kind = lowerCase(format);
  if (kind != "step" && kind != "iges" && kind != "brep")
    throw Error(ErrorCode::InvalidModel, "unknown file format '" + format + "' (Step, Iges or Brep)", {}, xpath);
  std::filesystem::path path(link);
  if (path.is_relative()) path = std::filesystem::path(configuration.source()).parent_path() / path;
  if (!std::ifstream(path).good())
    throw Error(ErrorCode::InvalidModel, "the linked file '" + path.string() + "' cannot be read", {}, xpath);
  return *configuration.cache().obtain<TopoDS_Shape>("external-file:" + kind + ":" + path.string(), [&] {
    TopoDS_Shape shape;
    if (kind == "step") shape = readInMetres<STEPControl_Reader>(path.string());
    if (kind == "iges") shape = readInMetres<IGESControl_Reader>(path.string());
    if (kind == "brep") {
      BRep_Builder builder;
      if (!BRepTools::Read(shape, path.string().c_str(), builder)) shape.Nullify();
    }
    if (shape.IsNull())
      throw Error(ErrorCode::InvalidModel, "the linked file '" + path.string() + "' holds no " + format + " shape", {},
                  xpath);
    return std::make_shared<const TopoDS_Shape>(shape);
  });
}

}  // namespace airshape::generic
