#pragma once

#include <string>

#include <xercesc/dom/DOMElement.hpp>

#include "airshape/fuselage/fuselage_services.h"
#include "airshape/model/placement.h"
#include "airshape/named_shape.h"

namespace airshape {
class Configuration;
}

namespace airshape::generic {

/// The shape of a system or deck element's `geometry` (CPACS after 3.5): its cuboids (with
/// a smaller upper face where given), cylinders, cones, ellipsoids, tori, multi-segment
/// shapes (lofted as fuselages are) and external CAD files, each moved by its own
/// transformation, all by the geometry's, then by `placement` (the component's place in
/// the aircraft). Faces are named "<uid>/<kind> <n>". Throws NoShape for a geometry with no
/// part, Error naming the part for a part that cannot be built.
NamedShape elementGeometry(const Configuration& configuration, const fuselage::FuselageServices& fuselages,
                           const xercesc::DOMElement& geometry, const std::string& xpath,
                           const model::Transform& placement, const std::string& uid);

}  // namespace airshape::generic
