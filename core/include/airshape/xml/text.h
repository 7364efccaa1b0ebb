#pragma once

#include <string>

#include <xercesc/util/XercesDefs.hpp>

XERCES_CPP_NAMESPACE_BEGIN
class DOMElement;
class DOMNode;
XERCES_CPP_NAMESPACE_END

namespace airshape::xml {

// Conversions between Xerces' UTF-16 strings and UTF-8 std::string, and small DOM helpers.

std::string toUtf8(const XMLCh* text);
std::u16string toXml(const std::string& utf8);

/// The element's tag name in UTF-8.
std::string name(const xercesc::DOMElement& element);
/// The concatenated text of the element's direct text and CDATA children.
std::string text(const xercesc::DOMElement& element);
/// Replaces the element's children by one text node.
void setText(xercesc::DOMElement& element, const std::string& text);
/// The attribute's value, or nullptr-like empty result when absent (check hasAttribute first).
bool hasAttribute(const xercesc::DOMElement& element, const std::string& attribute);
std::string attribute(const xercesc::DOMElement& element, const std::string& attribute);
/// The first child element, or nullptr. Faster than DOMElement::getFirstElementChild, which
/// goes through dynamic_cast for every node (a third of the time of opening a file).
xercesc::DOMElement* firstElement(const xercesc::DOMNode& parent);
/// The next sibling element, or nullptr.
xercesc::DOMElement* nextElement(const xercesc::DOMNode& element);
/// The first child element with that name, or nullptr.
xercesc::DOMElement* firstChild(const xercesc::DOMElement& parent, const std::string& name);

}  // namespace airshape::xml
