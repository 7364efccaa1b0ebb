#include "airshape/construction_guard.h"

#include <set>
#include <utility>

#include "airshape/error.h"

namespace airshape {

namespace {

/// The constructions under way on this thread, by what and uID.
thread_local std::set<std::pair<std::string, std::string>> underWay;

}  // namespace

ConstructionGuard::ConstructionGuard(std::string what, std::string uid, const std::string& message,
                                     const std::string& xpath)
    : what_(std::move(what)), uid_(std::move(uid)) {
  if (!underWay.emplace(what_, uid_).second) throw Error(ErrorCode::InvalidModel, message, {}, xpath);
}

ConstructionGuard::~ConstructionGuard() { underWay.erase({what_, uid_}); }

}  // namespace airshape
