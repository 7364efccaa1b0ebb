#include "output_paths.h"

#include <filesystem>

#include "airshape/error.h"

namespace airshape::cli {

void refuseUnwritableOutputs(const std::vector<std::string>& outputs, bool force) {
  for (const std::string& output : outputs) {
    std::error_code error;
    const std::filesystem::path folder = std::filesystem::path(output).parent_path();
    if (!folder.empty() && !std::filesystem::is_directory(folder, error))
      throw Error(ErrorCode::WriteFailed, "cannot write: folder " + folder.string() + " does not exist", output);
    if (!force && std::filesystem::exists(output, error))
      throw Error(ErrorCode::WriteFailed, "exists already; use --force to replace it", output);
  }
}

}  // namespace airshape::cli
