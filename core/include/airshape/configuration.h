#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "airshape/component_cache.h"
#include "airshape/component_shapes.h"
#include "airshape/graph/component_graph.h"
#include "airshape/problem.h"
#include "airshape/uid/uid_registry.h"
#include "airshape/xml/document.h"

namespace airshape::schema {
class CpacsType;
}

namespace airshape {

/// A CPACS 3 document opened for geometry: the kept XML document, the typed model
/// bound to it, the uID registry and the component graph.
class Configuration {
 public:
  /// Opens a file. Throws Error naming the file when it is missing, not XML, not CPACS,
  /// CPACS 2 (or older), or when its components form a parentUID cycle. Flaws the geometry
  /// can live with (schema violations, duplicate uIDs, dangling uIDrefs) are recorded in
  /// problems() and warnings() instead. Components are found at `locations` (those the loaded
  /// plugins declare: plugin::PluginHost::componentLocations); by default only the model.
  static Configuration open(const std::string& path,
                            const std::vector<graph::ComponentLocation>& locations = graph::resolveLocations({}));
  /// Opens a document held in a string; `name` stands for it in messages.
  static Configuration fromString(const std::string& xml, const std::string& name = "<string>",
                                  const std::vector<graph::ComponentLocation>& locations = graph::resolveLocations({}));

  Configuration(Configuration&&) noexcept;
  Configuration& operator=(Configuration&&) noexcept;
  ~Configuration();

  const std::string& source() const { return document_.source(); }
  /// The CPACS version the header declares, e.g. "3.5".
  const std::string& cpacsVersion() const { return cpacsVersion_; }

  schema::CpacsType& cpacs() const { return *cpacs_; }
  const xml::Document& document() const { return document_; }
  const uid::UidRegistry& uids() const { return uids_; }
  const graph::ComponentGraph& components() const { return components_; }

  /// Every schema violation found while reading (for `validate`).
  const Problems& schemaProblems() const { return schemaProblems_; }
  /// Those schema violations whose value could not be read at all ('abc' for a number): the
  /// value is left out of the model (a required number reads as 0), which changes the
  /// geometry, so the CLI prints them whenever a file is opened.
  const Problems& unreadableValues() const { return unreadableValues_; }
  /// What loading ignored or worked around: duplicate uIDs, dangling references, parents that
  /// are no components. Printed on stderr by the CLI when a file is opened.
  const Problems& warnings() const { return warnings_; }

  /// Geometry built from this configuration, kept until the model changes.
  ComponentCache& cache() const { return *cache_; }

  /// Records a warning of building: something odd about the geometry that was built all the
  /// same (a profile that crosses itself within the tolerance), naming its CPACS path. Each
  /// warning is kept once; builders call this from any thread.
  void warnAboutGeometry(const Problem& warning) const;
  /// The warnings of building so far, in the order they came (the CLI prints them).
  Problems geometryWarnings() const;

  /// The builders of component solids (those the loaded plugins registered).
  const ComponentShapes& shapes() const { return *shapes_; }
  void useShapes(const ComponentShapes& shapes) { shapes_ = &shapes; }

  /// Turns a build option on or off: one that a loaded plugin declares with its cut-outs
  /// (ComponentShapes::cutOuts, e.g. "duct_cutouts"; all are off when a file is opened). What
  /// was built under the other setting is forgotten. Throws Error(InvalidArgument) for a name
  /// no loaded plugin declares, saying which it knows.
  void setOption(const std::string& name, bool on);
  /// Whether a build option is on.
  bool option(const std::string& name) const { return options_.count(name) > 0; }

  /// Writes the model's values into the document (only what differs from it).
  void writeModel();

  // Editing. Each edit leaves the document, the typed model, the uIDs and the component
  // graph consistent, and invalidates in the cache exactly what was built for the
  // components the edit can change (their fingerprints, model/component_fingerprints.h)
  // and for those attached below them; the rest is reused.

  /// The text of the element, or the value of the attribute, an XPath addresses
  /// (xml/xpath.h). Throws Error(InvalidArgument) naming the path when it addresses nothing.
  std::string value(const std::string& xpath) const;
  /// Sets the text of the element (a leaf: it must hold no elements) or the attribute an
  /// XPath addresses, and reads the model anew. A value the schema refuses there (text
  /// for a number, say), or one that breaks the model (a parentUID cycle), is an Error and
  /// the document is left as it was.
  void setValue(const std::string& xpath, const std::string& value);
  /// The element an XPath addresses, with all it holds, as XML text (to copy it, say).
  std::string xmlOf(const std::string& xpath) const;
  /// Inserts the elements of an XML fragment (one or more elements, e.g. a <section> with
  /// its elements) as children of the element an XPath addresses, before its `position`-th
  /// child element (1-based; 0 appends). The fragment must be well-formed and leave the
  /// document usable (new uIDs unique, uIDrefs resolvable, no cycle); otherwise Error and
  /// the document is left as it was.
  void insertXml(const std::string& parentXPath, const std::string& fragment, std::size_t position = 0);
  /// Removes the element an XPath addresses, with all it holds; the same checks apply.
  void remove(const std::string& xpath);
  /// After editing the typed model (cpacs()) directly: writes it into the document and
  /// brings uIDs, components and cache up to date. The typed model is kept as it is.
  void modelChanged();
  /// Writes the model into the document and saves it atomically to `path`.
  void save(const std::string& path);

 private:
  Configuration(xml::Document document, const std::vector<graph::ComponentLocation>& locations);
  /// Reads the typed model, the uIDs and the component graph from the document.
  void load();
  /// Invalidates in the cache what was built for components whose fingerprint changed
  /// since the last edit (and for those attached below them).
  void invalidateChangedComponents();
  /// Applies a change to the document, reads the model anew and invalidates what depends
  /// on it; `undo` restores the document when the result is refused. `checkedPath` names
  /// the element whose new schema problems refuse the change ("" for none).
  void applyEdit(const std::function<void()>& change, const std::function<void()>& undo, const std::string& checkedPath,
                 const std::string& what);

  xml::Document document_;
  std::vector<graph::ComponentLocation> locations_;
  std::shared_ptr<schema::CpacsType> cpacs_;
  std::string cpacsVersion_;
  uid::UidRegistry uids_;
  graph::ComponentGraph components_;
  Problems schemaProblems_;
  Problems unreadableValues_;
  Problems warnings_;
  std::unique_ptr<ComponentCache> cache_ = std::make_unique<ComponentCache>();
  struct GeometryWarnings;
  std::unique_ptr<GeometryWarnings> geometryWarnings_;
  std::map<std::string, std::uint64_t> fingerprints_;  // of the components, as of the last edit
  std::set<std::string> options_;                      // the build options that are on
  const ComponentShapes* shapes_ = &noShapes();
  static const ComponentShapes& noShapes();
};

}  // namespace airshape
