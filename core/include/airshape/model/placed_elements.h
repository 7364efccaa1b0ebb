#pragma once

#include <string>
#include <unordered_map>

#include <Eigen/Geometry>

#include "airshape/configuration.h"
#include "airshape/model/placement.h"

namespace airshape::model {

/// The translation of each section (by uID) that positionings give: the toPoint of the
/// first positioning that targets it, chained through fromSectionUID. Throws Error when a
/// fromSectionUID names a section no positioning reaches, or when positionings loop.
std::unordered_map<std::string, Eigen::Vector3d> positioningTranslations(const schema::PositioningsType* positionings);

/// A section element with the full transformation C · Pos(section) · Sec · Elem that takes
/// its profile to global coordinates.
template <class Element>
struct PlacedElement {
  const Element* element;
  Transform transform;
};

/// Every section element of a body with sections, elements and positionings, placed by the
/// component matrix `componentMatrix`, by element uID. Throws Error for broken positionings.
template <class Component>
auto placedElements(const Component& component, const Transform& componentMatrix) {
  using Element = std::decay_t<decltype(component.sections->section[0].elements->element[0])>;
  std::unordered_map<std::string, PlacedElement<Element>> placed;
  if (!component.sections) return placed;
  const auto positioning = positioningTranslations(component.positionings.get());
  for (const auto& section : component.sections->section) {
    Transform sectionMatrix = componentMatrix;
    if (const auto shift = positioning.find(section.uID); shift != positioning.end())
      sectionMatrix.translate(shift->second);
    sectionMatrix = sectionMatrix * transformationMatrix(section.transformation.get());
    if (!section.elements) continue;
    for (const auto& element : section.elements->element)
      placed.emplace(element.uID, PlacedElement<Element>{
                                      &element, sectionMatrix * transformationMatrix(element.transformation.get())});
  }
  return placed;
}

/// Every section element of a lofted component (any component with sections, elements and
/// positionings) placed by its component transformation, by element uID.
template <class Component>
auto placedElements(const Configuration& configuration, const Component& component) {
  return placedElements(component, componentTransform(configuration, component.uID));
}

}  // namespace airshape::model
