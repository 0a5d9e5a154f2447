/*
  SIMD twice upsampling (the small-landmark mode of vpSSLDetector), compiled once per Highway target and
  dispatched at run time. The plain loop, with its clamped indices per output pixel, took 2.6 ms per 640x480
  image, more than the matching of a tracking frame; here each pair of output pixels 2 j + 1, 2 j + 2 comes from
  input columns j and j + 1 with fixed weights, so the interior is a few 16-bit multiply-adds per vector and an
  interleaved store.
*/
#undef HWY_TARGET_INCLUDE
// foreach_target.h re-includes this file once per target; the path is relative to modules/ssl/include.
#define HWY_TARGET_INCLUDE "../src/vpSSLResampleKernel.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/highway.h>

#include "vpSSLResampleKernel.h"

HWY_BEFORE_NAMESPACE();
namespace vpSSLResampleKernel {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Output pixels 2 j + 1 (weights 3:1 of columns j, j + 1) and 2 j + 2 (1:3), j in [j0, j1), in plain integers.
inline void pairsScalar(const uint8_t *top, const uint8_t *bottom, int wTop, int j0, int j1, uint8_t *out)
{
  const int wBottom = 4 - wTop;
  for (int j = j0; j < j1; ++j) {
    const int tOdd = 3 * top[j] + top[j + 1], tEven = top[j] + 3 * top[j + 1];
    const int bOdd = 3 * bottom[j] + bottom[j + 1], bEven = bottom[j] + 3 * bottom[j + 1];
    out[2 * j + 1] = static_cast<uint8_t>((wTop * tOdd + wBottom * bOdd + 8) >> 4);
    out[2 * j + 2] = static_cast<uint8_t>((wTop * tEven + wBottom * bEven + 8) >> 4);
  }
}

void UpsampleRowImpl(const uint8_t *top, const uint8_t *bottom, int wTop, int width, uint8_t *out)
{
  if (width <= 0) {
    return;
  }
  // The edges repeat the first and last columns: 4 times the same sample along the row.
  out[0] = static_cast<uint8_t>((wTop * 4 * top[0] + (4 - wTop) * 4 * bottom[0] + 8) >> 4);
  out[2 * width - 1] = static_cast<uint8_t>((wTop * 4 * top[width - 1] + (4 - wTop) * 4 * bottom[width - 1] + 8) >> 4);
  const int pairs = width - 1;
  int j = 0;
#if HWY_TARGET != HWY_SCALAR
  const hn::ScalableTag<uint16_t> d16;
  const hn::Rebind<uint8_t, decltype(d16)> d8;
  const int N = static_cast<int>(hn::Lanes(d16));
  const auto three = hn::Set(d16, 3), wt = hn::Set(d16, static_cast<uint16_t>(wTop));
  const auto wb = hn::Set(d16, static_cast<uint16_t>(4 - wTop)), eight = hn::Set(d16, 8);
  for (; j + N <= pairs; j += N) {
    const auto a0 = hn::PromoteTo(d16, hn::LoadU(d8, top + j)), a1 = hn::PromoteTo(d16, hn::LoadU(d8, top + j + 1));
    const auto b0 = hn::PromoteTo(d16, hn::LoadU(d8, bottom + j));
    const auto b1 = hn::PromoteTo(d16, hn::LoadU(d8, bottom + j + 1));
    const auto tOdd = hn::Add(hn::Mul(a0, three), a1), tEven = hn::Add(a0, hn::Mul(a1, three));
    const auto bOdd = hn::Add(hn::Mul(b0, three), b1), bEven = hn::Add(b0, hn::Mul(b1, three));
    // At most 4 * 1020 + 8: inside 16 bits.
    const auto odd = hn::ShiftRight<4>(hn::Add(hn::Add(hn::Mul(wt, tOdd), hn::Mul(wb, bOdd)), eight));
    const auto even = hn::ShiftRight<4>(hn::Add(hn::Add(hn::Mul(wt, tEven), hn::Mul(wb, bEven)), eight));
    // 0..255 after the shift: the signed demotion (the one every target has) keeps them as they are.
    const hn::RebindToSigned<decltype(d16)> di16;
    hn::StoreInterleaved2(hn::DemoteTo(d8, hn::BitCast(di16, odd)), hn::DemoteTo(d8, hn::BitCast(di16, even)), d8,
                          out + 2 * j + 1);
  }
#endif
  pairsScalar(top, bottom, wTop, j, pairs, out);
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
} // namespace HWY_NAMESPACE
} // namespace vpSSLResampleKernel
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include <visp3/core/vpException.h>

namespace vpSSLResampleKernel {
HWY_EXPORT(UpsampleRowImpl);

void upsampleRow(const uint8_t *top, const uint8_t *bottom, int wTop, int width, uint8_t *out)
{
  if (width > kMaxWidth) {
    throw vpException(vpException::dimensionError,
                      "vpSSLResampleKernel::upsampleRow: %d px, beyond the %d px a row "
                      "may have",
                      width, kMaxWidth);
  }
  HWY_DYNAMIC_DISPATCH(UpsampleRowImpl)(top, bottom, wTop, width, out);
}
} // namespace vpSSLResampleKernel
#endif
