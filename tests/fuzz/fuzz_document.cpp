// Fuzz target: a document read into the model, as every command reads its file (parse, typed
// model, uIDs, component graph), then written back. Any input may be refused with an Error;
// nothing may crash, hang or leak.
#include <cstddef>
#include <cstdint>
#include <string>

#include "airshape/configuration.h"
#include "airshape/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    airshape::Configuration configuration = airshape::Configuration::fromString(text, "fuzz.xml");
    (void)configuration.components().buildOrder();
    (void)configuration.document().toString();  // what `save` writes
  } catch (const airshape::Error&) {
  }
  return 0;
}
