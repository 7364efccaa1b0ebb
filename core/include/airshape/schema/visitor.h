#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "airshape/schema/child.h"
#include "airshape/schema/node.h"
#include "airshape/schema/value_codec.h"

namespace airshape::schema {

/// Numeric limits from the schema's minInclusive/maxInclusive/minExclusive/maxExclusive facets.
struct NumericRange {
  std::optional<double> minInclusive, maxInclusive, minExclusive, maxExclusive;
};

/// Where a field's text lives: an attribute, child elements, or the node's own text.
enum class FieldRole : unsigned char { Attribute, Element, Text };

/// What the schema says about one attribute or child element of a type.
struct FieldInfo {
  const char* name;  ///< attribute or element name; "" for Text
  FieldRole role;
  int minOccurs;
  int maxOccurs;              ///< -1: unbounded
  unsigned short index;       ///< position among the fields of the generated class
  const NumericRange* range;  ///< nullptr: no numeric limits
};

/// An xsd:choice: the alternatives are null-terminated lists of element names, the list
/// of alternatives is null-terminated too. At most one alternative may be present, and
/// one must be when minOccurs is 1.
struct ChoiceInfo {
  int minOccurs;
  const char* const* const* alternatives;
};

/// Access to the stored value(s) of one simple field, in text form.
class ValueSlot {
 public:
  virtual ~ValueSlot() = default;
  virtual ValueKind kind() const = 0;
  /// How many values are stored: 0 or 1 for single fields, any number for lists.
  virtual std::size_t count() const = 0;
  virtual std::string text(std::size_t index) const = 0;
  /// Whether `text` parses to the value stored at `index` (so the document needs no change).
  virtual bool holds(std::size_t index, const std::string& text) const = 0;
  /// Parses and stores a value (appending to a list, else replacing); on failure stores nothing.
  virtual ParseError assign(const std::string& text) = 0;
  virtual void clear() = 0;
  /// Whether a single value still has its default (zero, empty, first enumerator).
  virtual bool isDefault() const = 0;
  /// Whether `text` is a valid value of this field. Text that is not stays in the document
  /// untouched: the model could not hold it, so its absence there is no edit.
  virtual bool accepts(const std::string& text) const = 0;
};

/// Access to the child node(s) of one complex field.
class ChildSlot {
 public:
  virtual ~ChildSlot() = default;
  virtual std::size_t count() const = 0;
  virtual Node& at(std::size_t index) = 0;
  /// Adds a new, empty child (appending to a list, else replacing) and returns it.
  virtual Node& add() = 0;
  virtual void remove(std::size_t index) = 0;
};

/// Walks the fields of generated nodes. Readers, writers and validators implement it.
class Visitor {
 public:
  virtual ~Visitor() = default;
  virtual void value(const FieldInfo& field, ValueSlot& slot) = 0;
  virtual void child(const FieldInfo& field, ChildSlot& slot) = 0;
  /// A child element the model leaves out on purpose (see codegen/prune-list.txt).
  virtual void pruned(const char* /*elementName*/) {}
  /// Called after the fields of a type that has choice groups.
  virtual void choice(const ChoiceInfo& /*choice*/) {}
};

// ---- slot implementations, one per way a generated class stores a field ----

template <class Codec>
bool acceptedBy(const std::string& text) {
  typename Codec::Value parsed{};
  return !Codec::parse(text, parsed);
}

template <class Codec, class Storage>
class ValueSlotFor;

/// A required single value: always counted as present.
template <class Codec>
class ValueSlotFor<Codec, typename Codec::Value> final : public ValueSlot {
 public:
  explicit ValueSlotFor(typename Codec::Value& value) : value_(value) {}
  ValueKind kind() const override { return Codec::kind; }
  std::size_t count() const override { return 1; }
  std::string text(std::size_t) const override { return Codec::format(value_); }
  bool holds(std::size_t, const std::string& text) const override {
    typename Codec::Value parsed{};
    return !Codec::parse(text, parsed) && parsed == value_;
  }
  ParseError assign(const std::string& text) override { return Codec::parse(text, value_); }
  void clear() override { value_ = typename Codec::Value{}; }
  bool isDefault() const override { return value_ == typename Codec::Value{}; }
  bool accepts(const std::string& text) const override { return acceptedBy<Codec>(text); }

