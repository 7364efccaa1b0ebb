#pragma once

#include <map>
#include <memory>
#include <string>

namespace airshape::plugin {

/// What plugins offer each other: objects behind small abstract interfaces that the providing
/// plugin keeps in its own folder (plugins/NAME/include/airshape/NAME/...), by name. The name
/// carries the interface's version ("airshape.NAME/1"), since plugins are separate libraries
/// and share no type information: a consumer gets exactly the interface the name promises.
class ServiceRegistry {
 public:
  template <class Interface>
  void offer(const std::string& name, std::shared_ptr<const Interface> service) {
    services_[name] = std::move(service);
  }

  /// The service offered under `name`, or nullptr.
  template <class Interface>
  std::shared_ptr<const Interface> find(const std::string& name) const {
    const auto entry = services_.find(name);
    return entry == services_.end() ? nullptr : std::static_pointer_cast<const Interface>(entry->second);
  }

 private:
  std::map<std::string, std::shared_ptr<const void>> services_;
};

}  // namespace airshape::plugin
