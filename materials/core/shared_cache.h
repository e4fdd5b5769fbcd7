// A process-wide cache of immutable objects that are costly to build (per-material albedo
// tables): materials with the same key share one object. Thread-safe; an object is built
// outside the lock (builds take milliseconds to a fraction of a second), so two threads may
// both build one and the first stored wins. Bounded: a fit that moves a parameter
// continuously would otherwise grow it without end, so it is emptied when full (objects in use
// stay alive through their shared pointers).
#pragma once

#include <map>
#include <memory>
#include <mutex>

namespace scatterlab {

template <typename Key, typename Value> class SharedCache {
 public:
  explicit SharedCache(size_t maxEntries) : maxEntries_(maxEntries) {}

  // The object for `key`, built by make() (returning std::shared_ptr<const Value>) if absent.
  template <typename Make> std::shared_ptr<const Value> get(const Key& key, const Make& make) {
    {
      const std::lock_guard lock(mutex_);
      if (const auto it = entries_.find(key); it != entries_.end()) return it->second;
    }
    std::shared_ptr<const Value> value = make();
    const std::lock_guard lock(mutex_);
    if (entries_.size() >= maxEntries_) entries_.clear();
    return entries_.emplace(key, std::move(value)).first->second;
  }

 private:
  size_t maxEntries_;
  std::mutex mutex_;
  std::map<Key, std::shared_ptr<const Value>> entries_;
};

}  // namespace scatterlab
