#pragma once

#include <string>
#include <vector>

#include <xercesc/util/XercesDefs.hpp>

XERCES_CPP_NAMESPACE_BEGIN
class DOMElement;
XERCES_CPP_NAMESPACE_END

namespace airshape::schema {

class Visitor;

/// One element of a CPACS document as seen through the generated, typed model.
///
/// Generated classes derive from Node; each describes its attributes and child
/// elements to a Visitor, so reading, writing and validating are written once
/// (in the visitors) instead of once per schema type.
class Node {
 public:
  Node() = default;
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;
  virtual ~Node() = default;

  /// Presents every attribute and child element of this node to the visitor, in schema order.
  virtual void visit(Visitor& visitor) = 0;

  /// The name of the schema type this node was generated from, e.g. "wingType".
  virtual const char* schemaType() const = 0;

  /// The DOM element this node was read from or written to; nullptr for a node made in memory.
  xercesc::DOMElement* binding = nullptr;

  /// The CPACS path of the element, e.g. /cpacs/vehicles/aircraft/model[1]/systems[1].
  std::string xpath;

  /// Field indices of required values that the document did not contain. The writer leaves
  /// them out again unless they were set since, so a flawed file is saved as it was.
  std::vector<unsigned short> absentOnRead;

  /// Child elements the model leaves out although the schema has a place for them (such as a
  /// repeated uID's later definitions). The writer keeps them in the document as they are.
  std::vector<xercesc::DOMElement*> setAside;
};

}  // namespace airshape::schema
