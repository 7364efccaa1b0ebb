#include "airshape/schema/value_codec.h"

#include <charconv>
#include <cmath>
#include <string_view>

namespace airshape::schema {
namespace {

constexpr std::string_view kWhitespace = " \t\r\n";

std::string_view trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(kWhitespace);
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(kWhitespace);
  return text.substr(first, last - first + 1);
}

// std::from_chars rejects a leading '+', which XML Schema allows.
std::string_view withoutPlus(std::string_view text) {
  return (!text.empty() && text.front() == '+') ? text.substr(1) : text;
}

ParseError parseDouble(std::string_view text, double& out) {
  const std::string_view number = withoutPlus(trimmed(text));
  if (number == "NaN") {
    out = std::nan("");
    return std::nullopt;
  }
  if (number == "INF" || number == "-INF") {
    out = number.front() == '-' ? -HUGE_VAL : HUGE_VAL;
    return std::nullopt;
  }
  double value = 0.0;
  const auto result = std::from_chars(number.data(), number.data() + number.size(), value);
  if (number.empty() || result.ec != std::errc() || result.ptr != number.data() + number.size())
    return quoted(std::string(text)) + " is not a number";
  out = value;
  return std::nullopt;
}

// Some CPACS editors write every number as a decimal ("1.000000" for a count); an integral
// decimal means that integer, as a reader of the file would take it.
std::optional<long long> integralDecimal(std::string_view number) {
  double value = 0.0;
  const auto result = std::from_chars(number.data(), number.data() + number.size(), value);
  if (number.empty() || result.ec != std::errc() || result.ptr != number.data() + number.size()) return std::nullopt;
  constexpr double kLimit = 9.0e18;  // within long long, where every integral double is exact
  if (!std::isfinite(value) || std::fabs(value) > kLimit || value != std::trunc(value)) return std::nullopt;
  return static_cast<long long>(value);
}

}  // namespace

std::string quoted(const std::string& text) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string result = "'";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      result += "\\n";
    } else if (c == '\r') {
      result += "\\r";
    } else if (c == '\t') {
      result += "\\t";
    } else if (byte < 0x20 || byte == 0x7f) {
      result += std::string("\\x") + kHex[byte >> 4] + kHex[byte & 15];
    } else {
      result += c;
    }
  }
  return result + "'";
}

ParseError StringCodec::parse(const std::string& text, Value& out) {
  out = text;
  return std::nullopt;
}

ParseError UidRefCodec::parse(const std::string& text, Value& out) {
  // A reference names a uID; the surrounding whitespace of pretty-printed files is not part of it.
  out = std::string(trimmed(text));
  return std::nullopt;
}

ParseError DoubleCodec::parse(const std::string& text, Value& out) { return parseDouble(text, out); }

std::string DoubleCodec::format(const Value& value) {
  if (std::isnan(value)) return "NaN";
  if (std::isinf(value)) return value > 0 ? "INF" : "-INF";
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

ParseError IntegerCodec::parse(const std::string& text, Value& out) {
  const std::string_view number = withoutPlus(trimmed(text));
  long long value = 0;
  const auto result = std::from_chars(number.data(), number.data() + number.size(), value);
  if (!number.empty() && result.ec == std::errc() && result.ptr == number.data() + number.size()) {
    out = value;
    return std::nullopt;
  }
  if (const auto integral = integralDecimal(number)) {
    out = *integral;
    return std::nullopt;
  }
  return quoted(text) + " is not an integer";
}

std::string IntegerCodec::format(const Value& value) { return std::to_string(value); }

ParseError BooleanCodec::parse(const std::string& text, Value& out) {
  const std::string_view word = trimmed(text);
  if (word == "true" || word == "1") {
    out = true;
  } else if (word == "false" || word == "0") {
    out = false;
  } else {
    return quoted(text) + " is not a boolean (true, false, 1 or 0)";
  }
  return std::nullopt;
}

ParseError DoubleVectorCodec::parse(const std::string& text, Value& out) {
  Value values;
  const std::string_view all = trimmed(text);
  std::size_t start = 0;
  while (!all.empty() && start <= all.size()) {
    const std::size_t end = std::min(all.find(';', start), all.size());
    if (end == all.size() && start == end && start > 0) break;  // a trailing ';'
    double value = 0.0;
    if (parseDouble(all.substr(start, end - start), value)) {
      return quoted(std::string(trimmed(all.substr(start, end - start)))) + " in vector " + quoted(text) +
             " is not a number";
    }
    values.push_back(value);
    start = end + 1;
  }
  out = std::move(values);
  return std::nullopt;
}

std::string DoubleVectorCodec::format(const Value& value) {
  std::string text;
  for (std::size_t i = 0; i < value.size(); ++i) {
    if (i > 0) text += ';';
    text += DoubleCodec::format(value[i]);
  }
  return text;
}

int findEnumName(const char* const* names, std::size_t count, const std::string& text) {
  const std::string_view word = trimmed(text);
  for (std::size_t i = 0; i < count; ++i) {
    if (word == names[i]) return static_cast<int>(i);
  }
  return -1;
}

std::string describeEnumNames(const char* const* names, std::size_t count) {
  std::string text = "one of ";
  for (std::size_t i = 0; i < count; ++i) {
    if (i > 0) text += ", ";
    text += names[i];
  }
  return text;
}

}  // namespace airshape::schema