 private:
  typename Codec::Value& value_;
};

template <class Codec>
class ValueSlotFor<Codec, std::optional<typename Codec::Value>> final : public ValueSlot {
 public:
  explicit ValueSlotFor(std::optional<typename Codec::Value>& value) : value_(value) {}
  ValueKind kind() const override { return Codec::kind; }
  std::size_t count() const override { return value_ ? 1 : 0; }
  std::string text(std::size_t) const override { return Codec::format(*value_); }
  bool holds(std::size_t, const std::string& text) const override {
    typename Codec::Value parsed{};
    return value_ && !Codec::parse(text, parsed) && parsed == *value_;
  }
  ParseError assign(const std::string& text) override {
    typename Codec::Value parsed{};
    ParseError error = Codec::parse(text, parsed);
    if (!error) value_ = std::move(parsed);
    return error;
  }
  void clear() override { value_.reset(); }
  bool isDefault() const override { return !value_; }
  bool accepts(const std::string& text) const override { return acceptedBy<Codec>(text); }

 private:
  std::optional<typename Codec::Value>& value_;
};

template <class Codec>
class ValueSlotFor<Codec, std::vector<typename Codec::Value>> final : public ValueSlot {
 public:
  explicit ValueSlotFor(std::vector<typename Codec::Value>& values) : values_(values) {}
  ValueKind kind() const override { return Codec::kind; }
  std::size_t count() const override { return values_.size(); }
  std::string text(std::size_t index) const override { return Codec::format(values_[index]); }
  bool holds(std::size_t index, const std::string& text) const override {
    typename Codec::Value parsed{};
    return index < values_.size() && !Codec::parse(text, parsed) && parsed == values_[index];
  }
  ParseError assign(const std::string& text) override {
    typename Codec::Value parsed{};
    ParseError error = Codec::parse(text, parsed);
    if (!error) values_.push_back(std::move(parsed));
    return error;
  }
  void clear() override { values_.clear(); }
  bool isDefault() const override { return values_.empty(); }
  bool accepts(const std::string& text) const override { return acceptedBy<Codec>(text); }

 private:
  std::vector<typename Codec::Value>& values_;
};

template <class Storage>
class ChildSlotFor;

template <class T>
class ChildSlotFor<Child<T>> final : public ChildSlot {
 public:
  explicit ChildSlotFor(Child<T>& child) : child_(child) {}
  std::size_t count() const override { return child_ ? 1 : 0; }
  Node& at(std::size_t) override { return *child_; }
  Node& add() override { return child_.emplace(); }
  void remove(std::size_t) override { child_.reset(); }

 private:
  Child<T>& child_;
};

template <class T>
class ChildSlotFor<List<T>> final : public ChildSlot {
 public:
  explicit ChildSlotFor(List<T>& list) : list_(list) {}
  std::size_t count() const override { return list_.size(); }
  Node& at(std::size_t index) override { return list_[index]; }
  Node& add() override { return list_.append(); }
  void remove(std::size_t index) override { list_.erase(index); }

 private:
  List<T>& list_;
};

/// Helpers for generated visit() functions.
template <class Codec, class Storage>
void visitValue(Visitor& visitor, const FieldInfo& field, Storage& storage) {
  ValueSlotFor<Codec, Storage> slot(storage);
  visitor.value(field, slot);
}

template <class Storage>
void visitChild(Visitor& visitor, const FieldInfo& field, Storage& storage) {
  ChildSlotFor<Storage> slot(storage);
  visitor.child(field, slot);
}

}  // namespace airshape::schema
