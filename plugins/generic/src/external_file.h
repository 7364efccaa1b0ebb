#pragma once

#include <string>

#include <TopoDS_Shape.hxx>

namespace airshape {
class Configuration;
}

namespace airshape::generic {

/// The shape a STEP, IGES or BREP file holds, in metres (a STEP or IGES file is read in the
/// unit it declares), read once per configuration however many elements link it. `link` is
/// the file's path as CPACS gives it, relative to the folder of the configuration's file;
/// `format` the linkToFile's format attribute ("Step", "Iges", "Brep", any case). The file is
/// only read. Throws Error naming `xpath` when the format is missing or unknown, or the file
/// is missing or unreadable.
TopoDS_Shape readExternalFile(const Configuration& configuration, const std::string& link, const std::string& format,
                              const std::string& xpath);

}  // namespace airshape::generic
