#include "airshape/schema/element_reading.h"

#include <cmath>

#include "airshape/error.h"

namespace airshape::schema {

std::optional<double> numberIn(const xercesc::DOMElement& parent, const std::string& name, const std::string& xpath) {
  const xercesc::DOMElement* child = xml::firstChild(parent, name);
  if (child == nullptr) return std::nullopt;
  const std::string text = xml::text(*child);
  std::size_t used = 0;
  double value = NAN;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || text.find_first_not_of(" \t\r\n", used) != std::string::npos || !std::isfinite(value))
    throw Error(ErrorCode::InvalidModel, "'" + text + "' is not a number", {}, xpath + "/" + name);
  return value;
}

}  // namespace airshape::schema
