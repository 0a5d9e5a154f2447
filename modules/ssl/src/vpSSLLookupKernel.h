/*
  Private interface of the SIMD grey-level table look-up (the brightness normalisation's table applied to an
  image), implemented with Google Highway in vpSSLLookupKernel.cpp and picked at run time for the CPU.
*/
#ifndef VP_SSL_LOOKUP_KERNEL_H
#define VP_SSL_LOOKUP_KERNEL_H

#include <cstddef>
#include <cstdint>

namespace vpSSLLookupKernel {
//! dst[i] = lut[src[i]] for i in [0, n); src and dst may be the same array, but must not overlap otherwise.
//! Sizes: any n (size_t); src and dst hold n bytes (the callers pass getSize() of an image checked by
//! vpSSLImageCheck, whose 64-bit check guarantees that).
void applyTable(const uint8_t lut[256], const uint8_t *src, uint8_t *dst, std::size_t n);
} // namespace vpSSLLookupKernel

#endif
