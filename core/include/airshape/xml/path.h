#pragma once

#include <string>

#include <xercesc/util/XercesDefs.hpp>

XERCES_CPP_NAMESPACE_BEGIN
class DOMElement;
XERCES_CPP_NAMESPACE_END

namespace airshape::xml {

/// The XPath of an element from the root, with a 1-based [k] wherever siblings share its name.
std::string pathOf(const xercesc::DOMElement& element);

/// Whether the UTF-16 tag equals the ASCII name (no conversion, no allocation).
bool equalsAscii(const XMLCh* tag, const char* ascii);

}  // namespace airshape::xml
