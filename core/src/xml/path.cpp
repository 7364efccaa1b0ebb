#include "airshape/xml/path.h"

#include <xercesc/dom/DOM.hpp>
#include <xercesc/util/XMLString.hpp>

#include "airshape/xml/text.h"

namespace airshape::xml {

using namespace xercesc;

bool equalsAscii(const XMLCh* tag, const char* ascii) {
  for (; *tag != 0 && *ascii != 0; ++tag, ++ascii) {
    if (*tag != static_cast<XMLCh>(static_cast<unsigned char>(*ascii))) return false;
  }
  return *tag == 0 && *ascii == 0;
}

std::string pathOf(const DOMElement& element) {
  std::string step = "/" + name(element);
  const DOMNode* parent = element.getParentNode();
  if (parent == nullptr || parent->getNodeType() != DOMNode::ELEMENT_NODE) return step;
  const auto& parentElement = static_cast<const DOMElement&>(*parent);
  int index = 0;
  int count = 0;
  for (const DOMElement* sibling = firstElement(parentElement); sibling != nullptr; sibling = nextElement(*sibling)) {
    if (XMLString::equals(sibling->getTagName(), element.getTagName())) {
      ++count;
      if (sibling == &element) index = count;
    }
  }
  if (count > 1) step += "[" + std::to_string(index) + "]";
  return pathOf(parentElement) + step;
}

}  // namespace airshape::xml
