#include "airshape/uid/uid_registry.h"

#include <algorithm>
#include <vector>

#include <xercesc/dom/DOM.hpp>

#include "airshape/xml/path.h"
#include "airshape/xml/text.h"

namespace airshape::uid {

using namespace xercesc;

namespace {

/// Registers the uID of every element below and including `root`, in document order. A loop,
/// not a call per level, so that no nesting can exhaust the stack.
void collect(const DOMElement& root, const XMLCh* uidName,
             std::unordered_map<std::string, const DOMElement*>& definitions, Problems& problems) {
  std::vector<const DOMElement*> pending{&root};
  while (!pending.empty()) {
    const DOMElement& element = *pending.back();
    pending.pop_back();
    if (const DOMAttr* attribute = element.getAttributeNode(uidName)) {
      const std::string uid = xml::toUtf8(attribute->getValue());
      const auto [entry, inserted] = definitions.emplace(uid, &element);
      if (!inserted) {  // paths are worked out only here: most documents need none
        problems.push_back({Problem::Severity::Error, xml::pathOf(element),
                            "duplicate uID '" + uid + "' (first defined at " + xml::pathOf(*entry->second) +
                                "; this definition is ignored)"});
      }
    }
    const std::size_t firstChild = pending.size();
    for (const DOMElement* child = xml::firstElement(element); child != nullptr; child = xml::nextElement(*child))
      pending.push_back(child);
    std::reverse(pending.begin() + static_cast<std::ptrdiff_t>(firstChild), pending.end());  // first child on top
  }
}

}  // namespace

void UidRegistry::build(const DOMElement& root, const std::vector<schema::UidReference>& references) {
  definitions_.clear();
  problems_.clear();
  collect(root, u"uID", definitions_, problems_);
  for (const auto& reference : references) {
    if (!contains(reference.uid)) {
      problems_.push_back({Problem::Severity::Error, reference.xpath,
                           "uIDref '" + reference.uid + "' points to no element with that uID"});
    }
  }
}

const DOMElement* UidRegistry::definition(const std::string& uid) const {
  const auto entry = definitions_.find(uid);
  return entry == definitions_.end() ? nullptr : entry->second;
}

}  // namespace airshape::uid
