#include "airshape/xml/text.h"

#include <xercesc/dom/DOM.hpp>

namespace airshape::xml {

using namespace xercesc;

std::string toUtf8(const XMLCh* text) {
  std::string out;
  if (text == nullptr) return out;
  for (const XMLCh* p = text; *p != 0; ++p) {
    char32_t code = *p;
    if (code >= 0xD800 && code < 0xDC00 && p[1] >= 0xDC00 && p[1] < 0xE000) {
      code = 0x10000 + ((code - 0xD800) << 10) + (p[1] - 0xDC00);  // a surrogate pair
      ++p;
    }
    if (code < 0x80) {
      out += static_cast<char>(code);
    } else if (code < 0x800) {
      out += static_cast<char>(0xC0 | (code >> 6));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
      out += static_cast<char>(0xE0 | (code >> 12));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (code >> 18));
      out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    }
  }
  return out;
}

std::u16string toXml(const std::string& utf8) {
  std::u16string out;
  out.reserve(utf8.size());
  for (std::size_t i = 0; i < utf8.size();) {
    const auto byte = static_cast<unsigned char>(utf8[i]);
    const int length = byte < 0x80 ? 1 : byte < 0xE0 ? 2 : byte < 0xF0 ? 3 : 4;
    char32_t code = length == 1 ? byte : length == 2 ? (byte & 0x1F) : length == 3 ? (byte & 0x0F) : (byte & 0x07);
    for (int k = 1; k < length && i + static_cast<std::size_t>(k) < utf8.size(); ++k)
      code = (code << 6) | (static_cast<unsigned char>(utf8[i + static_cast<std::size_t>(k)]) & 0x3F);
    i += static_cast<std::size_t>(length);
    if (code >= 0x10000) {
      code -= 0x10000;
      out += static_cast<char16_t>(0xD800 + (code >> 10));
      out += static_cast<char16_t>(0xDC00 + (code & 0x3FF));
    } else {
      out += static_cast<char16_t>(code);
    }
  }
  return out;
}

std::string name(const DOMElement& element) { return toUtf8(element.getTagName()); }

std::string text(const DOMElement& element) {
  std::string out;
  for (DOMNode* child = element.getFirstChild(); child != nullptr; child = child->getNextSibling()) {
    const auto type = child->getNodeType();
    if (type == DOMNode::TEXT_NODE || type == DOMNode::CDATA_SECTION_NODE) out += toUtf8(child->getNodeValue());
  }
  return out;
}

void setText(DOMElement& element, const std::string& value) {
  while (DOMNode* child = element.getFirstChild()) element.removeChild(child)->release();
  element.appendChild(element.getOwnerDocument()->createTextNode(toXml(value).c_str()));
}

bool hasAttribute(const DOMElement& element, const std::string& attribute) {
  return element.hasAttribute(toXml(attribute).c_str());
}

std::string attribute(const DOMElement& element, const std::string& attribute) {
  return toUtf8(element.getAttribute(toXml(attribute).c_str()));
}

namespace {

DOMElement* elementFrom(DOMNode* node) {
  while (node != nullptr && node->getNodeType() != DOMNode::ELEMENT_NODE) node = node->getNextSibling();
  return static_cast<DOMElement*>(node);
}

}  // namespace

DOMElement* firstElement(const DOMNode& parent) { return elementFrom(parent.getFirstChild()); }

DOMElement* nextElement(const DOMNode& element) { return elementFrom(element.getNextSibling()); }

DOMElement* firstChild(const DOMElement& parent, const std::string& childName) {
  const std::u16string wanted = toXml(childName);
  for (DOMElement* child = firstElement(parent); child != nullptr; child = nextElement(*child)) {
    if (wanted == child->getTagName()) return child;
  }
  return nullptr;
}

}  // namespace airshape::xml
