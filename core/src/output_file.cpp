#include "airshape/output_file.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#include "airshape/error.h"

namespace airshape {

namespace fs = std::filesystem;

namespace {

Error writeFailed(const std::string& reason, const std::string& path) {
  return Error(ErrorCode::WriteFailed, "cannot write: " + reason, path);
}

/// A fresh folder named ".<file name>.XXXXXX" next to the target.
fs::path makeTemporaryFolder(const fs::path& folder, const fs::path& target) {
  std::string pattern = (folder / ("." + target.filename().string() + ".XXXXXX")).string();
  if (::mkdtemp(pattern.data()) == nullptr) throw writeFailed(std::strerror(errno), target.string());
  return pattern;
}

/// Moves what the writer left in `temporary` next to `target`: side files first, so that
/// the target's name only ever shows a file whose companions are there.
void moveIntoPlace(const fs::path& temporary, const fs::path& target) {
  const fs::path written = temporary / target.filename();
  if (!fs::exists(written)) throw writeFailed("the writer produced no file", target.string());
  std::vector<fs::path> sideFiles;
  for (const auto& entry : fs::directory_iterator(temporary))
    if (entry.path() != written) sideFiles.push_back(entry.path());
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  for (const fs::path& side : sideFiles)
    if (::rename(side.c_str(), (folder / side.filename()).c_str()) != 0)
      throw writeFailed(std::strerror(errno), (folder / side.filename()).string());
  if (::rename(written.c_str(), target.c_str()) != 0) throw writeFailed(std::strerror(errno), target.string());
}

void writeAll(int fd, const std::string& content, const std::string& path) {
  const char* data = content.data();
  std::size_t size = content.size();
  while (size > 0) {
    const ssize_t written = ::write(fd, data, size);
    if (written < 0) throw writeFailed(std::strerror(errno), path);
    data += written;
    size -= static_cast<std::size_t>(written);
  }
  if (::fsync(fd) != 0) throw writeFailed(std::strerror(errno), path);
}

}  // namespace

void writeFileSafely(const std::string& path, const std::function<void(const std::string& temporaryPath)>& write) {
  const fs::path target(path);
  if (target.filename().empty()) throw writeFailed("no file name", path);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code error;
  if (!fs::is_directory(folder, error)) throw writeFailed("folder " + folder.string() + " does not exist", path);
  if (fs::is_directory(target, error)) throw writeFailed("it is a folder", path);
  const fs::path temporary = makeTemporaryFolder(folder, target);
  try {
    write((temporary / target.filename()).string());
    moveIntoPlace(temporary, target);
  } catch (...) {
    fs::remove_all(temporary, error);
    throw;
  }
  fs::remove_all(temporary, error);
}

void writeTextFileSafely(const std::string& path, const std::string& content) {
  writeFileSafely(path, [&](const std::string& temporaryPath) {
    const int fd = ::open(temporaryPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) throw writeFailed(std::strerror(errno), path);
    try {
      writeAll(fd, content, path);
    } catch (...) {
      ::close(fd);
      throw;
    }
    if (::close(fd) != 0) throw writeFailed(std::strerror(errno), path);
  });
}

}  // namespace airshape
