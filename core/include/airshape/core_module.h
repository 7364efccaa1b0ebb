#pragma once

#include <string>

#include <boost/dll/shared_library.hpp>

namespace airshape {

/// The folder the core library was loaded from: where its modules and the built-in plugins lie.
std::string coreLibraryFolder();

/// A module beside the core library (coreLibraryFolder()), loaded now and kept to
/// itself: the parts that bring heavy libraries along (OCCT's data-exchange toolkits) live in
/// such modules so that only the processes that use them load them. Throws Error
/// (PluginFailed) naming the module's path and `what` it holds when it cannot be loaded.
boost::dll::shared_library loadCoreModule(const std::string& fileName, const std::string& what);

}  // namespace airshape
