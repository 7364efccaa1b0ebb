#pragma once

#include <xercesc/util/XercesDefs.hpp>

#include "airshape/schema/node.h"

namespace airshape::schema {

/// The node of the typed model below `root` that was read from `element` (found by descending
/// along the element's ancestors); nullptr when the model holds none (an element it leaves out).
Node* nodeBoundTo(Node& root, const xercesc::DOMElement& element);

/// The first node of the child field `field` (an element name, such as "transformation") of
/// `parent`; nullptr when the type has no such field or the document leaves it out.
Node* childNode(Node& parent, const char* field);

}  // namespace airshape::schema
