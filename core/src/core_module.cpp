#include "airshape/core_module.h"

#include <boost/dll/runtime_symbol_info.hpp>

#include "airshape/error.h"

namespace airshape {

std::string coreLibraryFolder() { return boost::dll::this_line_location().parent_path().string(); }

boost::dll::shared_library loadCoreModule(const std::string& fileName, const std::string& what) {
  const boost::dll::fs::path file = boost::dll::fs::path(coreLibraryFolder()) / fileName;
  boost::dll::fs::error_code error;
  boost::dll::shared_library loaded(file, boost::dll::load_mode::rtld_now | boost::dll::load_mode::rtld_local, error);
  if (error) throw Error(ErrorCode::PluginFailed, "cannot load " + what + ": " + error.message(), file.string());
  return loaded;
}

}  // namespace airshape
