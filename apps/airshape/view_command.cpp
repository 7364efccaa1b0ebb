// `airshape view FILE`: serves the browser viewer (docs/viewer.md) on 127.0.0.1 and rebuilds
// the aircraft whenever FILE changes on disk, so that the open page shows each edit; a file
// that no longer loads is said in the page, which keeps the last good geometry.
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>

#include <boost/config.hpp>
#include <nlohmann/json.hpp>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/export/export_scene.h"
#include "airshape/export/viewer_content.h"
#include "airshape/plugin/plugin_host.h"
#include "airshape/viewer/page.h"
#include "commands.h"
#include "local_http_server.h"
#include "open_configuration.h"

namespace airshape::cli {

namespace {

std::atomic<bool> interrupted{false};

struct ViewOptions {
  CpacsInput input;
  int port = 0;
  bool openBrowser = true;
};

ViewOptions parseViewOptions(const Arguments& given, const plugin::PluginHost& host) {
  Arguments arguments = given;
  ViewOptions options;
  options.input.options = takeOptionFlags(arguments, host);
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string& argument = arguments[i];
    if (argument == "--port" && i + 1 < arguments.size()) {
      const std::string& text = arguments[++i];
      char* end = nullptr;
      const long port = std::strtol(text.c_str(), &end, 10);
      if (text.empty() || *end != '\0' || port < 0 || port > 65535)
        throw Error(ErrorCode::InvalidArgument, "--port: '" + text + "' is not a port number (0 to 65535)");
      options.port = static_cast<int>(port);
    } else if (argument == "--no-browser") {
      options.openBrowser = false;
    } else if (!argument.empty() && argument[0] != '-' && options.input.path.empty()) {
      options.input.path = argument;
    } else {
      throw Error(ErrorCode::InvalidArgument, "view: unexpected argument '" + argument + "' (see airshape help view)");
    }
  }
  if (options.input.path.empty())
    throw Error(ErrorCode::InvalidArgument, "usage: airshape view FILE [--port P] [--no-browser]");
  return options;
}

/// When and how large the file was last seen: a change of either is an edit.
struct FileStamp {
  long long modified = -1, size = -1;
  bool operator!=(const FileStamp& other) const { return modified != other.modified || size != other.size; }
};

FileStamp stampOf(const std::string& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) return {};
  return {static_cast<long long>(status.st_mtim.tv_sec) * 1000000000LL + status.st_mtim.tv_nsec,
          static_cast<long long>(status.st_size)};
}

/// What the page is served: the last geometry that was built, and the state of the file now.
struct ViewedModel {
  int version = -1;  ///< counts good builds; the page reloads when it changes
  std::string glb;
  std::string componentsJson = "[]";
  std::string error;                 ///< why the file does not load now ("" when it does)
  std::vector<std::string> leftOut;  ///< components of the last build that failed
  /// The control devices (flaps, slats, spoilers): uID, type, control parameter range and the
  /// parameter they are shown at, as JSON for the page's sliders.
  std::string devicesJson = "[]";
  std::map<std::string, double> deflections;  ///< devices away from rest, by uID
};

/// The moving components of a configuration with their ranges, at their parameters.
std::string devicesOf(const Configuration& configuration, const std::map<std::string, double>& deflections) {
  nlohmann::json devices = nlohmann::json::array();
  for (const graph::Component& component : configuration.components().components()) {
    const ComponentMotion* motion = configuration.shapes().findMotion(component.nodeType);
    if (motion == nullptr || component.uid.empty()) continue;
    try {
      const auto [first, last] = motion->range(configuration, component.uid);
      const auto deflected = deflections.find(component.uid);
      const double rest = std::clamp(0.0, std::min(first, last), std::max(first, last));
      devices.push_back({{"uid", component.uid},
                         {"type", component.typeName},
                         {"min", std::min(first, last)},
                         {"max", std::max(first, last)},
                         {"value", deflected == deflections.end() ? rest : deflected->second}});
    } catch (const std::exception&) {
      // a device that cannot move (broken path) gets no slider; building it says why
    }
  }
  return devices.dump();
}

/// Builds every component with its mirrored half and keeps it as the model's next version.
/// Throws Error when the file cannot be used or nothing in it can be built.
void build(const CpacsInput& input, plugin::PluginHost& host, ViewedModel& model) {
  const std::string& path = input.path;
  const auto start = std::chrono::steady_clock::now();
  const Configuration configuration = openConfiguration(input, host);
  exporting::ExportOptions options;
  options.mirror = true;  // the page turns mirrored halves on and off
  options.skipFailed = true;
  for (const auto& [uid, parameter] : model.deflections)
    options.poses.push_back({uid, exporting::Pose::At::Parameter, parameter});
  const exporting::ExportScene scene = exporting::buildScene(configuration, options);
  if (scene.components.empty())
    throw Error(ErrorCode::NotImplemented, "nothing to show: no component could be built", path);
  model.glb = exporting::sceneGlb(scene, options);
  model.componentsJson = exporting::viewerComponentsJson(scene);
  model.leftOut = scene.leftOut;
  model.devicesJson = devicesOf(configuration, model.deflections);
  model.error.clear();
  ++model.version;
  std::cerr << "view: built " << scene.components.size() << " components of " << path << " in " << std::fixed
            << std::setprecision(2) << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
            << " s\n";
}

