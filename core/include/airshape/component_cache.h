#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

namespace airshape {

/// What plugins built for a configuration, by key (usually the component's uID and what
/// was built): built on first use, then reused by every later query.
class ComponentCache {
 public:
  /// The object stored under `key`, built by `build` if there is none yet.
  template <class T>
  std::shared_ptr<const T> obtain(const std::string& key, const std::function<std::shared_ptr<const T>()>& build) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (const auto found = entries_.find(key); found != entries_.end())
        return std::static_pointer_cast<const T>(found->second);
    }
    std::shared_ptr<const T> built = build();  // outside the lock: builders may obtain other entries
    std::lock_guard<std::mutex> lock(mutex_);
    return std::static_pointer_cast<const T>(entries_.emplace(key, built).first->second);
  }

  /// Forgets everything (after the model changed).
  void clear() {
    std::lock_guard<std::mutex> lock(mutex_);
    entries_.clear();
  }

 private:
  std::mutex mutex_;
  std::unordered_map<std::string, std::shared_ptr<const void>> entries_;
};

}  // namespace airshape
