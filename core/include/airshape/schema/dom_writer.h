#pragma once

#include "airshape/schema/node.h"

namespace airshape::schema {

/// Writes the values of `node` and its children back into the DOM element it is bound to.
/// Text that already holds the same value is left as it is, so an unedited model writes
/// nothing and the document keeps its exact formatting. New children are inserted in
/// schema order; children removed from the model are removed from the document.
void writeNode(Node& node, xercesc::DOMElement& element);

}  // namespace airshape::schema
