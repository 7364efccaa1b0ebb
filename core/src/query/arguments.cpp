#include "airshape/query/arguments.h"

#include <algorithm>
#include <cmath>

#include "airshape/error.h"

namespace airshape::query {

namespace {

const Json& required(const Json& query, const char* name) {
  const auto entry = query.find(name);
  if (entry == query.end()) throw Error(ErrorCode::InvalidArgument, std::string("missing argument '") + name + "'");
  return *entry;
}

}  // namespace

double numberArgument(const Json& query, const char* name) {
  const Json& value = required(query, name);
  if (!value.is_number())
    throw Error(ErrorCode::InvalidArgument, std::string("argument '") + name + "' must be a number");
  const double number = value.get<double>();
  if (!std::isfinite(number))
    throw Error(ErrorCode::InvalidArgument, std::string("argument '") + name + "' must be finite");
  return number;
}

double fractionArgument(const Json& query, const char* name) {
  const double value = numberArgument(query, name);
  if (value < 0.0 || value > 1.0)
    throw Error(ErrorCode::InvalidArgument, std::string(name) + " = " + Json(value).dump() + " is outside [0, 1]");
  return value;
}

std::array<double, 3> pointArgument(const Json& query, const char* name) {
  const Json& value = required(query, name);
  const bool threeNumbers = value.is_array() && value.size() == 3 &&
                            std::all_of(value.begin(), value.end(), [](const Json& x) { return x.is_number(); });
  if (!threeNumbers) throw Error(ErrorCode::InvalidArgument, std::string("argument '") + name + "' must be [x, y, z]");
  const std::array<double, 3> point = {value[0].get<double>(), value[1].get<double>(), value[2].get<double>()};
  if (!std::all_of(point.begin(), point.end(), [](double x) { return std::isfinite(x); }))
    throw Error(ErrorCode::InvalidArgument, std::string("argument '") + name + "' must be finite");
  return point;
}

std::string stringArgument(const Json& query, const char* name) {
  const Json& value = required(query, name);
  if (!value.is_string())
    throw Error(ErrorCode::InvalidArgument, std::string("argument '") + name + "' must be a string");
  return value.get<std::string>();
}

bool booleanArgument(const Json& query, const char* name) {
  const Json& value = required(query, name);
  if (!value.is_boolean())
    throw Error(ErrorCode::InvalidArgument, std::string("argument '") + name + "' must be true or false");
  return value.get<bool>();
}

std::size_t selectByIndexOrUid(const Json& query, const char* name, const std::vector<std::string>& uids,
                               const std::string& what) {
  const Json& value = required(query, name);
  if (value.is_string()) {
    const std::string uid = value.get<std::string>();
    for (std::size_t i = 0; i < uids.size(); ++i)
      if (uids[i] == uid) return i;
    throw Error(ErrorCode::InvalidArgument, "no " + what + " with uID '" + uid + "'");
  }
  if (value.is_number_integer()) {
    const long long index = value.get<long long>();
    if (index < 1 || index > static_cast<long long>(uids.size())) {
      throw Error(ErrorCode::InvalidArgument,
                  what + " index " + std::to_string(index) + " is out of range (there " +
                      (uids.size() == 1 ? "is 1 " : "are " + std::to_string(uids.size()) + " ") + what +
                      (uids.size() == 1 ? ")" : "s)"));
    }
    return static_cast<std::size_t>(index - 1);
  }
  throw Error(ErrorCode::InvalidArgument,
              std::string("argument '") + name + "' must be a 1-based index or a uID string");
}

}  // namespace airshape::query
