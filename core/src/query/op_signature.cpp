#include "airshape/query/op_signature.h"

#include <cctype>

namespace airshape::query {

namespace {

/// The identifier an argument's text starts with, after brackets and quotes.
std::string argumentName(const std::string& text) {
  std::size_t start = 0;
  while (start < text.size() && !(std::isalnum(static_cast<unsigned char>(text[start])) || text[start] == '_')) ++start;
  std::size_t end = start;
  while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_')) ++end;
  return text.substr(start, end - start);
}

std::string trimmed(const std::string& text) {
  const std::size_t first = text.find_first_not_of(' ');
  const std::size_t last = text.find_last_not_of(' ');
  return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
}

}  // namespace

OpSignature signatureOf(const Op& op) {
  OpSignature signature;
  const std::size_t arrow = op.summary.find("->");
  if (arrow == std::string::npos) {
    signature.answer = trimmed(op.summary);
    return signature;
  }
  signature.answer = trimmed(op.summary.substr(arrow + 2));
  const std::string before = op.summary.substr(0, arrow);
  int depth = 0;  // inside brackets: optional
  std::string item;
  const auto take = [&](bool optional) {
    const std::string name = argumentName(item);
    if (!name.empty()) (optional ? signature.optional : signature.arguments).push_back(name);
    item.clear();
  };
  bool optional = false;
  for (const char c : before) {
    if (c == '[') {
      ++depth;
      optional = true;
    } else if (c == ']') {
      --depth;
    } else if (c == ',' && depth <= 1) {
      take(optional);
      optional = depth > 0;
      continue;
    }
    if (c != '[' && c != ']') item += c;
    if (c == ':' && depth > 0) item += ' ';  // `"name": value`: only the name counts
  }
  take(optional);
  return signature;
}

Json describeOps(const QueryRegistry& registry) {
  Json ops = Json::array();
  for (const Op* op : registry.ops()) {
    const OpSignature signature = signatureOf(*op);
    ops.push_back({{"name", op->name},
                   {"owner", op->owner},
                   {"summary", op->summary},
                   {"arguments", signature.arguments},
                   {"optional", signature.optional},
                   {"answer", signature.answer}});
  }
  return ops;
}

}  // namespace airshape::query
