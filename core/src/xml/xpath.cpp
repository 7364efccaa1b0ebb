#include "airshape/xml/xpath.h"

#include <vector>

#include <xercesc/dom/DOM.hpp>

#include "airshape/error.h"
#include "airshape/xml/text.h"

namespace airshape::xml {

namespace {

/// One step of a path: a name, and either a position or an attribute test.
struct Step {
  std::string name;
  int position = 1;
  std::string attribute, value;  ///< the attribute test, when attribute is not empty
};

Error badPath(const std::string& xpath, const std::string& why) {
  return Error(ErrorCode::InvalidArgument, "XPath " + xpath + ": " + why);
}

std::vector<std::string> splitSteps(const std::string& xpath) {
  if (xpath.size() < 2 || xpath[0] != '/' || xpath[1] == '/')
    throw badPath(xpath, "expected an absolute path such as /cpacs/header/name");
  std::vector<std::string> steps;
  std::string current;
  char quote = 0;
  for (std::size_t i = 1; i < xpath.size(); ++i) {
    const char c = xpath[i];
    if (quote == 0 && c == '/') {
      steps.push_back(current);
      current.clear();
      continue;
    }
    if (c == '\'' || c == '"') quote = quote == 0 ? c : (quote == c ? 0 : quote);
    current += c;
  }
  steps.push_back(current);
  for (const std::string& step : steps)
    if (step.empty()) throw badPath(xpath, "empty step");
  return steps;
}

Step parseStep(const std::string& text, const std::string& xpath) {
  Step step;
  const std::size_t open = text.find('[');
  step.name = text.substr(0, open);
  if (open == std::string::npos) return step;
  if (text.back() != ']') throw badPath(xpath, "unclosed predicate in '" + text + "'");
  const std::string predicate = text.substr(open + 1, text.size() - open - 2);
  if (!predicate.empty() && predicate[0] == '@') {
    const std::size_t equals = predicate.find('=');
    if (equals == std::string::npos || predicate.size() < equals + 3)
      throw badPath(xpath, "expected [@name='value'] in '" + text + "'");
    step.attribute = predicate.substr(1, equals - 1);
    step.value = predicate.substr(equals + 2, predicate.size() - equals - 3);
    return step;
  }
  try {
    std::size_t used = 0;
    step.position = std::stoi(predicate, &used);
    if (used != predicate.size() || step.position < 1) throw std::invalid_argument("position");
  } catch (const std::exception&) {
    throw badPath(xpath, "expected a position [k >= 1] or [@name='value'] in '" + text + "'");
  }
  return step;
}

bool matches(const xercesc::DOMElement& element, const Step& step) {
  if (name(element) != step.name) return false;
  return step.attribute.empty() ||
         (hasAttribute(element, step.attribute) && attribute(element, step.attribute) == step.value);
}

xercesc::DOMElement* childMatching(const xercesc::DOMElement& parent, const Step& step) {
  int seen = 0;
  for (xercesc::DOMElement* child = firstElement(parent); child != nullptr; child = nextElement(*child))
    if (matches(*child, step) && ++seen == step.position) return child;
  return nullptr;
}

}  // namespace

XPathTarget resolveXPath(xercesc::DOMElement& root, const std::string& xpath) {
  std::vector<std::string> steps = splitSteps(xpath);
  XPathTarget target;
  if (steps.back()[0] == '@') {
    target.attribute = steps.back().substr(1);
    steps.pop_back();
    if (steps.empty()) throw badPath(xpath, "an attribute needs an element");
  }
  const Step first = parseStep(steps[0], xpath);
  if (!matches(root, first) || first.position != 1) throw badPath(xpath, "the root element is <" + name(root) + ">");
  xercesc::DOMElement* element = &root;
  for (std::size_t i = 1; i < steps.size(); ++i) {
    element = childMatching(*element, parseStep(steps[i], xpath));
    if (element == nullptr) throw badPath(xpath, "no element matches '" + steps[i] + "'");
  }
  if (!target.attribute.empty() && !hasAttribute(*element, target.attribute))
    throw badPath(xpath, "the element has no attribute '" + target.attribute + "'");
  target.element = element;
  return target;
}

}  // namespace airshape::xml
