#pragma once

#include <string>

#include <xercesc/util/XercesDefs.hpp>

XERCES_CPP_NAMESPACE_BEGIN
class DOMElement;
XERCES_CPP_NAMESPACE_END

namespace airshape {

/// The CPACS version a document declares: header/cpacsVersion or, since CPACS 3.5,
/// header/versionInfos/versionInfo/cpacsVersion (the entry header/version names, else
/// the last). Empty when the header declares none.
std::string declaredCpacsVersion(const xercesc::DOMElement& cpacsRoot);

/// Throws Error unless `root` is a <cpacs> element declaring a CPACS 3.x version.
void requireCpacs3(const xercesc::DOMElement& root, const std::string& file);

}  // namespace airshape
