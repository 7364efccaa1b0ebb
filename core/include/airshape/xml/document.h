#pragma once

#include <memory>
#include <string>

#include <xercesc/util/XercesDefs.hpp>

XERCES_CPP_NAMESPACE_BEGIN
class DOMDocument;
class DOMElement;
class DOMNode;
XERCES_CPP_NAMESPACE_END

namespace airshape::xml {

/// An XML document held as a Xerces-C DOM. The whole document is kept, including
/// everything the typed model does not know, so saving it loses nothing.
class Document {
 public:
  /// Parses a file (or takes it from a ReadAhead of that path, read_ahead.h). Throws Error
  /// (FileNotFound, NotXml) naming the file and the line.
  static Document fromFile(const std::string& path);
  /// Reads and parses a file here and now, whatever is read ahead.
  static Document readFile(const std::string& path);
  /// Parses a string; `name` stands for the source in error messages.
  static Document fromString(const std::string& text, const std::string& name = "<string>");

  Document(Document&&) noexcept;
  Document& operator=(Document&&) noexcept;
  ~Document();

  xercesc::DOMDocument& dom() const;
  xercesc::DOMElement* root() const;
  /// The file (or name) the document came from.
  const std::string& source() const { return source_; }

  /// The document as UTF-8 XML text.
  std::string toString() const;
  /// Writes the document atomically: to a temporary file beside `path`, then renamed over it.
  /// Throws Error(WriteFailed) and leaves no partial file under `path`.
  void save(const std::string& path) const;

 private:
  struct Impl;
  explicit Document(std::unique_ptr<Impl> impl, std::string source);
  std::unique_ptr<Impl> impl_;
  std::string source_;
};

/// A node (a whole document, or an element with all it holds) as UTF-8 XML text.
std::string serialized(const xercesc::DOMNode& node);

}  // namespace airshape::xml
