#include "airshape/uid/uid_registry.h"

#include <xercesc/dom/DOM.hpp>

#include "airshape/xml/path.h"
#include "airshape/xml/text.h"

namespace airshape::uid {

using namespace xercesc;

namespace {

void collect(const DOMElement& element, const XMLCh* uidName,
             std::unordered_map<std::string, const DOMElement*>& definitions, Problems& problems) {
  if (const DOMAttr* attribute = element.getAttributeNode(uidName)) {
    const std::string uid = xml::toUtf8(attribute->getValue());
    const auto [entry, inserted] = definitions.emplace(uid, &element);
    if (!inserted) {  // paths are worked out only here: most documents need none
      problems.push_back({Problem::Severity::Error, xml::pathOf(element),
                          "duplicate uID '" + uid + "' (first defined at " + xml::pathOf(*entry->second) +
                              "; this definition is ignored)"});
    }
  }
  for (const DOMElement* child = xml::firstElement(element); child != nullptr; child = xml::nextElement(*child))
    collect(*child, uidName, definitions, problems);
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
