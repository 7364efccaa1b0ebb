#include "airshape/configuration.h"

#include <xercesc/dom/DOM.hpp>

#include "airshape/cpacs_version.h"
#include "airshape/error.h"
#include "airshape/model/primary_model.h"
#include "airshape/schema/dom_reader.h"
#include "airshape/schema/dom_writer.h"
#include "airshape/schema/generated/cpacs_model.h"
#include "airshape/uid/repeated_uids.h"

namespace airshape {

Configuration::Configuration(xml::Document document, const std::vector<graph::ComponentLocation>& locations)
    : document_(std::move(document)), cpacs_(std::make_unique<schema::CpacsType>()) {
  xercesc::DOMElement& root = *document_.root();
  requireCpacs3(root, document_.source());
  cpacsVersion_ = declaredCpacsVersion(root);

  schema::ReadReport report;
  schema::readNode(root, *cpacs_, "/cpacs", report);
  schemaProblems_ = std::move(report.problems);

  uids_.build(root, report.references);
  uid::setAsideRepeatedUids(*cpacs_, uids_);
  for (const Problem& problem : uids_.problems())
    warnings_.push_back({Problem::Severity::Warning, problem.xpath, problem.message});

  const Problems skipped = model::primaryModel(*cpacs_).skipped;
  warnings_.insert(warnings_.end(), skipped.begin(), skipped.end());
  try {
    components_ = graph::ComponentGraph::build(root, locations, warnings_);
  } catch (const Error& error) {
    throw error.inFile(document_.source());
  }
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

const ComponentShapes& Configuration::noShapes() {
  static const ComponentShapes none;
  return none;
}

void Configuration::writeModel() { schema::writeNode(*cpacs_, *document_.root()); }

void Configuration::save(const std::string& path) {
  writeModel();
  document_.save(path);
}

}  // namespace airshape
