#pragma once

#include <string>
#include <vector>

#include "airshape/named_shape.h"
#include "airshape/schema/generated/cpacs_model.h"

namespace airshape {
class Configuration;
}

namespace airshape::fuselage {

/// The build option that cuts duct assemblies out of wings and fuselages.
inline constexpr const char* kDuctCutOuts = "duct_cutouts";

/// The duct of this uID in any aircraft model, or null.
const schema::DuctType* ductNamed(const Configuration& configuration, const std::string& uid);

/// The duct assembly of this uID; throws Error when there is none.
const schema::DuctAssemblyType& ductAssemblyNamed(const Configuration& configuration, const std::string& uid);

/// A duct assembly: the Boolean union of its ducts, with the mirrored halves of those that
/// have a symmetry plane (the cutting tool the schema applies to wings and fuselages). Throws
/// NoShape for an assembly that names no duct.
NamedShape ductAssemblySolid(const Configuration& configuration, const schema::DuctAssemblyType& assembly);

/// The duct holding a duct segment of this uID; throws Error when there is none.
const schema::DuctType& ductHolding(const Configuration& configuration, const std::string& segmentUid);

/// What the duct assemblies cut out of the wing or fuselage with this uID while duct cut-outs
/// are on: the solid of every assembly of its model whose excludeObjectUIDs does not name it and
/// whose box meets the component's (none for a component of any other kind, or an assembly that
/// names no duct).
std::vector<NamedShape> ductCutOutsOf(const Configuration& configuration, const std::string& uid);

}  // namespace airshape::fuselage
