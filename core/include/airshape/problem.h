#pragma once

#include <string>
#include <vector>

namespace airshape {

/// One thing wrong with a document, located by the CPACS path (XPath) of the node.
struct Problem {
  enum class Severity { Error, Warning };
  Severity severity;
  std::string xpath;
  std::string message;

  /// "xpath: message", the form used on stderr and by `airshape validate`.
  std::string describe() const { return xpath + ": " + message; }
};

using Problems = std::vector<Problem>;

}  // namespace airshape
