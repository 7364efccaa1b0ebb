#include "airshape/schema/dom_writer.h"

#include <algorithm>

#include <xercesc/dom/DOM.hpp>

#include "airshape/schema/visitor.h"
#include "airshape/xml/path.h"
#include "airshape/xml/text.h"

namespace airshape::schema {

using namespace xercesc;

namespace {

/// The element names of a type in schema order, to insert new children where they belong.
class ElementOrder final : public Visitor {
 public:
  void value(const FieldInfo& field, ValueSlot&) override {
    if (field.role == FieldRole::Element) names.push_back(field.name);
  }
  void child(const FieldInfo& field, ChildSlot&) override { names.push_back(field.name); }
  void pruned(const char* elementName) override { names.push_back(elementName); }

  std::vector<const char*> names;
};

class WritingVisitor final : public Visitor {
 public:
  WritingVisitor(Node& node, DOMElement& element) : node_(node), element_(element) {
    ElementOrder order;
    node.visit(order);
    order_ = std::move(order.names);
  }

  void value(const FieldInfo& field, ValueSlot& slot) override {
    switch (field.role) {
      case FieldRole::Attribute:
        writeAttribute(field, slot);
        break;
      case FieldRole::Text:
        if (slot.accepts(xml::text(element_)) && !slot.holds(0, xml::text(element_)))
          xml::setText(element_, slot.text(0));
        break;
      case FieldRole::Element:
        writeValues(field, slot);
        break;
    }
  }

  void child(const FieldInfo& field, ChildSlot& slot) override {
    std::vector<DOMElement*> existing = children(field.name);
    for (std::size_t i = 0; i < slot.count(); ++i) {
      Node& child = slot.at(i);
      if (child.binding == nullptr || child.binding->getParentNode() != &element_) {
        child.binding = insert(field.name);
        child.xpath = node_.xpath + "/" + field.name + (field.maxOccurs != 1 ? "[" + std::to_string(i + 1) + "]" : "");
      }
      existing.erase(std::remove(existing.begin(), existing.end(), child.binding), existing.end());
      writeNode(child, *child.binding);
    }
    for (DOMElement* orphan : existing) {
      const bool keep = std::find(node_.setAside.begin(), node_.setAside.end(), orphan) != node_.setAside.end();
      if (!keep) element_.removeChild(orphan)->release();  // removed from the model
    }
  }

 private:
  bool wasAbsent(const FieldInfo& field) const {
    return std::find(node_.absentOnRead.begin(), node_.absentOnRead.end(), field.index) != node_.absentOnRead.end();
  }

  void writeAttribute(const FieldInfo& field, ValueSlot& slot) {
    const std::u16string name = xml::toXml(field.name);
    const DOMAttr* attribute = element_.getAttributeNode(name.c_str());
    if (attribute != nullptr && !slot.accepts(xml::toUtf8(attribute->getValue()))) return;  // kept as written
    if (slot.count() == 0 || (attribute == nullptr && wasAbsent(field) && slot.isDefault())) {
      if (attribute != nullptr) element_.removeAttribute(name.c_str());
      return;
    }
    if (attribute != nullptr && slot.holds(0, xml::toUtf8(attribute->getValue()))) return;
    element_.setAttribute(name.c_str(), xml::toXml(slot.text(0)).c_str());
  }

  void writeValues(const FieldInfo& field, ValueSlot& slot) {
    std::vector<DOMElement*> existing = children(field.name);
    existing.erase(
        std::remove_if(existing.begin(), existing.end(), [&](DOMElement* e) { return !slot.accepts(xml::text(*e)); }),
        existing.end());  // invalid text stays as written
    std::size_t count = slot.count();
    if (existing.empty() && wasAbsent(field) && slot.isDefault()) count = 0;  // keep a flawed file as it was
    for (std::size_t i = 0; i < count; ++i) {
      DOMElement* target = i < existing.size() ? existing[i] : insert(field.name);
      if (i >= existing.size() || !slot.holds(i, xml::text(*target))) xml::setText(*target, slot.text(i));
    }
    for (std::size_t i = count; i < existing.size(); ++i) element_.removeChild(existing[i])->release();
  }

  std::vector<DOMElement*> children(const char* name) const {
    std::vector<DOMElement*> found;
    for (DOMElement* c = xml::firstElement(element_); c != nullptr; c = xml::nextElement(*c))
      if (xml::equalsAscii(c->getTagName(), name)) found.push_back(c);
    return found;
  }

  std::size_t rank(const XMLCh* tag) const {
    for (std::size_t i = 0; i < order_.size(); ++i)
      if (xml::equalsAscii(tag, order_[i])) return i;
    return order_.size();  // unknown elements keep their place at the end of the known ones
  }

  /// A new empty child element, after its same-named siblings, before the elements the schema puts later.
  DOMElement* insert(const char* name) {
    DOMElement* created = element_.getOwnerDocument()->createElement(xml::toXml(name).c_str());
    const std::size_t myRank = rank(created->getTagName());
    DOMElement* before = nullptr;
    for (DOMElement* c = xml::firstElement(element_); c != nullptr; c = xml::nextElement(*c)) {
      if (rank(c->getTagName()) > myRank) {
        before = c;
        break;
      }
    }
    element_.insertBefore(created, before);
    return created;
  }

  Node& node_;
  DOMElement& element_;
  std::vector<const char*> order_;
};

}  // namespace

void writeNode(Node& node, DOMElement& element) {
  node.binding = &element;
  WritingVisitor visitor(node, element);
  node.visit(visitor);
}

}  // namespace airshape::schema
