#pragma once

#include <memory>
#include <optional>
#include <string>

#include <xercesc/dom/DOMElement.hpp>

#include "airshape/schema/dom_reader.h"
#include "airshape/xml/text.h"

namespace airshape::schema {

/// An element read into a schema node of its own, outside the document's model: parts of
/// layouts newer than the CPACS 3.5 schema the model is generated from (a model's fuel
/// elements of later CPACS versions), read into the 3.5 types they share.
/// What the type does not know is skipped; the node is bound to the element, which is left
/// unchanged.
template <class Node>
std::shared_ptr<Node> readElement(const xercesc::DOMElement& element, const std::string& xpath) {
  auto node = std::make_shared<Node>();
  ReadReport ignored;  // what the schema does not say is read as far as it goes
  readNode(const_cast<xercesc::DOMElement&>(element), *node, xpath, ignored);
  return node;
}

/// The first child of that name read so (readElement), or null without one.
template <class Node>
std::shared_ptr<Node> readChild(const xercesc::DOMElement& parent, const std::string& name, const std::string& xpath) {
  const xercesc::DOMElement* child = xml::firstChild(parent, name);
  return child == nullptr ? nullptr : readElement<Node>(*child, xpath + "/" + name);
}

/// The number the first child of that name holds; absent without the child. Throws
/// Error(InvalidModel) naming the child when its text is no finite number.
std::optional<double> numberIn(const xercesc::DOMElement& parent, const std::string& name, const std::string& xpath);

}  // namespace airshape::schema
