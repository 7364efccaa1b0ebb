#include "airshape/xml/nesting.h"

#include <algorithm>

#include <xercesc/dom/DOM.hpp>

#include "airshape/error.h"
#include "airshape/xml/text.h"

namespace airshape::xml {

using namespace xercesc;

std::size_t nestingDepth(const DOMElement& element) {
  // Walks the tree in document order with parent links instead of a call per level.
  std::size_t depth = 1;
  std::size_t deepest = 1;
  const DOMElement* current = &element;
  while (true) {
    if (const DOMElement* child = firstElement(*current)) {
      current = child;
      deepest = std::max(deepest, ++depth);
      continue;
    }
    while (current != &element && nextElement(*current) == nullptr) {
      current = static_cast<const DOMElement*>(current->getParentNode());
      --depth;
    }
    if (current == &element) return deepest;
    current = nextElement(*current);
  }
}

void requireNestingWithinLimit(const DOMElement& element, const std::string& source, std::size_t depthOfElement) {
  const std::size_t depth = depthOfElement - 1 + nestingDepth(element);
  if (depth > kMaximumNesting)
    throw Error(ErrorCode::NotXml,
                "elements are nested " + std::to_string(depth) + " levels deep; Airshape reads at most " +
                    std::to_string(kMaximumNesting) + " (CPACS needs fewer than 30)",
                source);
}

}  // namespace airshape::xml
