// Peak heap memory of a run, measured inside one process.
//
// The executable defines the C allocation functions itself and forwards them
// to glibc's implementation (__libc_malloc and friends). ELF symbol
// interposition makes every shared library of the process (libstdc++'s
// operator new, libgmsh, CGAL's GMP/MPFR) call these definitions, so all
// heap traffic of every mesher is counted the same way. The counter is the
// sum of malloc_usable_size() of the live blocks: what the allocator really
// handed out, slack included, without the allocator's own bookkeeping and
// without pages that free() keeps cached (so it does not depend on when
// glibc returns memory to the system, unlike VmRSS).
//
// Include this header from exactly ONE translation unit of the executable:
// it defines the allocation functions. Compiled with
// -DAFM_BENCH_NO_HEAP_METER it defines nothing and measures 0, which is how
// the meter's own cost on the timings was measured.
//
//   heap_meter::reset_peak();
//   const std::size_t baseline = heap_meter::current();
//   run();
//   const std::size_t extra = heap_meter::peak() - baseline;
#ifndef AFM_BENCHMARK_HEAP_METER_H
#define AFM_BENCHMARK_HEAP_METER_H

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <malloc.h>

// glibc exports its allocator under these names (GLIBC_2.2.5) precisely so
// that a replacement malloc can forward to it.
extern "C" {
void* __libc_malloc(std::size_t);
void __libc_free(void*);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* __libc_memalign(std::size_t, std::size_t);
void* __libc_valloc(std::size_t);
void* __libc_pvalloc(std::size_t);
}

namespace heap_meter {
namespace internal {

// Constant-initialised (zero before any constructor runs), so allocations
// made during static initialisation are counted too.
inline std::atomic<std::int64_t> current_bytes{0};
inline std::atomic<std::int64_t> peak_bytes{0};
inline std::atomic<std::uint64_t> allocations{0};

inline void* counted(void* p)
{
  if(p != nullptr) {
    const std::int64_t n = std::int64_t(malloc_usable_size(p));
    const std::int64_t now = current_bytes.fetch_add(n, std::memory_order_relaxed) + n;
    std::int64_t old = peak_bytes.load(std::memory_order_relaxed);
    while(now > old && !peak_bytes.compare_exchange_weak(old, now, std::memory_order_relaxed)) {
    }
    allocations.fetch_add(1, std::memory_order_relaxed);
  }
  return p;
}

inline void uncounted(void* p)
{
  if(p != nullptr) current_bytes.fetch_sub(std::int64_t(malloc_usable_size(p)), std::memory_order_relaxed);
}

} // namespace internal

/// bytes in live heap blocks now
inline std::size_t current() { return std::size_t((std::max<std::int64_t>)(0, internal::current_bytes.load())); }
/// the largest value of current() since the last reset_peak()
inline std::size_t peak() { return std::size_t((std::max<std::int64_t>)(0, internal::peak_bytes.load())); }
/// number of allocations since the start of the process
inline std::uint64_t allocations() { return internal::allocations.load(); }
/// starts a new measurement: peak() = current()
inline void reset_peak() { internal::peak_bytes.store(internal::current_bytes.load()); }

} // namespace heap_meter

#ifndef AFM_BENCH_NO_HEAP_METER

// The replacements. The set is glibc's list of functions a replacement
// malloc must provide ("Replacing malloc" in the glibc manual), plus
// reallocarray, which glibc would otherwise serve from its own realloc
// without passing through ours.
extern "C" {

void* malloc(std::size_t n) noexcept { return heap_meter::internal::counted(__libc_malloc(n)); }

void free(void* p) noexcept
{
  heap_meter::internal::uncounted(p);
  __libc_free(p);
}

void* calloc(std::size_t n, std::size_t size) noexcept
{
  return heap_meter::internal::counted(__libc_calloc(n, size));
}

void* realloc(void* p, std::size_t n) noexcept
{
  // the old block is released by a successful realloc (or by realloc(p, 0))
  const std::size_t old = p != nullptr ? malloc_usable_size(p) : 0;
  void* q = __libc_realloc(p, n);
  if(q == nullptr && n != 0) return nullptr; // failed: p is untouched
  heap_meter::internal::current_bytes.fetch_sub(std::int64_t(old), std::memory_order_relaxed);
  return heap_meter::internal::counted(q);
}

void* reallocarray(void* p, std::size_t n, std::size_t size) noexcept
{
  std::size_t bytes;
  if(__builtin_mul_overflow(n, size, &bytes)) {
    errno = ENOMEM;
    return nullptr;
  }
  return realloc(p, bytes);
}

void* memalign(std::size_t alignment, std::size_t n) noexcept
{
  return heap_meter::internal::counted(__libc_memalign(alignment, n));
}

void* aligned_alloc(std::size_t alignment, std::size_t n) noexcept
{
  return heap_meter::internal::counted(__libc_memalign(alignment, n));
}

int posix_memalign(void** out, std::size_t alignment, std::size_t n) noexcept
{
  if(alignment % sizeof(void*) != 0 || (alignment & (alignment - 1)) != 0) return EINVAL;
  void* p = __libc_memalign(alignment, n);
  if(p == nullptr) return ENOMEM;
  *out = heap_meter::internal::counted(p);
  return 0;
}

void* valloc(std::size_t n) noexcept { return heap_meter::internal::counted(__libc_valloc(n)); }

void* pvalloc(std::size_t n) noexcept { return heap_meter::internal::counted(__libc_pvalloc(n)); }

} // extern "C"

#endif // AFM_BENCH_NO_HEAP_METER

#endif // AFM_BENCHMARK_HEAP_METER_H
