#include "gmsh_session.h"

#include <gmsh.h>

#include "airshape/error.h"

namespace airshape::meshing {

namespace {

std::mutex& sessionMutex() {
  static std::mutex mutex;
  return mutex;
}

}  // namespace

GmshSession::GmshSession(const std::string& modelName) : lock_(sessionMutex()) {
  gmsh::initialize(0, nullptr, false);  // no gmshrc: a user's Gmsh settings must not change our meshes
  gmsh::option::setNumber("General.Terminal", 0);
  // One thread: Gmsh 4.8 meshes surfaces side by side through shared OCCT evaluators, which
  // made a mesh differ from run to run and once freed memory twice (docs/meshing.md).
  gmsh::option::setNumber("General.NumThreads", 1);
  gmsh::logger::start();
  gmsh::model::add(modelName);
}

GmshSession::~GmshSession() {
  try {
    gmsh::logger::stop();
    gmsh::finalize();
  } catch (...) {  // NOLINT: a destructor must not throw; Gmsh has nothing more to say here
  }
}

void callGmsh(const std::string& what, const std::function<void()>& call) {
  try {
    call();
  } catch (const std::string& message) {
    // Gmsh's message may end where its log goes on ("... intersect at point" and the point on
    // the next lines): the error lines of the log, joined, say it all.
    std::string said;
    std::vector<std::string> log;
    gmsh::logger::get(log);
    for (const std::string& line : log)
      if (line.rfind("Error", 0) == 0) said += (said.empty() ? "" : "; ") + line.substr(line.find(':') + 1);
    throw Error(ErrorCode::InvalidModel, what + " failed in Gmsh: " + (said.empty() ? message : said));
  }
}

std::vector<std::string> takeGmshMessages() {
  std::vector<std::string> messages;
  gmsh::logger::get(messages);
  gmsh::logger::stop();
  gmsh::logger::start();
  return messages;
}

}  // namespace airshape::meshing
