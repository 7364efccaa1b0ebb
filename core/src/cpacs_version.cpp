#include "airshape/cpacs_version.h"

#include <xercesc/dom/DOM.hpp>

#include "airshape/error.h"
#include "airshape/xml/text.h"

namespace airshape {

using namespace xercesc;

namespace {

std::string trimmed(std::string text) {
  text.erase(0, text.find_first_not_of(" \t\r\n"));
  text.erase(text.find_last_not_of(" \t\r\n") + 1);
  return text;
}

}  // namespace

std::string declaredCpacsVersion(const DOMElement& root) {
  const DOMElement* header = xml::firstChild(root, "header");
  if (header == nullptr) return {};
  if (const DOMElement* version = xml::firstChild(*header, "cpacsVersion")) return trimmed(xml::text(*version));
  const DOMElement* infos = xml::firstChild(*header, "versionInfos");
  if (infos == nullptr) return {};
  const DOMElement* headerVersion = xml::firstChild(*header, "version");
  const std::string wanted = headerVersion ? trimmed(xml::text(*headerVersion)) : std::string();
  std::string last;
  for (const DOMElement* info = xml::firstElement(*infos); info != nullptr; info = xml::nextElement(*info)) {
    const DOMElement* version = xml::firstChild(*info, "cpacsVersion");
    if (version == nullptr) continue;
    last = trimmed(xml::text(*version));
    if (!wanted.empty() && trimmed(xml::attribute(*info, "version")) == wanted) return last;
  }
  return last;
}

void requireCpacs3(const DOMElement& root, const std::string& file) {
  const std::string rootName = xml::name(root);
  if (rootName != "cpacs")
    throw Error(ErrorCode::NotCpacs, "not a CPACS document (the root element is <" + rootName + ">, not <cpacs>)",
                file);
  const std::string version = declaredCpacsVersion(root);
  if (version.empty()) {
    throw Error(ErrorCode::UnsupportedVersion,
                "declares no CPACS version (no /cpacs/header/cpacsVersion nor versionInfos); files without one are "
                "CPACS 2 or older, and airshape reads CPACS 3",
                file);
  }
  const std::string major = version.substr(0, version.find('.'));
  if (major == "3") return;
  if (major == "2" || major == "1" || major == "0")
    throw Error(ErrorCode::UnsupportedVersion,
                "is a CPACS " + major + " file (cpacsVersion " + version + "); airshape reads CPACS 3", file,
                "/cpacs/header/cpacsVersion");
  throw Error(ErrorCode::UnsupportedVersion, "declares CPACS version " + version + "; airshape reads CPACS 3", file,
              "/cpacs/header/cpacsVersion");
}

}  // namespace airshape
