#include "airshape/uid/repeated_uids.h"

#include <xercesc/dom/DOM.hpp>

#include "airshape/schema/visitor.h"
#include "airshape/xml/text.h"

namespace airshape::uid {

namespace {

class RepeatedUidRemover final : public schema::Visitor {
 public:
  RepeatedUidRemover(schema::Node& node, const UidRegistry& registry, std::size_t& removed)
      : node_(node), registry_(registry), removed_(removed) {}

  void value(const schema::FieldInfo&, schema::ValueSlot&) override {}

  void child(const schema::FieldInfo&, schema::ChildSlot& slot) override {
    for (std::size_t i = slot.count(); i-- > 0;) {
      schema::Node& child = slot.at(i);
      if (isRepetition(child)) {
        node_.setAside.push_back(child.binding);
        slot.remove(i);
        ++removed_;
      } else {
        RepeatedUidRemover inner(child, registry_, removed_);
        child.visit(inner);
      }
    }
  }

 private:
  bool isRepetition(const schema::Node& child) const {
    if (child.binding == nullptr || !xml::hasAttribute(*child.binding, "uID")) return false;
    const xercesc::DOMElement* first = registry_.definition(xml::attribute(*child.binding, "uID"));
    return first != nullptr && first != child.binding;
  }

  schema::Node& node_;
  const UidRegistry& registry_;
  std::size_t& removed_;
};

}  // namespace

std::size_t setAsideRepeatedUids(schema::Node& root, const UidRegistry& registry) {
  std::size_t removed = 0;
  RepeatedUidRemover remover(root, registry, removed);
  root.visit(remover);
  return removed;
}

}  // namespace airshape::uid
