// An allocator whose value-less construct() default-initialises, so that
// std::vector<T, DefaultInitAllocator<T>>::resize(n) leaves new arithmetic
// elements uninitialised instead of zero-filling them: for buffers that are
// written in full right after growing (a memset of tens of MB per run
// otherwise). Everything else is std::allocator's.
//
// UninitVector<T> is that vector: the type of the run's large output buffers
// (SlarImage, SlarPictures, SceneGeometryMaps, SlarLineProfiles), which are
// written in full by parallel loops, so that their pages are first touched by
// the threads that write them instead of by a serial memset (about 70 MB per
// 2000 x 2000 run: ~7% of the pipeline's time on one thread, and serial).
// assign(n, value) and resize(n, value) still fill; resize(n) and
// UninitVector<T>(n) do not.
//
// Example:
//   std::vector<double, ris::DefaultInitAllocator<double>> sums;
//   sums.resize(rows * bins);  // no zero fill: every element written next
//   ris::UninitVector<float> image;
//   image.resize(n);           // likewise
#pragma once

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

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

template <typename T>
using UninitVector = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace ris
