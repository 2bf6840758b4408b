/* malloc_count.so: counts the calls of malloc, calloc, realloc and aligned allocations of a
   process (operator new goes through malloc in libstdc++) and prints the totals to stderr at
   exit, as "malloc_count: PROGRAM: N calls, B bytes" (a singleton MPI run also
   reports its orted). For the allocation-per-step check of
   regression/benchmarks/explicit_contact_benchmark.sh: run N1 and N2 steps of the same model and
   divide the difference of the counts by N2 - N1.
     cc -O2 -shared -fPIC -o malloc_count.so malloc_count.c
     LD_PRELOAD=./malloc_count.so railfe deck.xml ... */
#define _GNU_SOURCE
#include <errno.h>
#include <stddef.h>
#include <stdio.h>

extern void* __libc_malloc(size_t);
extern void* __libc_calloc(size_t, size_t);
extern void* __libc_realloc(void*, size_t);
extern void* __libc_memalign(size_t, size_t);

static unsigned long long calls, bytes;

void* malloc(size_t size) {
  __atomic_add_fetch(&calls, 1, __ATOMIC_RELAXED);
  __atomic_add_fetch(&bytes, size, __ATOMIC_RELAXED);
  return __libc_malloc(size);
}

void* calloc(size_t n, size_t size) {
  __atomic_add_fetch(&calls, 1, __ATOMIC_RELAXED);
  __atomic_add_fetch(&bytes, n * size, __ATOMIC_RELAXED);
  return __libc_calloc(n, size);
}

void* realloc(void* p, size_t size) {
  __atomic_add_fetch(&calls, 1, __ATOMIC_RELAXED);
  __atomic_add_fetch(&bytes, size, __ATOMIC_RELAXED);
  return __libc_realloc(p, size);
}

void* memalign(size_t alignment, size_t size) {
  __atomic_add_fetch(&calls, 1, __ATOMIC_RELAXED);
  __atomic_add_fetch(&bytes, size, __ATOMIC_RELAXED);
  return __libc_memalign(alignment, size);
}

int posix_memalign(void** out, size_t alignment, size_t size) {
  void* p = memalign(alignment, size);
  if (!p)
    return ENOMEM;
  *out = p;
  return 0;
}

void* aligned_alloc(size_t alignment, size_t size) {
  return memalign(alignment, size);
}

__attribute__((destructor)) static void report(void) {
  fprintf(stderr, "malloc_count: %s: %llu calls, %llu bytes\n", program_invocation_short_name,
          calls, bytes);
}
