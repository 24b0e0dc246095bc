// An allocator whose value-less construct() default-initialises, so that
// std::vector<T, DefaultInitAllocator<T>>::resize(n) leaves new arithmetic
// elements uninitialised instead of zero-filling them: for buffers that are
// written in full right after growing (a memset of tens of MB per run
// otherwise). Everything else is std::allocator's.
//
// Example:
//   std::vector<double, ris::DefaultInitAllocator<double>> sums;
//   sums.resize(rows * bins);  // no zero fill: every element written next
#pragma once

#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace ris {

template <typename T>
class DefaultInitAllocator : public std::allocator<T> {
 public:
  using std::allocator<T>::allocator;
  template <typename U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    std::allocator_traits<std::allocator<T>>::construct(static_cast<std::allocator<T>&>(*this), p,
                                                        std::forward<Args>(args)...);
  }
};

}  // namespace ris
