/*
  SIMD table look-up of bytes (the normalisation table of vpSSLDetector), compiled once per Highway target and
  dispatched at run time. A scalar loop takes one byte per cycle at best, a tenth of a 640x480
  detection; byte shuffles look up 16 entries of the table per 128-bit block at once.

  The 256-entry table is 16 tables of 16 entries, one per high nibble of the index. For table h, the index
  x XOR 16 h has a high nibble of 0 exactly where x belongs to it; adding 0x70 with saturation then leaves the
  low nibble with bit 7 clear there and sets bit 7 everywhere else, where the shuffle yields 0. The 16 partial
  results are ORed.
*/
#undef HWY_TARGET_INCLUDE
// foreach_target.h re-includes this file once per target; the path is relative to modules/ssl/include.
#define HWY_TARGET_INCLUDE "../src/vpSSLLookupKernel.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/highway.h>

#include "vpSSLLookupKernel.h"

HWY_BEFORE_NAMESPACE();
namespace vpSSLLookupKernel {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void ApplyTableImpl(const uint8_t *lut, const uint8_t *src, uint8_t *dst, std::size_t n)
{
#if HWY_TARGET == HWY_SCALAR
  for (std::size_t i = 0; i < n; ++i) {
    dst[i] = lut[src[i]];
  }
#else
  const hn::ScalableTag<uint8_t> d;
  using V = hn::Vec<decltype(d)>;
  const std::size_t N = hn::Lanes(d);
#if !HWY_HAVE_SCALABLE
  V table[16];
  for (int h = 0; h < 16; ++h) {
    table[h] = hn::LoadDup128(d, lut + 16 * h);
  }
#endif
  const V bias = hn::Set(d, 0x70);
  std::size_t i = 0;
  for (; i + N <= n; i += N) {
    const V x = hn::LoadU(d, src + i);
    V r = hn::Zero(d);
    for (int h = 0; h < 16; ++h) {
      const V idx = hn::SaturatedAdd(hn::Xor(x, hn::Set(d, static_cast<uint8_t>(16 * h))), bias);
#if HWY_HAVE_SCALABLE
      // Vectors of scalable targets (SVE) cannot be array elements: the tables are loaded as used (from L1).
      const V table = hn::LoadDup128(d, lut + 16 * h);
      r = hn::Or(r, hn::TableLookupBytesOr0(table, idx));
#else
      r = hn::Or(r, hn::TableLookupBytesOr0(table[h], idx));
#endif
    }
    hn::StoreU(r, d, dst + i);
  }
  for (; i < n; ++i) {
    dst[i] = lut[src[i]];
  }
#endif
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
} // namespace HWY_NAMESPACE
} // namespace vpSSLLookupKernel
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace vpSSLLookupKernel {
HWY_EXPORT(ApplyTableImpl);

void applyTable(const uint8_t lut[256], const uint8_t *src, uint8_t *dst, std::size_t n)
{
  HWY_DYNAMIC_DISPATCH(ApplyTableImpl)(lut, src, dst, n);
}
} // namespace vpSSLLookupKernel
#endif
