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

  /// "xpath: message" on one line, the form used on stderr and by `airshape validate`: a line
  /// break that a uID or a name brought into the message is written as \n.
  std::string describe() const {
    std::string line = xpath + ": ";
    for (const char c : message)
      line += c == '\n' ? std::string("\\n") : c == '\r' ? std::string("\\r") : std::string(1, c);
    return line;
  }
};

using Problems = std::vector<Problem>;

}  // namespace airshape
