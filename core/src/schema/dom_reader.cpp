#include "airshape/schema/dom_reader.h"

#include <algorithm>

#include <xercesc/dom/DOM.hpp>

#include "airshape/schema/visitor.h"
#include "airshape/xml/path.h"
#include "airshape/xml/text.h"

namespace airshape::schema {

using namespace xercesc;

namespace {

std::string occursText(int count) { return count == 1 ? "once" : std::to_string(count) + " times"; }

/// Why `text` breaks the numeric limits, or an empty string.
std::string rangeViolation(const NumericRange& range, const std::string& text) {
  double value = 0.0;
  if (DoubleCodec::parse(text, value)) return {};  // reported as "not a number" already
  if (range.minInclusive && value < *range.minInclusive)
    return "must be at least " + DoubleCodec::format(*range.minInclusive);
  if (range.maxInclusive && value > *range.maxInclusive)
    return "must be at most " + DoubleCodec::format(*range.maxInclusive);
  if (range.minExclusive && value <= *range.minExclusive)
    return "must be greater than " + DoubleCodec::format(*range.minExclusive);
  if (range.maxExclusive && value >= *range.maxExclusive)
    return "must be less than " + DoubleCodec::format(*range.maxExclusive);
  return {};
}

class ReadingVisitor final : public Visitor {
 public:
  ReadingVisitor(DOMElement& element, Node& node, ReadReport& report)
      : element_(element), node_(node), report_(report) {
    for (DOMElement* child = xml::firstElement(element); child != nullptr; child = xml::nextElement(*child))
      children_.push_back({child, false});
  }

  void value(const FieldInfo& field, ValueSlot& slot) override {
    switch (field.role) {
      case FieldRole::Attribute:
        readAttribute(field, slot);
        break;
      case FieldRole::Text:
        if (!assign(field, slot, xml::text(element_), node_.xpath)) node_.absentOnRead.push_back(field.index);
        break;
      case FieldRole::Element: {
        const std::vector<DOMElement*> found = claim(field);
        bool anyValid = false;
        for (std::size_t i = 0; i < found.size(); ++i)
          anyValid = assign(field, slot, xml::text(*found[i]), childPath(field, i)) || anyValid;
        if (!anyValid && field.minOccurs > 0 && field.maxOccurs == 1) node_.absentOnRead.push_back(field.index);
        break;
      }
    }
  }

  void child(const FieldInfo& field, ChildSlot& slot) override {
    const std::vector<DOMElement*> found = claim(field);
    for (std::size_t i = 0; i < found.size(); ++i) {
      Node& child = slot.add();
      child.binding = found[i];
      child.xpath = childPath(field, i);
      readNode(*found[i], child, child.xpath, report_);
    }
  }

  void pruned(const char* elementName) override {
    for (auto& entry : children_)
      if (xml::equalsAscii(entry.element->getTagName(), elementName)) entry.claimed = true;
  }

  void choice(const ChoiceInfo& choice) override {
    std::vector<std::string> present;
    std::string all;
    for (const char* const* const* alternative = choice.alternatives; *alternative != nullptr; ++alternative) {
      std::string label;
      bool isPresent = false;
      for (const char* const* name = *alternative; *name != nullptr; ++name) {
        label += (label.empty() ? "" : "+") + std::string(*name);
        isPresent = isPresent || hasChild(*name);
      }
      if (label.empty()) continue;
      all += (all.empty() ? "" : " | ") + label;
      if (isPresent) present.push_back(label);
    }
    if (present.size() > 1) {
      problem(node_.xpath,
              "elements " + present[0] + " and " + present[1] + " exclude each other (choose one of " + all + ")");
    } else if (present.empty() && choice.minOccurs > 0) {
      problem(node_.xpath, "needs one of " + all);
    }
  }

  /// Children that no field claimed: not part of the schema type.
  void reportUnexpected() {
    for (const auto& entry : children_) {
      if (!entry.claimed) {
        problem(
            node_.xpath + "/" + xml::name(*entry.element),
            "element '" + xml::name(*entry.element) + "' is not allowed in " + node_.schemaType() + " (kept as is)");
      }
    }
  }

 private:
  struct ChildEntry {
    DOMElement* element;
    bool claimed;
  };

  void problem(const std::string& xpath, const std::string& message) {
    report_.problems.push_back({Problem::Severity::Error, xpath, message});
  }

  bool hasChild(const char* name) const {
    return std::any_of(children_.begin(), children_.end(),
                       [&](const ChildEntry& e) { return xml::equalsAscii(e.element->getTagName(), name); });
  }

  std::vector<DOMElement*> claim(const FieldInfo& field) {
    std::vector<DOMElement*> found;
    for (auto& entry : children_) {
      if (xml::equalsAscii(entry.element->getTagName(), field.name)) {
        entry.claimed = true;
        found.push_back(entry.element);
      }
    }
    const int count = static_cast<int>(found.size());
    if (count < field.minOccurs) {
      problem(node_.xpath, field.minOccurs == 1
                               ? "missing required element '" + std::string(field.name) + "'"
                               : "element '" + std::string(field.name) + "' occurs " + occursText(count) +
                                     ", at least " + std::to_string(field.minOccurs) + " needed");
    }
    if (field.maxOccurs >= 0 && count > field.maxOccurs) {
      problem(node_.xpath + "/" + field.name, "element '" + std::string(field.name) + "' occurs " + occursText(count) +
                                                  ", at most " + occursText(field.maxOccurs) + " allowed");
    }
    return found;
  }

  std::string childPath(const FieldInfo& field, std::size_t index) const {
    std::string path = node_.xpath + "/" + field.name;
    if (field.maxOccurs != 1) path += "[" + std::to_string(index + 1) + "]";
    return path;
  }

  void readAttribute(const FieldInfo& field, ValueSlot& slot) {
    const std::u16string name = xml::toXml(field.name);
    const DOMAttr* attribute = element_.getAttributeNode(name.c_str());
    if (attribute == nullptr) {
      if (field.minOccurs > 0) {
        problem(node_.xpath, "missing required attribute '" + std::string(field.name) + "'");
        node_.absentOnRead.push_back(field.index);
      }
      return;
    }
    if (!assign(field, slot, xml::toUtf8(attribute->getValue()), node_.xpath + "/@" + field.name) &&
        field.minOccurs > 0)
      node_.absentOnRead.push_back(field.index);
  }

  /// Stores the value of `text`; returns false (and reports why) when it is no valid value.
  bool assign(const FieldInfo& field, ValueSlot& slot, const std::string& text, const std::string& xpath) {
    if (ParseError error = slot.assign(text)) {
      problem(xpath, *error);
      report_.unreadableValues.push_back(report_.problems.back());
      return false;
    }
    if (field.range != nullptr) {
      const std::string violation = rangeViolation(*field.range, text);
      if (!violation.empty()) problem(xpath, "value " + text + " " + violation);
    }
    if (slot.kind() == ValueKind::UidRef && !slot.text(slot.count() - 1).empty())
      report_.references.push_back({slot.text(slot.count() - 1), xpath});
    return true;
  }

  DOMElement& element_;
  Node& node_;
  ReadReport& report_;
  std::vector<ChildEntry> children_;
};

}  // namespace

void readNode(DOMElement& element, Node& node, const std::string& xpath, ReadReport& report) {
  node.binding = &element;
  node.xpath = xpath;
  ReadingVisitor visitor(element, node, report);
  node.visit(visitor);
  visitor.reportUnexpected();
}

}  // namespace airshape::schema
