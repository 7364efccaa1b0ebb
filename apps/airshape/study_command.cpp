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

/// The folder holding the package `airshape` with its study engine: the installed one beside
/// this program (PREFIX/bin and PREFIX/<install dir>), else the build tree's.
std::filesystem::path pythonPackageFolder() {
  std::error_code ignored;
  const std::filesystem::path program = std::filesystem::canonical("/proc/self/exe", ignored);
  const std::vector<std::filesystem::path> candidates = {
      program.parent_path().parent_path() / AIRSHAPE_INSTALLED_PYTHON_DIR, AIRSHAPE_BUILD_PYTHON_DIR};
  for (const std::filesystem::path& folder : candidates)
    if (std::filesystem::exists(folder / "airshape" / "study" / "__main__.py", ignored)) return folder;
  throw Error(ErrorCode::NotImplemented,
              "study: the Python package airshape is not beside this program (it is built with the Python "
              "bindings: python3-dev, pybind11-dev)");
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
