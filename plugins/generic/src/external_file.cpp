#include "external_file.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/core_module.h"

namespace airshape::generic {

namespace {

std::string lowerCase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

/// A STEP or IGES file's shape in metres, read by the exchange module (exchange_reader.cpp),
/// which is loaded on first use and kept.
TopoDS_Shape readExchangeFile(const std::string& kind, const std::string& path) {
  using Entry = void(const std::string&, const std::string&, TopoDS_Shape&);
  static const boost::dll::shared_library module =
      loadCoreModule("libairshape_generic_exchange.so", "the STEP and IGES reader");
  TopoDS_Shape shape;
  module.get<Entry>("airshape_read_exchange_file")(kind, path, shape);
  return shape;
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
    if (kind == "step" || kind == "iges") shape = readExchangeFile(kind, path.string());
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
