#include "airshape/schema/node_lookup.h"

#include <cstring>
#include <vector>

#include <xercesc/dom/DOMElement.hpp>

#include "airshape/schema/visitor.h"

namespace airshape::schema {

namespace {

/// Finds, among a node's children, the first one that satisfies a test.
class ChildFinder final : public Visitor {
 public:
  using Test = bool (*)(const FieldInfo&, const Node&, const void*);
  ChildFinder(Test test, const void* wanted) : test_(test), wanted_(wanted) {}

  void value(const FieldInfo&, ValueSlot&) override {}
  void child(const FieldInfo& field, ChildSlot& slot) override {
    for (std::size_t i = 0; found == nullptr && i < slot.count(); ++i)
      if (test_(field, slot.at(i), wanted_)) found = &slot.at(i);
  }

  Node* found = nullptr;

 private:
  Test test_;
  const void* wanted_;
};

Node* firstChild(Node& parent, ChildFinder::Test test, const void* wanted) {
  ChildFinder finder(test, wanted);
  parent.visit(finder);
  return finder.found;
}

}  // namespace

Node* nodeBoundTo(Node& root, const xercesc::DOMElement& element) {
  std::vector<const xercesc::DOMNode*> below;  // the element and its ancestors below the root's
  const xercesc::DOMNode* step = &element;
  for (; step != nullptr && step != root.binding; step = step->getParentNode()) below.push_back(step);
  if (step == nullptr) return nullptr;
  Node* current = &root;
  for (auto ancestor = below.rbegin(); current != nullptr && ancestor != below.rend(); ++ancestor)
    current = firstChild(
        *current, [](const FieldInfo&, const Node& node, const void* wanted) { return node.binding == wanted; },
        *ancestor);
  return current;
}

Node* childNode(Node& parent, const char* field) {
  return firstChild(
      parent,
      [](const FieldInfo& info, const Node&, const void* wanted) {
        return std::strcmp(info.name, static_cast<const char*>(wanted)) == 0;
      },
      field);
}

}  // namespace airshape::schema
