#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace airshape::schema {

/// What a simple value is; the UID kinds let the UID registry find definitions and references.
enum class ValueKind { String, Uid, UidRef, Double, Integer, Boolean, DoubleVector, Enum };

/// The outcome of parsing one text: empty when it parsed, else why not (e.g. "not a number").
using ParseError = std::optional<std::string>;

// A codec turns the text of an attribute or element into a typed value and back.
// parse() leaves `out` untouched when it fails; format() gives the shortest text
// that parses back to the same value.

struct StringCodec {
  using Value = std::string;
  static constexpr ValueKind kind = ValueKind::String;
  static ParseError parse(const std::string& text, Value& out);
  static std::string format(const Value& value) { return value; }
};

/// A uID attribute: a string that names this node.
struct UidCodec : StringCodec {
  static constexpr ValueKind kind = ValueKind::Uid;
};

/// A string that refers to a uID elsewhere in the document.
struct UidRefCodec : StringCodec {
  static constexpr ValueKind kind = ValueKind::UidRef;
  static ParseError parse(const std::string& text, Value& out);
};

struct DoubleCodec {
  using Value = double;
  static constexpr ValueKind kind = ValueKind::Double;
  static ParseError parse(const std::string& text, Value& out);
  static std::string format(const Value& value);
};

struct IntegerCodec {
  using Value = long long;
  static constexpr ValueKind kind = ValueKind::Integer;
  static ParseError parse(const std::string& text, Value& out);
  static std::string format(const Value& value);
};

struct BooleanCodec {
  using Value = bool;
  static constexpr ValueKind kind = ValueKind::Boolean;
  static ParseError parse(const std::string& text, Value& out);
  static std::string format(const Value& value) { return value ? "true" : "false"; }
};

/// CPACS vectors: numbers separated by semicolons, e.g. "0.0;0.5;1.0".
struct DoubleVectorCodec {
  using Value = std::vector<double>;
  static constexpr ValueKind kind = ValueKind::DoubleVector;
  static ParseError parse(const std::string& text, Value& out);
  static std::string format(const Value& value);
};

/// A value as messages show it: in single quotes, with line breaks, tabs and other control
/// characters escaped (\n, \t, \x01), so that every problem stays on one line and a value of
/// only whitespace is visible.
std::string quoted(const std::string& text);

/// The texts of an enumeration's values in declaration order; specialised by generated code.
template <class E>
struct EnumNames;

/// Index of `text` among `names` (count entries), or -1.
int findEnumName(const char* const* names, std::size_t count, const std::string& text);
/// "one of a, b, c": the message for a text that is none of the enumeration's values.
std::string describeEnumNames(const char* const* names, std::size_t count);

template <class E>
struct EnumCodec {
  using Value = E;
  static constexpr ValueKind kind = ValueKind::Enum;
  static ParseError parse(const std::string& text, Value& out) {
    constexpr std::size_t count = sizeof(EnumNames<E>::values) / sizeof(EnumNames<E>::values[0]);
    const int index = findEnumName(EnumNames<E>::values, count, text);
    if (index < 0) return quoted(text) + " is not " + describeEnumNames(EnumNames<E>::values, count);
    out = static_cast<E>(index);
    return std::nullopt;
  }
  static std::string format(const Value& value) { return EnumNames<E>::values[static_cast<int>(value)]; }
};

/// Text of an enumeration value, e.g. toString(SymmetryXyXzYzType::XZPlane) == "x-z-plane".
template <class E>
const char* toString(E value) {
  return EnumNames<E>::values[static_cast<int>(value)];
}

}  // namespace airshape::schema
