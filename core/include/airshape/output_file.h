#pragma once

#include <functional>
#include <string>

namespace airshape {

/// Writes `path` so that it appears complete or not at all: `write` is given a path with
/// the same file name inside a fresh hidden folder next to `path` and writes there (with
/// any side files it needs, such as a glTF's .bin); only when it returns are the files
/// moved into place, side files first, the file itself last. When `write` throws, or the
/// folder is missing or not writable, nothing is left behind and an Error(WriteFailed)
/// names `path` and the reason.
void writeFileSafely(const std::string& path, const std::function<void(const std::string& temporaryPath)>& write);

/// Writes `content` to `path` with writeFileSafely, flushed to disk before it is moved.
void writeTextFileSafely(const std::string& path, const std::string& content);

}  // namespace airshape
