#pragma once

#include <memory>
#include <ostream>
#include <streambuf>

namespace airshape {

/// The process's standard output kept for a command's own answers while this lives: whatever
/// libraries print there (OCCT writes some diagnostics to standard output) goes to standard
/// error instead, so that a protocol spoken on standard output (`airshape query`: one JSON
/// answer per line) stays readable. Where the descriptors cannot be rearranged, `answers()` is
/// std::cout itself.
class ProtectedOutput {
 public:
  ProtectedOutput();
  ~ProtectedOutput();
  ProtectedOutput(const ProtectedOutput&) = delete;
  ProtectedOutput& operator=(const ProtectedOutput&) = delete;

  /// The stream to write answers to: the original standard output.
  std::ostream& answers() { return answers_; }

 private:
  int original_ = -1;  ///< a duplicate of the original standard output, or -1
  std::unique_ptr<std::streambuf> buffer_;
  std::ostream answers_;
};

}  // namespace airshape
