#pragma once

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace airshape::schema {

/// A child element that occurs at most once. Held by pointer so that generated
/// classes can refer to each other in any order and recursively.
///
/// It owns a plain pointer, not a std::unique_ptr: the generated model has some 600 such members,
/// and GCC instantiating std::unique_ptr for each of them cost 5 s in every source that includes
/// the model (docs/building.md). The child is destroyed with its holder, whose destructor is
/// defined where every generated class is complete.
template <class T>
class Child {
 public:
  Child() = default;
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;
  ~Child() { delete node_; }

  explicit operator bool() const { return node_ != nullptr; }
  T* get() const { return node_; }
  T& operator*() const { return *node_; }
  T* operator->() const { return node_; }

  /// Creates the child (replacing any present one) and returns it.
  T& emplace() {
    reset();
    node_ = new T();
    return *node_;
  }
  void reset() {
    delete node_;
    node_ = nullptr;
  }

 private:
  T* node_ = nullptr;
};

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
