#pragma once

#include <string>

namespace airshape {

/// Stops a construction that would need itself: while a guard for (`what`, `uid`) lives on a
/// thread, making another one for the same pair on that thread throws Error(InvalidModel) with
/// `message`, naming `xpath` (an element positioned on one positioned on it, a wall placed on a
/// wall placed on it), where the construction would otherwise recurse for ever.
class ConstructionGuard {
 public:
  ConstructionGuard(std::string what, std::string uid, const std::string& message, const std::string& xpath);
  ~ConstructionGuard();
  ConstructionGuard(const ConstructionGuard&) = delete;
  ConstructionGuard& operator=(const ConstructionGuard&) = delete;

 private:
  std::string what_;
  std::string uid_;
};

}  // namespace airshape
