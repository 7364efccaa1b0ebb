#pragma once

#include <string>

namespace airshape::viewer {

/// Whether this build carries the viewer: three.js was fetched with npm when it was built.
bool available();

/// What to say when it does not.
inline constexpr const char* kUnavailable =
    "this build has no viewer: npm was missing when it was built (docs/viewer.md)";

/// The three.js version the viewer carries ("" without it).
std::string threeVersion();

/// What the page knows before it shows anything: the title, and for each component its
/// name (the glTF node's), type and measures, as a JSON array (see viewer.js).
struct PageContent {
  std::string title;
  std::string componentsJson = "[]";
};

/// A page that opens from disk with no network: the viewer's scripts and the model (GLB
/// bytes, inlined in base64) in one HTML file. Requires available().
std::string standalonePage(const PageContent& content, const std::string& glb);

/// The page `airshape view` serves: it fetches /model.glb and /components.json, and polls
/// /version to reload them when the file changes. Requires available().
std::string livePage(const PageContent& content);

/// Base64 of bytes (RFC 4648, with padding).
std::string base64(const std::string& bytes);

}  // namespace airshape::viewer
