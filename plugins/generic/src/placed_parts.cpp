#include "placed_parts.h"

#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/model/placement.h"
#include "airshape/schema/element_reading.h"
#include "airshape/xml/path.h"
#include "element_geometry.h"
#include "external_file.h"

namespace airshape::generic {

namespace {

using xercesc::DOMElement;

/// An element's own transformation, translated by the origin of `parentUid` (unless its
/// translation is absGlobal or there is no parent).
model::Transform placed(const Configuration& configuration, const DOMElement& element, const std::string& xpath,
                        const std::string& parentUid) {
  const auto transformation = schema::readChild<schema::TransformationType>(element, "transformation", xpath);
  return model::placedOnParent(configuration, transformation.get(), parentUid);
}

/// Whether an element lies in the vehicles' element definitions, outside the models, the
/// profiles and the materials (CPACS versions keep system elements in several places).
bool inElementLibrary(const std::string& path) {
  for (const char* outside : {"/cpacs/vehicles/aircraft/", "/cpacs/vehicles/rotorcraft/", "/cpacs/vehicles/profiles/",
                              "/cpacs/vehicles/materials/"})
    if (path.rfind(outside, 0) == 0) return false;
  return path.rfind("/cpacs/vehicles/", 0) == 0;
}

/// The element a component's reference (`reference`, e.g. systemElementUID) names, which must
/// be an element definition (`kind` says which in errors).
const DOMElement& referencedElement(const Configuration& configuration, const graph::Component& component,
                                    const std::string& reference, const std::string& kind) {
  const DOMElement* link = xml::firstChild(*component.element, reference);
  if (link == nullptr) throw NoShape("the component names no " + kind + ": no shape", component.xpath);
  const std::string uid = xml::text(*link);
  const DOMElement* element = configuration.uids().definition(uid);
  if (element == nullptr || !inElementLibrary(xml::pathOf(*element)))
    throw Error(ErrorCode::InvalidModel, "'" + uid + "' names no " + kind, {}, component.xpath + "/" + reference);
  return *element;
}

/// The shape of the geometry of a component's element, at the component's placement.
NamedShape elementShape(const Configuration& configuration, const fuselage::FuselageServices& fuselages,
                        const graph::Component& component, const DOMElement& element,
                        const model::Transform& placement) {
  const DOMElement* geometry = xml::firstChild(element, "geometry");
  const std::string elementPath = xml::pathOf(element);
  if (geometry == nullptr) throw NoShape("the element has no geometry (mass only): no shape", elementPath);
  return elementGeometry(configuration, fuselages, *geometry, elementPath + "/geometry", placement, component.uid);
}

}  // namespace

NamedShape systemComponentShape(const Configuration& configuration, const fuselage::FuselageServices& fuselages,
                                const std::string& uid) {
  const graph::Component& component = configuration.components().named(uid);
  const DOMElement& element = referencedElement(configuration, component, "systemElementUID", "system element");
  // A parentUID that names a component places it; else it sits in the aircraft's frame.
  const std::string parent =
      configuration.components().named(component.parentUid).nodeType == "genericSystem" ? "" : component.parentUid;
  return elementShape(configuration, fuselages, component, element,
                      placed(configuration, *component.element, component.xpath, parent));
}

NamedShape deckComponentShape(const Configuration& configuration, const fuselage::FuselageServices& fuselages,
                              const std::string& uid) {
  const graph::Component& component = configuration.components().named(uid);
  const DOMElement& element = referencedElement(configuration, component, "deckElementUID", "deck element");
  const graph::Component& deck = configuration.components().named(component.parentUid);
  const model::Transform deckPlacement = placed(configuration, *deck.element, deck.xpath, deck.parentUid);
  return elementShape(configuration, fuselages, component, element,
                      deckPlacement * placed(configuration, *component.element, component.xpath, ""));
}

NamedShape externalObjectShape(const Configuration& configuration, const std::string& uid) {
  const graph::Component& component = configuration.components().named(uid);
  const DOMElement* link = xml::firstChild(*component.element, "linkToFile");
  if (link == nullptr) throw Error(ErrorCode::InvalidModel, "no linkToFile given", {}, component.xpath);
  const TopoDS_Shape shape = readExternalFile(configuration, xml::text(*link), xml::attribute(*link, "format"),
                                              component.xpath + "/linkToFile");
  NamedShape named{shape, {}};
  for (TopExp_Explorer face(shape, TopAbs_FACE); face.More(); face.Next())
    named.faces.emplace_back(uid + "/external", TopoDS::Face(face.Current()));
  return transformedNamedShape(named, placed(configuration, *component.element, component.xpath, component.parentUid));
}

NamedShape compoundOfParts(const Configuration& configuration, const std::string& uid, const std::string& childType) {
  const DOMElement* whole = configuration.components().named(uid).element;
  // Its parts are the components inside its element, whatever parent their parentUID names.
  const auto inside = [whole](const graph::Component& part) {
    for (const xercesc::DOMNode* above = part.element->getParentNode(); above != nullptr;
         above = above->getParentNode())
      if (above == whole) return true;
    return false;
  };
  std::vector<const NamedShape*> parts;
  for (const graph::Component& child : configuration.components().components()) {
    if (child.nodeType != childType || !inside(child)) continue;
    try {
      parts.push_back(&configuration.shapes().namedShapeOf(configuration, child.uid));
    } catch (const NoShape&) {
      // a component described by its mass only: nothing to add
    }
  }
  if (parts.empty())
    throw NoShape("none of its components has a shape: no shape", configuration.components().named(uid).xpath);
  return compoundOfNamedShapes(parts);
}

}  // namespace airshape::generic
