#include "airshape/xml/document.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <xercesc/dom/DOM.hpp>
#include <xercesc/framework/MemBufFormatTarget.hpp>
#include <xercesc/framework/MemBufInputSource.hpp>
#include <xercesc/parsers/XercesDOMParser.hpp>
#include <xercesc/sax/ErrorHandler.hpp>
#include <xercesc/sax/SAXParseException.hpp>
#include <xercesc/util/PlatformUtils.hpp>

#include "airshape/error.h"
#include "airshape/output_file.h"
#include "airshape/xml/nesting.h"
#include "airshape/xml/read_ahead.h"
#include "airshape/xml/text.h"

namespace airshape::xml {

using namespace xercesc;
namespace fs = std::filesystem;

namespace {

void initializeXerces() {
  // Initialised once per process and never terminated: documents may outlive any scope.
  static const bool initialized = [] {
    XMLPlatformUtils::Initialize();
    return true;
  }();
  (void)initialized;
}

/// Keeps the first fatal error or error of a parse, with its position.
class FirstErrorHandler : public ErrorHandler {
 public:
  void warning(const SAXParseException&) override {}
  void error(const SAXParseException& e) override { record(e); }
  void fatalError(const SAXParseException& e) override { record(e); }
  void resetErrors() override { message_.clear(); }
  const std::string& message() const { return message_; }

 private:
  void record(const SAXParseException& e) {
    if (!message_.empty()) return;
    message_ = "not well-formed XML (line " + std::to_string(e.getLineNumber()) + ", column " +
               std::to_string(e.getColumnNumber()) + ": " + toUtf8(e.getMessage()) + ")";
  }
  std::string message_;
};

std::string readWholeFile(const std::string& path) {
  std::error_code error;
  if (!fs::exists(path, error)) throw Error(ErrorCode::FileNotFound, "no such file", path);
  if (fs::is_directory(path, error)) throw Error(ErrorCode::FileNotFound, "is a directory, not a file", path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorCode::FileNotFound, "cannot be opened for reading", path);
  std::string content(fs::file_size(path, error), '\0');
  in.read(content.data(), static_cast<std::streamsize>(content.size()));
  if (error || in.gcount() != static_cast<std::streamsize>(content.size()))
    throw Error(ErrorCode::FileNotFound, "cannot be read", path);
  return content;
}

}  // namespace

struct Document::Impl {
  std::unique_ptr<XercesDOMParser> parser;  // owns the DOM
};

Document::Document(std::unique_ptr<Impl> impl, std::string source)
    : impl_(std::move(impl)), source_(std::move(source)) {}
Document::Document(Document&&) noexcept = default;
Document& Document::operator=(Document&&) noexcept = default;
Document::~Document() = default;

Document Document::fromFile(const std::string& path) {
  if (std::optional<Document> readAhead = takeReadAhead(path)) return std::move(*readAhead);
  return readFile(path);
}

Document Document::readFile(const std::string& path) { return fromString(readWholeFile(path), path); }

Document Document::fromString(const std::string& text, const std::string& name) {
  initializeXerces();
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw Error(ErrorCode::NotXml, "is empty, not an XML document", name);
  auto impl = std::make_unique<Impl>();
  impl->parser = std::make_unique<XercesDOMParser>();
  XercesDOMParser& parser = *impl->parser;
  parser.setValidationScheme(XercesDOMParser::Val_Never);
  parser.setDoNamespaces(false);  // keep namespace declarations as plain attributes, as written
  parser.setLoadExternalDTD(false);
  parser.setCreateEntityReferenceNodes(false);
  parser.setCreateCommentNodes(true);
  FirstErrorHandler errors;
  parser.setErrorHandler(&errors);
  MemBufInputSource input(reinterpret_cast<const XMLByte*>(text.data()), text.size(), name.c_str());
  try {
    parser.parse(input);
  } catch (const XMLException& e) {
    throw Error(ErrorCode::NotXml, "cannot be parsed: " + toUtf8(e.getMessage()), name);
  } catch (const DOMException& e) {
    throw Error(ErrorCode::NotXml, "cannot be parsed: " + toUtf8(e.getMessage()), name);
  }
  if (!errors.message().empty()) throw Error(ErrorCode::NotXml, errors.message(), name);
  if (parser.getDocument() == nullptr || parser.getDocument()->getDocumentElement() == nullptr)
    throw Error(ErrorCode::NotXml, "has no root element", name);
  requireNestingWithinLimit(*parser.getDocument()->getDocumentElement(), name);
  parser.setErrorHandler(nullptr);
  return Document(std::move(impl), name);
}

DOMDocument& Document::dom() const { return *impl_->parser->getDocument(); }

DOMElement* Document::root() const { return dom().getDocumentElement(); }

std::string Document::toString() const { return serialized(dom()); }

std::string serialized(const DOMNode& node) {
  DOMImplementation* implementation = DOMImplementationRegistry::getDOMImplementation(u"LS");
  std::unique_ptr<DOMLSSerializer, void (*)(DOMLSSerializer*)> serializer(
      static_cast<DOMImplementationLS*>(implementation)->createLSSerializer(),
      [](DOMLSSerializer* s) { s->release(); });
  std::unique_ptr<DOMLSOutput, void (*)(DOMLSOutput*)> output(
      static_cast<DOMImplementationLS*>(implementation)->createLSOutput(), [](DOMLSOutput* o) { o->release(); });
  MemBufFormatTarget target;
  output->setByteStream(&target);
  output->setEncoding(u"UTF-8");
  serializer->write(&node, output.get());
  return std::string(reinterpret_cast<const char*>(target.getRawBuffer()), target.getLen());
}

void Document::save(const std::string& path) const { writeTextFileSafely(path, toString()); }

}  // namespace airshape::xml
