#include "airshape/model/component_fingerprints.h"

#include <xercesc/dom/DOM.hpp>

#include "airshape/configuration.h"
#include "airshape/xml/text.h"

namespace airshape::model {

namespace {

/// FNV-1a, 64 bits: fast, and collisions between two versions of one component are not a
/// practical concern.
class Hash {
 public:
  void add(const XMLCh* text) {
    for (const XMLCh* c = text; c != nullptr && *c != 0; ++c) mix(static_cast<std::uint64_t>(*c));
    mix(0xFFFF);  // separates consecutive strings
  }
  std::uint64_t value() const { return value_; }

 private:
  void mix(std::uint64_t unit) {
    value_ ^= unit;
    value_ *= 1099511628211ull;
  }
  std::uint64_t value_ = 14695981039346656037ull;
};

bool isInside(const xercesc::DOMNode* node, const xercesc::DOMElement& ancestor) {
  for (; node != nullptr; node = node->getParentNode())
    if (node == &ancestor) return true;
  return false;
}

/// Hashes an element's subtree (names, attributes, text); with `references`, also notes
/// the texts that name a uID defined outside `scope`.
void hashSubtree(const xercesc::DOMElement& element, Hash& hash, const Configuration* references,
                 const xercesc::DOMElement& scope, std::set<const xercesc::DOMElement*>& referenced) {
  hash.add(element.getTagName());
  const xercesc::DOMNamedNodeMap* attributes = element.getAttributes();
  for (XMLSize_t i = 0; attributes != nullptr && i < attributes->getLength(); ++i) {
    hash.add(attributes->item(i)->getNodeName());
    hash.add(attributes->item(i)->getNodeValue());
  }
  bool hasChildElement = false;
  for (const xercesc::DOMNode* child = element.getFirstChild(); child != nullptr; child = child->getNextSibling()) {
    if (child->getNodeType() == xercesc::DOMNode::ELEMENT_NODE) {
      hasChildElement = true;
      hashSubtree(static_cast<const xercesc::DOMElement&>(*child), hash, references, scope, referenced);
    } else if (child->getNodeType() == xercesc::DOMNode::TEXT_NODE ||
               child->getNodeType() == xercesc::DOMNode::CDATA_SECTION_NODE) {
      hash.add(child->getNodeValue());
    }
  }
  if (references != nullptr && !hasChildElement) {
    const xercesc::DOMElement* target = references->uids().definition(xml::text(element));
    if (target != nullptr && !isInside(target, scope)) referenced.insert(target);
  }
}

std::uint64_t fingerprint(const Configuration& configuration, const xercesc::DOMElement& element) {
  Hash hash;
  std::set<const xercesc::DOMElement*> referenced, none;
  hashSubtree(element, hash, &configuration, element, referenced);
  for (const xercesc::DOMElement* target : referenced) hashSubtree(*target, hash, nullptr, *target, none);
  return hash.value();
}

}  // namespace

std::map<std::string, std::uint64_t> componentFingerprints(const Configuration& configuration) {
  std::map<std::string, std::uint64_t> fingerprints;
  for (const graph::Component& component : configuration.components().components())
    if (component.element != nullptr) fingerprints[component.uid] = fingerprint(configuration, *component.element);
  return fingerprints;
}

std::set<std::string> changedComponents(const Configuration& configuration,
                                        const std::map<std::string, std::uint64_t>& before,
                                        const std::map<std::string, std::uint64_t>& after) {
  std::set<std::string> changed;
  for (const auto& [uid, hash] : after)
    if (const auto old = before.find(uid); old == before.end() || old->second != hash) changed.insert(uid);
  for (const auto& [uid, hash] : before)
    if (after.count(uid) == 0) changed.insert(uid);
  // Children after parents in build order: one pass carries a change down every chain.
  const graph::ComponentGraph& graph = configuration.components();
  for (std::size_t index : graph.buildOrder()) {
    const graph::Component& component = graph.components()[index];
    if (changed.count(component.parentUid) > 0) changed.insert(component.uid);
  }
  return changed;
}

}  // namespace airshape::model
