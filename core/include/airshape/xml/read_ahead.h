#pragma once

#include <optional>
#include <string>

#include "airshape/xml/document.h"

namespace airshape::xml {

/// Reads and parses a file on another thread while its owner does other work (the airshape
/// command loads its plugins meanwhile: tens of milliseconds each, so a large file is open
/// when they are). The next Document::fromFile of the same path takes the document, or the
/// error reading it, instead of reading again. One read ahead at a time; the destructor waits
/// for the thread and drops a document nobody took.
class ReadAhead {
 public:
  explicit ReadAhead(const std::string& path);
  ~ReadAhead();
  ReadAhead(const ReadAhead&) = delete;
  ReadAhead& operator=(const ReadAhead&) = delete;
};

/// The document read ahead for `path`, once (a second call finds none); rethrows the Error of
/// reading it.
std::optional<Document> takeReadAhead(const std::string& path);

}  // namespace airshape::xml
