// A thread-safe free list of reusable objects (buffers with their capacity, scratch structures):
// take() gives back the object returned last (the warmest in the CPU's caches) or a new, empty one;
// give_back() keeps it for the next take. Process-wide pools hold one as a function-local static.
#pragma once
#include <mutex>
#include <new>
#include <utility>
#include <vector>

namespace ontile {

template <class T>
class FreeList {
 public:
  // The most recently returned object, or T{} when none is kept.
  T take() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (free_.empty()) return T{};
    T item = std::move(free_.back());
    free_.pop_back();
    return item;
  }
  // Keeps `item` for a later take. With no memory to keep it, it is destroyed by its owner.
  void give_back(T&& item) noexcept {
    const std::lock_guard<std::mutex> lock(mutex_);
    try {
      free_.push_back(std::move(item));
    } catch (const std::bad_alloc&) {
      // push_back's strong guarantee: `item` still holds the object, and its owner frees it.
    }
  }

 private:
  std::mutex mutex_;
  std::vector<T> free_;
};

}  // namespace ontile
