#include "airshape/viewer/page.h"

#include <cstdio>
#include <stdexcept>

namespace airshape::viewer {

namespace resources {
// Defined by the files viewer/embed_text.cmake generates: each text in pieces, null-ended.
extern const char* const page_html_parts[];
extern const char* const page_css_parts[];
extern const char* const page_js_parts[];
#if AIRSHAPE_VIEWER_HAS_THREE
extern const char* const three_js_parts[];
extern const char* const gltf_loader_js_parts[];
extern const char* const orbit_controls_js_parts[];
#endif
}  // namespace resources

namespace {

std::string joined(const char* const* parts) {
  std::string text;
  for (; *parts != nullptr; ++parts) text += *parts;
  return text;
}

/// A JSON string literal; "</" is written "<\/" so that the text cannot end a <script>.
std::string jsonString(const std::string& text) {
  std::string out = "\"";
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c == '/' && i > 0 && text[i - 1] == '<') {
      out += "\\/";
    } else if (c < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
      out += escaped;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

std::string htmlEscaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else
      out += c;
  }
  return out;
}

/// The components' JSON made safe inside a <script> element.
std::string scriptSafe(const std::string& json) {
  std::string out;
  for (std::size_t i = 0; i < json.size(); ++i) {
    out += json[i];
    if (json[i] == '<' && i + 1 < json.size() && json[i + 1] == '/') out += "\\";
  }
  return out;
}

/// The page template with each {{NAME}} replaced once by its value (values are not searched).
std::string filledPage(const PageContent& content, const std::string& config) {
  if (!available()) throw std::runtime_error(kUnavailable);
#if AIRSHAPE_VIEWER_HAS_THREE
  const std::pair<std::string, std::string> values[] = {{"TITLE", htmlEscaped(content.title)},
                                                        {"CSS", joined(resources::page_css_parts)},
                                                        {"THREE", joined(resources::three_js_parts)},
                                                        {"GLTF_LOADER", joined(resources::gltf_loader_js_parts)},
                                                        {"ORBIT_CONTROLS", joined(resources::orbit_controls_js_parts)},
                                                        {"CONFIG", config},
                                                        {"VIEWER", joined(resources::page_js_parts)}};
  const std::string page = joined(resources::page_html_parts);
  std::string out;
  std::size_t at = 0;
  while (true) {
    const std::size_t open = page.find("{{", at);
    if (open == std::string::npos) break;
    const std::size_t close = page.find("}}", open);
    const std::string name = page.substr(open + 2, close - open - 2);
    out.append(page, at, open - at);
    for (const auto& [key, value] : values)
      if (key == name) out += value;
    at = close + 2;
  }
  out.append(page, at, std::string::npos);
  return out;
#else
  (void)content;
  (void)config;
  return {};
#endif
}

std::string configJson(const PageContent& content, bool live, const std::string& model) {
  return "{\"title\": " + jsonString(content.title) + ", \"live\": " + (live ? "true" : "false") +
         ", \"model\": " + (model.empty() ? "null" : "\"" + model + "\"") +
         ", \"components\": " + scriptSafe(content.componentsJson) + "}";
}

}  // namespace

bool available() { return AIRSHAPE_VIEWER_HAS_THREE != 0; }

std::string threeVersion() { return available() ? AIRSHAPE_THREE_VERSION : ""; }

std::string base64(const std::string& bytes) {
  static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned value = (static_cast<unsigned char>(bytes[i]) << 16) |
                           (static_cast<unsigned char>(bytes[i + 1]) << 8) | static_cast<unsigned char>(bytes[i + 2]);
    for (int shift = 18; shift >= 0; shift -= 6) out += alphabet[(value >> shift) & 0x3F];
  }
  if (i < bytes.size()) {
    unsigned value = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) value |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    out += alphabet[(value >> 18) & 0x3F];
    out += alphabet[(value >> 12) & 0x3F];
    out += i + 1 < bytes.size() ? alphabet[(value >> 6) & 0x3F] : '=';
    out += '=';
  }
  return out;
}

std::string standalonePage(const PageContent& content, const std::string& glb) {
  return filledPage(content, configJson(content, false, base64(glb)));
}

std::string livePage(const PageContent& content) { return filledPage(content, configJson(content, true, "")); }

}  // namespace airshape::viewer
