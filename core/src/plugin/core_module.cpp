#include "airshape/plugin/core_module.h"

#include "airshape/error.h"
#include "airshape/plugin/plugin_host.h"

namespace airshape::plugin {

boost::dll::shared_library loadCoreModule(const std::string& fileName, const std::string& what) {
  const boost::dll::fs::path file = boost::dll::fs::path(PluginHost::coreLibraryFolder()) / fileName;
  boost::dll::fs::error_code error;
  boost::dll::shared_library loaded(file, boost::dll::load_mode::rtld_now | boost::dll::load_mode::rtld_local, error);
  if (error) throw Error(ErrorCode::PluginFailed, "cannot load " + what + ": " + error.message(), file.string());
  return loaded;
}

}  // namespace airshape::plugin
