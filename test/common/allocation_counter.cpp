#include "allocation_counter.h"

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

namespace {
std::atomic<int> g_armed{0};
std::atomic<long> g_calls{0};

void *allocate(std::size_t size, std::size_t align)
{
  if (g_armed.load() > 0) {
    ++g_calls;
  }
  void *p = align <= alignof(std::max_align_t) ? std::malloc(size == 0 ? 1 : size)
                                               : std::aligned_alloc(align, (size + align - 1) / align * align);
  if (p == nullptr) {
    throw std::bad_alloc();
  }
  return p;
}
} // namespace

void *operator new(std::size_t size)
{
  return allocate(size, alignof(std::max_align_t));
}
void *operator new[](std::size_t size)
{
  return allocate(size, alignof(std::max_align_t));
}
void *operator new(std::size_t size, std::align_val_t align)
{
  return allocate(size, static_cast<std::size_t>(align));
}
void *operator new[](std::size_t size, std::align_val_t align)
{
  return allocate(size, static_cast<std::size_t>(align));
}
void operator delete(void *p) noexcept
{
  std::free(p);
}
void operator delete[](void *p) noexcept
{
  std::free(p);
}
void operator delete(void *p, std::size_t) noexcept
{
  std::free(p);
}
void operator delete[](void *p, std::size_t) noexcept
{
  std::free(p);
}
void operator delete(void *p, std::align_val_t) noexcept
{
  std::free(p);
}
void operator delete[](void *p, std::align_val_t) noexcept
{
  std::free(p);
}
void operator delete(void *p, std::size_t, std::align_val_t) noexcept
{
  std::free(p);
}
void operator delete[](void *p, std::size_t, std::align_val_t) noexcept
{
  std::free(p);
}

namespace sslt {
AllocationCounter::AllocationCounter()
{
  g_calls = 0;
  ++g_armed;
}
AllocationCounter::~AllocationCounter()
{
  --g_armed;
}
long AllocationCounter::count() const
{
  return g_calls.load();
}
} // namespace sslt
