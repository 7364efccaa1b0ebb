// The STEP and IGES readers of the generic plugin, in a module of their own
// (libairshape_generic_exchange.so, beside the plugins), loaded only when a file links a STEP or
// IGES file: OCCT's data-exchange toolkits are built with BIND_NOW on Debian, and loading them
// with the plugin cost every process about 20 ms.
#include <mutex>
#include <string>

#include <IGESControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <TopoDS_Shape.hxx>

namespace {

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

/// The module's entry: the shape of a "step" or "iges" file in metres, null when it holds none.
extern "C" __attribute__((visibility("default"))) void airshape_read_exchange_file(const std::string& kind,
                                                                                   const std::string& path,
                                                                                   TopoDS_Shape& shape) {
  shape = kind == "step" ? readInMetres<STEPControl_Reader>(path) : readInMetres<IGESControl_Reader>(path);
}
