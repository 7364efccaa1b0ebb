#pragma once

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace airshape::schema {

/// A child element that occurs at most once. Held by pointer so that generated
/// classes can refer to each other in any order and recursively.
template <class T>
class Child {
 public:
  explicit operator bool() const { return node_ != nullptr; }
  T* get() const { return node_.get(); }
  T& operator*() const { return *node_; }
  T* operator->() const { return node_.get(); }

  /// Creates the child (replacing any present one) and returns it.
  T& emplace() {
    node_ = std::make_unique<T>();
    return *node_;
  }
  void reset() { node_.reset(); }

 private:
  std::unique_ptr<T> node_;
};

/// A child element that may occur several times, in document order.
template <class T>
class List {
 public:
  class Iterator {
   public:
    using Inner = typename std::vector<std::unique_ptr<T>>::const_iterator;
    explicit Iterator(Inner inner) : inner_(inner) {}
    T& operator*() const { return **inner_; }
    T* operator->() const { return inner_->get(); }
    Iterator& operator++() {
      ++inner_;
      return *this;
    }
    bool operator!=(const Iterator& other) const { return inner_ != other.inner_; }
    bool operator==(const Iterator& other) const { return inner_ == other.inner_; }

   private:
    Inner inner_;
  };

  std::size_t size() const { return items_.size(); }
  bool empty() const { return items_.empty(); }
  T& operator[](std::size_t index) const { return *items_[index]; }
  Iterator begin() const { return Iterator(items_.begin()); }
  Iterator end() const { return Iterator(items_.end()); }

  T& append() {
    items_.push_back(std::make_unique<T>());
    return *items_.back();
  }
  void erase(std::size_t index) { items_.erase(items_.begin() + static_cast<std::ptrdiff_t>(index)); }
  void clear() { items_.clear(); }

 private:
  std::vector<std::unique_ptr<T>> items_;
};

}  // namespace airshape::schema
