#include "airshape/uid/uid_registry.h"

#include <xercesc/dom/DOM.hpp>

#include "airshape/xml/path.h"
#include "airshape/xml/text.h"

namespace airshape::uid {

using namespace xercesc;

namespace {

void collect(const DOMElement& element, const XMLCh* uidName,
             std::unordered_map<std::string, UidRegistry::Definition>& definitions, Problems& problems) {
  if (const DOMAttr* attribute = element.getAttributeNode(uidName)) {
    const std::string uid = xml::toUtf8(attribute->getValue());
    const std::string xpath = xml::pathOf(element);
    const auto [entry, inserted] = definitions.emplace(uid, UidRegistry::Definition{xpath, &element});
    if (!inserted) {
      problems.push_back(
          {Problem::Severity::Error, xpath,
           "duplicate uID '" + uid + "' (first defined at " + entry->second.xpath + "; this definition is ignored)"});
    }
  }
  for (const DOMElement* child = element.getFirstElementChild(); child != nullptr;
       child = child->getNextElementSibling())
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

const std::string* UidRegistry::find(const std::string& uid) const {
  const auto entry = definitions_.find(uid);
  return entry == definitions_.end() ? nullptr : &entry->second.xpath;
}

const DOMElement* UidRegistry::definition(const std::string& uid) const {
  const auto entry = definitions_.find(uid);
  return entry == definitions_.end() ? nullptr : entry->second.element;
}

}  // namespace airshape::uid
