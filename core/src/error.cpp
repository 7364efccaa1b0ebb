#include "airshape/error.h"

namespace airshape {
namespace {

// "file: /cpacs/path: message" with the parts that are known.
std::string oneLine(const std::string& message, const std::string& file, const std::string& cpacsPath) {
  std::string line;
  if (!file.empty()) line += file + ": ";
  if (!cpacsPath.empty()) line += cpacsPath + ": ";
  return line + message;
}

}  // namespace

Error::Error(ErrorCode code, const std::string& message, std::string file, std::string cpacsPath)
    : std::runtime_error(oneLine(message, file, cpacsPath)),
      code_(code),
      message_(message),
      file_(std::move(file)),
      cpacsPath_(std::move(cpacsPath)) {}

Error Error::inFile(const std::string& file) const {
  return file_.empty() ? Error(code_, message_, file, cpacsPath_) : *this;
}

}  // namespace airshape
