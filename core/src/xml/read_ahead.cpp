#include "airshape/xml/read_ahead.h"

#include <future>
#include <mutex>

namespace airshape::xml {

namespace {

/// The one pending read: its path and the parse under way.
struct PendingRead {
  std::mutex mutex;
  std::string path;
  std::future<Document> document;
};

PendingRead& pending() {
  static PendingRead read;
  return read;
}

}  // namespace

ReadAhead::ReadAhead(const std::string& path) {
  PendingRead& read = pending();
  const std::lock_guard<std::mutex> lock(read.mutex);
  if (read.document.valid()) return;  // one at a time
  read.path = path;
  read.document = std::async(std::launch::async, [path] { return Document::readFile(path); });
}

ReadAhead::~ReadAhead() {
  PendingRead& read = pending();
  std::future<Document> unused;
  {
    const std::lock_guard<std::mutex> lock(read.mutex);
    unused = std::move(read.document);
    read.path.clear();
  }
  if (unused.valid()) unused.wait();  // its document (or error) is dropped with it
}

std::optional<Document> takeReadAhead(const std::string& path) {
  PendingRead& read = pending();
  std::future<Document> document;
  {
    const std::lock_guard<std::mutex> lock(read.mutex);
    if (!read.document.valid() || read.path != path) return std::nullopt;
    document = std::move(read.document);
    read.path.clear();
  }
  return document.get();
}

}  // namespace airshape::xml
