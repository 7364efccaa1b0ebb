#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "airshape/problem.h"
#include "airshape/schema/dom_reader.h"

namespace airshape::uid {

/// Every uID of a document, each mapped to the element that defines it.
///
/// Real files repeat uIDs; the first definition in document order wins and each
/// repetition is reported. References that point nowhere are reported too.
class UidRegistry {
 public:
  /// Registers every element with a uID attribute under `root` (the whole document,
  /// modelled or not) and checks the references found while reading the model.
  void build(const xercesc::DOMElement& root, const std::vector<schema::UidReference>& references);

  /// The element that defines `uid` (the first in document order), or nullptr.
  const xercesc::DOMElement* definition(const std::string& uid) const;
  bool contains(const std::string& uid) const { return definition(uid) != nullptr; }
  std::size_t size() const { return definitions_.size(); }

  /// Duplicate uIDs and dangling uIDrefs, as errors with the XPaths involved.
  const Problems& problems() const { return problems_; }

 private:
  std::unordered_map<std::string, const xercesc::DOMElement*> definitions_;  // uid -> the first definition
  Problems problems_;
};

}  // namespace airshape::uid