/// A build after an edit: a failure is kept as the model's error, the last geometry stays.
void rebuild(const CpacsInput& input, plugin::PluginHost& host, ViewedModel& model) {
  try {
    build(input, host, model);
  } catch (const std::exception& error) {
    model.error = error.what();
    std::cerr << "view: " << model.error << " (the page keeps the last geometry)\n";
  }
}

/// POST /deflect?uid=U&parameter=P: shows device U at control parameter P (rebuilt now).
LocalHttpServer::Response deflect(const LocalHttpServer::Request& request, const CpacsInput& input,
                                  plugin::PluginHost& host, ViewedModel& model) {
  const auto uid = LocalHttpServer::parameter(request.query, "uid");
  const auto text = LocalHttpServer::parameter(request.query, "parameter");
  char* end = nullptr;
  const double parameter = text ? std::strtod(text->c_str(), &end) : 0.0;
  if (!uid || !text || text->empty() || *end != '\0')
    return {400, "text/plain; charset=utf-8", "deflect: give uid and a numeric parameter\n"};
  const nlohmann::json devices = nlohmann::json::parse(model.devicesJson);
  const auto device = std::find_if(devices.begin(), devices.end(), [&](const auto& d) { return d["uid"] == *uid; });
  if (device == devices.end()) return {400, "text/plain; charset=utf-8", "deflect: '" + *uid + "' is no device\n"};
  if (parameter < (*device)["min"].get<double>() || parameter > (*device)["max"].get<double>())
    return {400, "text/plain; charset=utf-8", "deflect: " + *text + " is outside the range of '" + *uid + "'\n"};
  model.deflections[*uid] = parameter;
  rebuild(input, host, model);
  return {200, "application/json", nlohmann::json({{"version", model.version}}).dump()};
}

LocalHttpServer::Response answer(const LocalHttpServer::Request& request, const CpacsInput& input,
                                 plugin::PluginHost& host, ViewedModel& model, const std::string& title, bool& quit) {
  if (request.method == "POST" && request.path == "/quit") {
    quit = true;
    return {200, "text/plain; charset=utf-8", "the airshape view server ends\n"};
  }
  if (request.method == "POST" && request.path == "/deflect") return deflect(request, input, host, model);
  if (request.method != "GET") return {405, "text/plain; charset=utf-8", "only GET, and POST /deflect or /quit\n"};
  if (request.path == "/" || request.path == "/index.html")
    return {200, "text/html; charset=utf-8", viewer::livePage({title, "[]"})};
  if (request.path == "/model.glb") return {200, "model/gltf-binary", model.glb};
  if (request.path == "/components.json") return {200, "application/json", model.componentsJson};
  if (request.path == "/devices") return {200, "application/json", model.devicesJson};
  if (request.path == "/version") {
    const nlohmann::json state = {{"version", model.version},
                                  {"error", model.error.empty() ? nlohmann::json() : nlohmann::json(model.error)},
                                  {"leftOut", model.leftOut}};
    return {200, "application/json", state.dump()};
  }
  return {404, "text/plain; charset=utf-8", "not found\n"};
}

/// Opens the page in the desktop's browser (xdg-open), if there is one; never waits for it.
void openInBrowser(const std::string& url) {
  if (::access("/usr/bin/xdg-open", X_OK) != 0) {
    std::cerr << "view: no browser to open (xdg-open is missing); open " << url << " yourself\n";
    return;
  }
  const pid_t child = ::fork();
  if (child == 0) {
    ::execl("/usr/bin/xdg-open", "xdg-open", url.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
}

}  // namespace

int runView(const Arguments& arguments, plugin::PluginHost& host) {
  const ViewOptions options = parseViewOptions(arguments, host);
  if (!viewer::available()) throw Error(ErrorCode::NotImplemented, viewer::kUnavailable);
  ViewedModel model;
  FileStamp seen = stampOf(options.input.path);
  build(options.input, host, model);  // a file that never loads is refused like any command's

  const std::string title = std::filesystem::path(options.input.path).filename().string();
  LocalHttpServer server(options.port);
  const std::string url = "http://127.0.0.1:" + std::to_string(server.port()) + "/";
  std::cout << "airshape view: " << url << " (Ctrl-C ends)" << std::endl;
  if (options.openBrowser) openInBrowser(url);
  std::signal(SIGINT, [](int) { interrupted = true; });
  std::signal(SIGTERM, [](int) { interrupted = true; });
  std::signal(SIGCHLD, SIG_IGN);  // browsers started are not waited for

  bool quit = false;
  while (!quit && !interrupted) {
    if (const auto request = server.next(250))
      server.respond(answer(*request, options.input, host, model, title, quit));
    const FileStamp now = stampOf(options.input.path);
    if (now != seen) {
      seen = now;
      rebuild(options.input, host, model);
    }
  }
  std::cerr << "view: ended\n";
  return kSuccess;
}

}  // namespace airshape::cli

// The entry the airshape command looks up when it loads the export module (command_modules.cpp).
extern "C" BOOST_SYMBOL_EXPORT int airshape_run_view(const airshape::cli::Arguments& arguments,
                                                     airshape::plugin::PluginHost& host) {
  return airshape::cli::runView(arguments, host);
}
