// `airshape study`: design studies run in the Python package's study engine (airshape.study),
// which speaks to Dask's clusters; this command hands its arguments over to it.
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "airshape/error.h"
#include "commands.h"

namespace airshape::cli {

namespace {

/// Whether a folder holds the package `airshape` with its study engine and its compiled part.
bool holdsPythonPackage(const std::filesystem::path& folder) {
  std::error_code ignored;
  if (!std::filesystem::exists(folder / "airshape" / "study" / "__main__.py", ignored)) return false;
  for (const auto& entry : std::filesystem::directory_iterator(folder / "airshape", ignored))
    if (entry.path().filename().string().rfind("_airshape", 0) == 0 && entry.path().extension() == ".so") return true;
  return false;
}

/// The folder holding the package `airshape`: the installed one beside this program (PREFIX/bin
/// and PREFIX/<install dir>), else the build tree's.
std::filesystem::path pythonPackageFolder() {
  std::error_code ignored;
  const std::filesystem::path program = std::filesystem::canonical("/proc/self/exe", ignored);
  for (const std::filesystem::path& folder : {program.parent_path().parent_path() / AIRSHAPE_INSTALLED_PYTHON_DIR,
                                              std::filesystem::path(AIRSHAPE_BUILD_PYTHON_DIR)})
    if (holdsPythonPackage(folder)) return folder;
  throw Error(ErrorCode::NotImplemented,
              "study: the Python package airshape is not built beside this program: build it with "
              "`cmake --build build --target _airshape` (scripts/test.sh builds everything)");
}

}  // namespace

int runStudy(const Arguments& arguments, plugin::PluginHost&) {
  std::string path = pythonPackageFolder().string();
  if (const char* given = std::getenv("PYTHONPATH"); given != nullptr && *given != '\0')
    path += std::string(":") + given;
  ::setenv("PYTHONPATH", path.c_str(), 1);
  std::vector<std::string> words = {AIRSHAPE_PYTHON, "-m", "airshape.study"};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  ::execv(AIRSHAPE_PYTHON, argv.data());  // returns only when Python cannot be started
  throw Error(ErrorCode::NotImplemented,
              std::string("study: cannot start ") + AIRSHAPE_PYTHON + ": " + std::strerror(errno));
}

}  // namespace airshape::cli
