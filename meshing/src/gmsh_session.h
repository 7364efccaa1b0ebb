#pragma once

#include <functional>
#include <mutex>
#include <string>
#include <vector>

namespace airshape::meshing {

/// Gmsh's API for the time of one mesh: Gmsh keeps one global model, so one session at a time
/// in a process (others wait), with Gmsh's own output kept off the terminal and its messages
/// collected.
class GmshSession {
 public:
  explicit GmshSession(const std::string& modelName);
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

 private:
  std::unique_lock<std::mutex> lock_;
};

/// Runs a call into Gmsh; Gmsh's errors (it throws its last message as a string) become
/// Error(InvalidModel) saying `what` failed and why.
void callGmsh(const std::string& what, const std::function<void()>& call);

/// Gmsh's messages since the session began (or since the last call), "Error: ...",
/// "Warning: ..." and the like, and forgets them.
std::vector<std::string> takeGmshMessages();

}  // namespace airshape::meshing
