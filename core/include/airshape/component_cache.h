#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <unordered_map>

namespace airshape {

/// How a cache has been used since the configuration was opened.
struct CacheStatistics {
  std::size_t built = 0;        ///< objects built (first use, or again after an edit)
  std::size_t reused = 0;       ///< requests answered from the cache
  std::size_t invalidated = 0;  ///< objects forgotten because the model changed
  /// Builds per key ("geometry:W1", "shape:F1", ...), to see what an edit rebuilt.
  std::map<std::string, std::size_t> buildsByKey;
};

/// What plugins built for a configuration, by key: "<what>:<component uID>" for what
/// belongs to one component, a plain name for what belongs to the whole model. Built on
/// first use, then reused by every later query, until an edit invalidates it.
class ComponentCache {
 public:
  /// The object stored under `key`, built by `build` if there is none yet.
  template <class T>
  std::shared_ptr<const T> obtain(const std::string& key, const std::function<std::shared_ptr<const T>()>& build) {
    return obtainFor(key, componentOfKey(key), build);
  }
  /// The same for an object that depends on more than one component (a component cut by the cutters
  /// that pass through it): kept under `key` whatever it holds, forgotten on every edit.
  template <class T>
  std::shared_ptr<const T> obtainForWholeModel(const std::string& key,
                                               const std::function<std::shared_ptr<const T>()>& build) {
    return obtainFor(key, std::string(), build);
  }

  /// Forgets everything.
  void clear();
  /// Forgets what was built for these components and everything built for the whole model.
  void invalidate(const std::set<std::string>& componentUids);
  /// Objects built from now on keep `anchor` alive (the typed model they may point into),
  /// so that what an edit leaves cached stays valid when the model is read anew.
  void setAnchor(std::shared_ptr<const void> anchor);
  CacheStatistics statistics() const;

 private:
  struct Entry {
    std::shared_ptr<const void> value;
    std::shared_ptr<const void> anchor;
    std::string component;  ///< the uID of the component it was built for; "" the whole model
  };

  /// The component a key belongs to: what follows the first ':', or "" for the whole model.
  static std::string componentOfKey(const std::string& key);

  template <class T>
  std::shared_ptr<const T> obtainFor(const std::string& key, const std::string& component,
                                     const std::function<std::shared_ptr<const T>()>& build) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (const auto found = entries_.find(key); found != entries_.end()) {
        ++statistics_.reused;
        return std::static_pointer_cast<const T>(found->second.value);
      }
    }
    std::shared_ptr<const T> built = build();  // outside the lock: builders may obtain other entries
    std::lock_guard<std::mutex> lock(mutex_);
    const auto [entry, inserted] = entries_.emplace(key, Entry{built, anchor_, component});
    if (inserted) {
      ++statistics_.built;
      ++statistics_.buildsByKey[key];
    }
    return std::static_pointer_cast<const T>(entry->second.value);
  }

  mutable std::mutex mutex_;
  std::unordered_map<std::string, Entry> entries_;
  std::shared_ptr<const void> anchor_;
  CacheStatistics statistics_;
};

}  // namespace airshape
