#pragma once

#include <string>

#include <TopoDS_Shape.hxx>

namespace airshape::generic {

/// The shape a STEP, IGES or BREP file holds, in metres (a STEP or IGES file is read in the
/// unit it declares). `link` is the file's path as CPACS gives it, relative to the folder of
/// `cpacsFile`; `format` the linkToFile's format attribute ("Step", "Iges", "Brep", any
/// case). The file is only read. Throws Error naming `xpath` when the format is missing or
/// unknown, or the file is missing or unreadable.
TopoDS_Shape readExternalFile(const std::string& cpacsFile, const std::string& link, const std::string& format,
                              const std::string& xpath);

}  // namespace airshape::generic
