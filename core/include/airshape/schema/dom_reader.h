#pragma once

#include <string>
#include <vector>

#include "airshape/problem.h"
#include "airshape/schema/node.h"

namespace airshape::schema {

/// A uIDref found while reading: the referenced uID and where the reference stands.
struct UidReference {
  std::string uid;
  std::string xpath;
};

/// What reading a document into the model found besides the values themselves.
struct ReadReport {
  Problems problems;                     ///< every schema violation, with its XPath
  Problems unreadableValues;             ///< those of them whose value could not be read at all
  std::vector<UidReference> references;  ///< every uIDref of the modelled part
};

/// Fills `node` (and, recursively, its children) from `element`, binding each node to
/// its DOM element so that a later write changes only what was edited.
void readNode(xercesc::DOMElement& element, Node& node, const std::string& xpath, ReadReport& report);

}  // namespace airshape::schema
