#include "airshape/configuration.h"

#include <mutex>
#include <set>

#include <xercesc/dom/DOM.hpp>

#include "airshape/cpacs_version.h"
#include "airshape/error.h"
#include "airshape/model/component_fingerprints.h"
#include "airshape/schema/dom_reader.h"
#include "airshape/schema/dom_writer.h"
#include "airshape/schema/generated/cpacs_model.h"
#include "airshape/uid/repeated_uids.h"
#include "airshape/xml/nesting.h"
#include "airshape/xml/path.h"
#include "airshape/xml/text.h"
#include "airshape/xml/xpath.h"

namespace airshape {

struct Configuration::GeometryWarnings {
  std::mutex mutex;
  Problems warnings;
};

Configuration::Configuration(xml::Document document, const std::vector<graph::ComponentLocation>& locations)
    : document_(std::move(document)), locations_(locations), geometryWarnings_(std::make_unique<GeometryWarnings>()) {
  xercesc::DOMElement& root = *document_.root();
  requireCpacs3(root, document_.source());
  cpacsVersion_ = declaredCpacsVersion(root);
  load();
}

void Configuration::load() {
  xercesc::DOMElement& root = *document_.root();
  auto cpacs = std::make_shared<schema::CpacsType>();
  schema::ReadReport report;
  schema::readNode(root, *cpacs, "/cpacs", report);

  uid::UidRegistry uids;
  uids.build(root, report.references);
  uid::setAsideRepeatedUids(*cpacs, uids);
  Problems warnings;
  for (const Problem& problem : uids.problems())
    warnings.push_back({Problem::Severity::Warning, problem.xpath, problem.message});
  graph::ComponentGraph components;
  try {
    components = graph::ComponentGraph::build(root, locations_, *cpacs, warnings);
  } catch (const Error& error) {
    throw error.inFile(document_.source());
  }
  // Only now, when nothing can fail any more, does the configuration change.
  cpacs_ = std::move(cpacs);
  schemaProblems_ = std::move(report.problems);
  unreadableValues_ = std::move(report.unreadableValues);
  uids_ = std::move(uids);
  warnings_ = std::move(warnings);
  components_ = std::move(components);
  cache_->setAnchor(cpacs_);
}

Configuration Configuration::open(const std::string& path, const std::vector<graph::ComponentLocation>& locations) {
  return Configuration(xml::Document::fromFile(path), locations);
}

Configuration Configuration::fromString(const std::string& text, const std::string& name,
                                        const std::vector<graph::ComponentLocation>& locations) {
  return Configuration(xml::Document::fromString(text, name), locations);
}

Configuration::Configuration(Configuration&&) noexcept = default;
Configuration& Configuration::operator=(Configuration&&) noexcept = default;
Configuration::~Configuration() = default;

void Configuration::setOption(const std::string& name, bool on) {
  std::string known;
  for (const ComponentCutOuts& cutOuts : shapes().cutOuts()) {
    if (cutOuts.option == name) {
      if (option(name) == on) return;
      if (on) {
        options_.insert(name);
      } else {
        options_.erase(name);
      }
      cache().clear();
      return;
    }
    known += (known.empty() ? "" : ", ") + cutOuts.option;
  }
  throw Error(ErrorCode::InvalidArgument, "no build option '" + name + "' (the loaded plugins declare " +
                                              (known.empty() ? std::string("none") : known) + ")");
}

const ComponentShapes& Configuration::noShapes() {
  static const ComponentShapes none;
  return none;
}

void Configuration::warnAboutGeometry(const Problem& warning) const {
  const std::lock_guard<std::mutex> lock(geometryWarnings_->mutex);
  for (const Problem& known : geometryWarnings_->warnings)
    if (known.xpath == warning.xpath && known.message == warning.message) return;
  geometryWarnings_->warnings.push_back(warning);
}

Problems Configuration::geometryWarnings() const {
  const std::lock_guard<std::mutex> lock(geometryWarnings_->mutex);
  return geometryWarnings_->warnings;
}

void Configuration::writeModel() { schema::writeNode(*cpacs_, *document_.root()); }

std::string Configuration::value(const std::string& xpath) const {
  const xml::XPathTarget target = xml::resolveXPath(*document_.root(), xpath);
  return target.attribute.empty() ? xml::text(*target.element) : xml::attribute(*target.element, target.attribute);
}

void Configuration::setValue(const std::string& xpath, const std::string& value) {
  const xml::XPathTarget target = xml::resolveXPath(*document_.root(), xpath);
  if (target.attribute.empty() && xml::firstElement(*target.element) != nullptr)
    throw Error(ErrorCode::InvalidArgument, "XPath " + xpath + ": addresses an element holding elements, not a value");
  const std::string previous = this->value(xpath);
  const auto write = [&](const std::string& text) {
    if (target.attribute.empty())
      xml::setText(*target.element, text);
    else
      target.element->setAttribute(xml::toXml(target.attribute).c_str(), xml::toXml(text).c_str());
  };
  applyEdit([&] { write(value); }, [&] { write(previous); }, xml::pathOf(*target.element), xpath);
}

std::string Configuration::xmlOf(const std::string& xpath) const {
  const xml::XPathTarget target = xml::resolveXPath(*document_.root(), xpath);
  if (!target.attribute.empty()) throw Error(ErrorCode::InvalidArgument, "XPath " + xpath + ": names an attribute");
  std::string text = xml::serialized(*target.element);
  if (text.rfind("<?xml", 0) == 0) text.erase(0, text.find("?>") + 2);  // no declaration for a fragment
  return text;
}

void Configuration::insertXml(const std::string& parentXPath, const std::string& fragment, std::size_t position) {
  xercesc::DOMElement& parent = *xml::resolveXPath(*document_.root(), parentXPath).element;
  const xml::Document parsed = xml::Document::fromString("<fragment>" + fragment + "</fragment>", "the XML to insert");
  std::size_t parentDepth = 1;
  for (const xercesc::DOMNode* above = parent.getParentNode(); above != nullptr; above = above->getParentNode())
    parentDepth += above->getNodeType() == xercesc::DOMNode::ELEMENT_NODE ? 1 : 0;
  xml::requireNestingWithinLimit(*parsed.root(), "the XML to insert",
                                 parentDepth);  // the wrapper stands for the parent
  xercesc::DOMNode* before = nullptr;
  if (position > 0) {
    before = xml::firstElement(parent);
    for (std::size_t k = 1; k < position && before != nullptr; ++k) before = xml::nextElement(*before);
    if (before == nullptr)
      throw Error(ErrorCode::InvalidArgument,
                  "XPath " + parentXPath + ": has fewer than " + std::to_string(position) + " child elements");
  }
  std::vector<xercesc::DOMNode*> inserted;
  for (xercesc::DOMElement* element = xml::firstElement(*parsed.root()); element != nullptr;
       element = xml::nextElement(*element))
    inserted.push_back(document_.dom().importNode(element, true));
  if (inserted.empty()) throw Error(ErrorCode::InvalidArgument, "the XML to insert holds no element");
  applyEdit(
      [&] {
        for (xercesc::DOMNode* node : inserted) parent.insertBefore(node, before);
      },
      [&] {
        for (xercesc::DOMNode* node : inserted) parent.removeChild(node)->release();
      },
      xml::pathOf(parent), parentXPath);
}

void Configuration::remove(const std::string& xpath) {
  const xml::XPathTarget target = xml::resolveXPath(*document_.root(), xpath);
  if (!target.attribute.empty()) throw Error(ErrorCode::InvalidArgument, "XPath " + xpath + ": names an attribute");
  if (target.element == document_.root()) throw Error(ErrorCode::InvalidArgument, "cannot remove the root element");
  xercesc::DOMNode* parent = target.element->getParentNode();
  xercesc::DOMNode* next = target.element->getNextSibling();
  applyEdit([&] { parent->removeChild(target.element); }, [&] { parent->insertBefore(target.element, next); }, "",
            xpath);
  target.element->release();
}

void Configuration::applyEdit(const std::function<void()>& change, const std::function<void()>& undo,
                              const std::string& checkedPath, const std::string& what) {
  // Problems name paths with [1] on every step, pathOf only where siblings share a name.
  const auto withoutFirstPositions = [](std::string path) {
    for (std::size_t at = path.find("[1]"); at != std::string::npos; at = path.find("[1]", at)) path.erase(at, 3);
    return path;
  };
  const std::string checked = withoutFirstPositions(checkedPath);
  const auto problemsThere = [&] {
    std::set<std::string> messages;
    if (checked.empty()) return messages;
    for (const Problem& problem : schemaProblems_)
      if (withoutFirstPositions(problem.xpath).rfind(checked, 0) == 0) messages.insert(problem.message);
    return messages;
  };
  const std::set<std::string> problemsBefore = problemsThere();
  const std::size_t uidProblemsBefore = uids_.problems().size();
  if (fingerprints_.empty()) fingerprints_ = model::componentFingerprints(*this);
  change();
  try {
    load();
    for (const std::string& problem : problemsThere())
      if (problemsBefore.count(problem) == 0)
        throw Error(ErrorCode::InvalidArgument, "refused: " + problem, document_.source(), what);
    if (uids_.problems().size() > uidProblemsBefore)
      throw Error(ErrorCode::InvalidArgument, "refused: " + uids_.problems().back().message, document_.source(), what);
  } catch (...) {
    undo();
    load();
    throw;
  }
  invalidateChangedComponents();
}

void Configuration::modelChanged() {
  if (fingerprints_.empty()) fingerprints_ = model::componentFingerprints(*this);
  const std::shared_ptr<schema::CpacsType> edited = cpacs_;
  writeModel();
  load();
  cpacs_ = edited;  // the caller's model stays the one in use
  cache_->setAnchor(cpacs_);
  invalidateChangedComponents();
}

void Configuration::invalidateChangedComponents() {
  std::map<std::string, std::uint64_t> fingerprints = model::componentFingerprints(*this);
  cache_->invalidate(model::changedComponents(*this, fingerprints_, fingerprints));
  fingerprints_ = std::move(fingerprints);
}

void Configuration::save(const std::string& path) {
  writeModel();
  document_.save(path);
}

}  // namespace airshape
