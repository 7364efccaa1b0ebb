#include "xde_module.h"

#include "airshape/core_module.h"

namespace airshape::exporting {

void writeWithXcaf(const std::string& format, const ExportScene& scene, const std::string& path,
                   const std::string& target) {
  using Entry = void(const std::string&, const ExportScene&, const std::string&, const std::string&);
  static const boost::dll::shared_library module =
      loadCoreModule("libairshape_export_xde.so", "the XCAF-based writers");
  module.get<Entry>("airshape_write_with_xcaf")(format, scene, path, target);
}

}  // namespace airshape::exporting
