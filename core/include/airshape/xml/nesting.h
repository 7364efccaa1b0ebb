#pragma once

#include <cstddef>
#include <string>

#include <xercesc/util/XercesDefs.hpp>

XERCES_CPP_NAMESPACE_BEGIN
class DOMElement;
XERCES_CPP_NAMESPACE_END

namespace airshape::xml {

/// The deepest nesting of elements Airshape reads. CPACS itself nests fewer than 30 levels;
/// the limit keeps every recursive walk over a document (the typed model, paths, the writer
/// Xerces serialises with) far from the end of the stack, whatever a file holds.
constexpr std::size_t kMaximumNesting = 1000;

/// How many levels of elements `element` holds, itself included (a leaf is 1). Iterative.
std::size_t nestingDepth(const xercesc::DOMElement& element);

/// Throws Error(NotXml) naming `source` when elements below `element` (which sits at
/// `depthOfElement`, the root being 1) nest deeper than kMaximumNesting.
void requireNestingWithinLimit(const xercesc::DOMElement& element, const std::string& source,
                               std::size_t depthOfElement = 1);

}  // namespace airshape::xml
