#include "airshape/component_cache.h"

namespace airshape {

std::string ComponentCache::componentOfKey(const std::string& key) {
  const std::size_t colon = key.find(':');
  return colon == std::string::npos ? std::string() : key.substr(colon + 1);
}

void ComponentCache::clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  statistics_.invalidated += entries_.size();
  entries_.clear();
}

void ComponentCache::invalidate(const std::set<std::string>& componentUids) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto entry = entries_.begin(); entry != entries_.end();) {
    const std::string& component = entry->second.component;
    if (component.empty() || componentUids.count(component) > 0) {
      entry = entries_.erase(entry);
      ++statistics_.invalidated;
    } else {
      ++entry;
    }
  }
}

void ComponentCache::setAnchor(std::shared_ptr<const void> anchor) {
  std::lock_guard<std::mutex> lock(mutex_);
  anchor_ = std::move(anchor);
}

CacheStatistics ComponentCache::statistics() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return statistics_;
}

}  // namespace airshape
