#pragma once

#include <string>

#include <xercesc/util/XercesDefs.hpp>

XERCES_CPP_NAMESPACE_BEGIN
class DOMElement;
XERCES_CPP_NAMESPACE_END

namespace airshape::xml {

/// What an XPath addresses: an element, or one of its attributes.
struct XPathTarget {
  xercesc::DOMElement* element = nullptr;
  std::string attribute;  ///< empty: the element itself (its text)
};

/// Resolves the absolute XPaths CPACS tools use, from the document's root element:
/// `/cpacs/vehicles/aircraft/model[1]/systems/genericSystems/genericSystem[@uID='S']/name`,
/// ending in an element or in `/@attribute`. A step is a name with at most one predicate, a
/// 1-based position `[k]` or an attribute test `[@name='value']` (or "value"); without a
/// predicate it takes the first element of that name. Throws Error(InvalidArgument)
/// naming the path and the first step that matches nothing.
XPathTarget resolveXPath(xercesc::DOMElement& root, const std::string& xpath);

}  // namespace airshape::xml
