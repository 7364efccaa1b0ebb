#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace airshape {

/// What kind of failure an Error reports; the C API and the CLI map these to status codes.
enum class ErrorCode {
  FileNotFound,        ///< the input file does not exist or cannot be read
  NotXml,              ///< the input is not well-formed XML
  NotCpacs,            ///< well-formed XML, but not a CPACS document
  UnsupportedVersion,  ///< a CPACS document of a version other than 3.x
  InvalidModel,        ///< the document breaks a rule the geometry needs (dangling uIDref, cycle, ...)
  InvalidArgument,     ///< a caller's argument is out of range or names nothing
  WriteFailed,         ///< an output file could not be written
  PluginFailed,        ///< a plugin could not be loaded or registered
  NotImplemented,      ///< the request needs a builder that does not exist yet
};

/// The one exception type of Airshape: a code, a message, and where it happened
/// (the file and the CPACS path of the offending node, when known).
class Error : public std::runtime_error {
 public:
  Error(ErrorCode code, const std::string& message, std::string file = {}, std::string cpacsPath = {});

  ErrorCode code() const { return code_; }
  /// The message alone, without file and path.
  const std::string& message() const { return message_; }
  const std::string& file() const { return file_; }
  const std::string& cpacsPath() const { return cpacsPath_; }

  /// The same error, now naming the file it happened in (if it named none).
  Error inFile(const std::string& file) const;

 private:
  ErrorCode code_;
  std::string message_;
  std::string file_;
  std::string cpacsPath_;
};

/// A component that exists but has no shape (an element placed without a body, a lofted component without
/// segments): measures refuse it with this error, the configuration's box leaves it out.
class NoShape : public Error {
 public:
  NoShape(const std::string& message, std::string cpacsPath)
      : Error(ErrorCode::InvalidModel, message, {}, std::move(cpacsPath)) {}
};

}  // namespace airshape
