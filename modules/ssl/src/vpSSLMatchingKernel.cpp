/*
  SIMD kernel of the matching function (paper Eq. 3 and 5), compiled once per Highway target and dispatched at
  run time (foreach_target.h + HWY_EXPORT + HWY_DYNAMIC_DISPATCH): one binary runs AVX-512, AVX2, SSE4, NEON or
  the scalar fallback, whichever the CPU has.

  The paper (Sec. 4) thought the non-sequential sample offsets ruled SIMD out. They do not: for a fixed xi the
  samples X + xi d, X + a_xi d and X + b_xi d of neighbouring pixels X along a row are neighbours too, so one
  vector of consecutive pixels needs three unaligned loads per xi and direction, in all four directions (the
  vertical ones read three other rows at the same columns).

  The absolute differences are taken on bytes (a full vector of pixels per instruction) and summed in 16-bit
  lanes, each holding an (even, odd) pair of pixels: `all` accumulates the pair's 16-bit value s_e + 256 s_o and
  `odd` accumulates s_o. Both wrap modulo 2^16, but each pixel's true sum lies within +-255 w <= +-32640, so the
  even sum all - 256 odd and the odd sum are exact once read as int16. Half as many loads as with pixels widened
  to 16 bits, and unaligned loads are what bounds this loop (see doc/kernel.md).
*/
#undef HWY_TARGET_INCLUDE
// foreach_target.h re-includes this file once per target; the path is relative to modules/ssl/include, the
// library's include directory (__FILE__ would expand inside foreach_target.h, naming that header instead).
#define HWY_TARGET_INCLUDE "../src/vpSSLMatchingKernel.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/highway.h>

#include <algorithm>
#include <climits>
#include <cstdlib>

#include "vpSSLMatchingKernel.h"

HWY_BEFORE_NAMESPACE();
namespace vpSSLMatchingKernel {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

#if HWY_TARGET == HWY_SCALAR

// One lane per vector: the byte-pair trick needs at least two, so the fallback is the plain sum (same integers).
void MatchSpanImpl(const Params &P, int v, int u0, int u1)
{
  const int w = P.window;
  int32_t *out = P.out + static_cast<std::ptrdiff_t>(v) * P.width;
  for (int u = u0; u < u1; ++u) {
    const bool valid[4] = {u + w < P.width, u >= w, v + w < P.height, v >= w};
    const uint8_t *p = P.pixels + v * P.stride + u;
    bool any = false;
    int best = 0;
    for (int dir = 0; dir < 4; ++dir) {
      if (!valid[dir]) {
        continue;
      }
      int sum = 0;
      for (int xi = 1; xi <= w; ++xi) {
        const std::ptrdiff_t *o = P.offsets[dir][xi];
        sum += std::abs(p[o[0]] - p[o[1]]) - std::abs(p[o[0]] - p[o[2]]);
      }
      best = any ? std::max(best, sum) : sum;
      any = true;
    }
    out[u] = best;
  }
}

#else

using D8 = hn::ScalableTag<uint8_t>;
using D16 = hn::RepartitionToWide<D8>;
using DI16 = hn::RebindToSigned<D16>;
using V8 = hn::Vec<D8>;
using V16 = hn::Vec<D16>;
using VI16 = hn::Vec<DI16>;
using MI16 = hn::Mask<DI16>;

HWY_INLINE V8 AbsDiff8(V8 a, V8 b)
{
  return hn::Or(hn::SaturatedSub(a, b), hn::SaturatedSub(b, a));
}

// One xi term of Eq. 3, |I(X + xi d) - I(X + a d)| - |I(X + xi d) - I(X + b d)|, for a vector of pixels X.
HWY_INLINE void AddTerm(const uint8_t *pc, const uint8_t *pa, const uint8_t *pb, V16 &all, V16 &odd)
{
  const D8 d8;
  const D16 d16;
  const V8 c = hn::LoadU(d8, pc);
  const V16 s = hn::BitCast(d16, AbsDiff8(c, hn::LoadU(d8, pa)));
  const V16 t = hn::BitCast(d16, AbsDiff8(c, hn::LoadU(d8, pb)));
  all = hn::Add(all, hn::Sub(s, t));
  odd = hn::Add(odd, hn::Sub(hn::ShiftRight<8>(s), hn::ShiftRight<8>(t)));
}

/*
  Eq. 3 in direction `dir` for U (1 or 2) vectors of consecutive pixels starting at p, as even-pixel and
  odd-pixel sums. One direction at a time keeps the three offsets of each xi in registers for the U vectors.
*/
template <int U>
HWY_INLINE void SumDirection(const Params &P, const uint8_t *p, int dir, VI16 &e0, VI16 &o0, VI16 &e1, VI16 &o1)
{
  const D8 d8;
  const D16 d16;
  const DI16 di16;
  const size_t N = hn::Lanes(d8);
  V16 all0 = hn::Zero(d16), odd0 = hn::Zero(d16), all1 = hn::Zero(d16), odd1 = hn::Zero(d16);
  const std::ptrdiff_t *o = P.offsets[dir][1];
  for (int xi = 1; xi <= P.window; ++xi, o += 3) {
    const uint8_t *pc = p + o[0], *pa = p + o[1], *pb = p + o[2];
    AddTerm(pc, pa, pb, all0, odd0);
    if (U > 1) {
      AddTerm(pc + N, pa + N, pb + N, all1, odd1);
    }
  }
  e0 = hn::BitCast(di16, hn::Sub(all0, hn::ShiftLeft<8>(odd0)));
  o0 = hn::BitCast(di16, odd0);
  e1 = hn::BitCast(di16, hn::Sub(all1, hn::ShiftLeft<8>(odd1)));
  o1 = hn::BitCast(di16, odd1);
}

// -32768 is below any sum (>= -255 * 128), so it marks "no valid direction yet".
HWY_INLINE VI16 None()
{
  return hn::Set(DI16(), static_cast<int16_t>(SHRT_MIN));
}

// Masks of the even pixels 2j and the odd pixels 2j + 1 among the first n pixels of a vector.
HWY_INLINE void FirstPixels(int n, MI16 &even, MI16 &odd)
{
  const DI16 d;
  const int clamped = std::min(std::max(n, 0), static_cast<int>(hn::Lanes(D8())));
  even = hn::FirstN(d, static_cast<size_t>((clamped + 1) / 2));
  odd = hn::FirstN(d, static_cast<size_t>(clamped / 2));
}

// Maximum over directions (Eq. 5) for the vector at column u; pixels where `dir` is invalid keep their best.
HWY_INLINE void Combine(const Params &P, int dir, int u, VI16 e, VI16 o, VI16 &bestE, VI16 &bestO)
{
  MI16 me, mo;
  if (dir == kPlusX) {
    // +x is valid for the pixels u + i with u + i + w <= width - 1.
    FirstPixels(P.width - P.window - u, me, mo);
    e = hn::IfThenElse(me, e, None());
    o = hn::IfThenElse(mo, o, None());
  } else if (dir == kMinusX) {
    // -x is valid for u + i >= w.
    FirstPixels(P.window - u, me, mo);
    e = hn::IfThenElse(me, None(), e);
    o = hn::IfThenElse(mo, None(), o);
  }
  bestE = hn::Max(bestE, e);
  bestO = hn::Max(bestO, o);
}

// Stores min(count, N) values of M in pixel order, 0 where no direction was valid.
HWY_INLINE void StoreMap(VI16 bestE, VI16 bestO, int count, int32_t *out)
{
  const DI16 d;
  const int N = static_cast<int>(hn::Lanes(D8()));
  if (count <= 0) {
    return;
  }
  HWY_ALIGN int16_t pixels[HWY_MAX_BYTES];
  hn::StoreInterleaved2(hn::IfThenZeroElse(hn::Eq(bestE, None()), bestE),
                        hn::IfThenZeroElse(hn::Eq(bestO, None()), bestO), d, pixels);
  if (count < N) {
    std::copy(pixels, pixels + count, out);
    return;
  }
  const hn::Half<DI16> dh;
  const hn::Rebind<int32_t, decltype(dh)> d32;
  const size_t half = hn::Lanes(d);
  for (size_t k = 0; k < 2; ++k) {
    const VI16 m = hn::Load(d, pixels + k * half);
    hn::StoreU(hn::PromoteTo(d32, hn::LowerHalf(dh, m)), d32, out + k * half);
    hn::StoreU(hn::PromoteTo(d32, hn::UpperHalf(dh, m)), d32, out + k * half + half / 2);
  }
}

/*
  M for the `count` (<= U N) pixels starting at column u of row v. A direction is computed when it is valid for
  at least one of them; the pixels for which it is not are masked out of the maximum (their loads still land in
  the padding of the copy, and pixels past `count` are never stored).
*/
template <int U> HWY_INLINE void MatchBlock(const Params &P, int v, int u, int count, int32_t *out)
{
  const int N = static_cast<int>(hn::Lanes(D8()));
  const int w = P.window;
  const uint8_t *p = P.pixels + v * P.stride + u;
  const bool valid[4] = {u + w < P.width, u + count - 1 >= w, v + w < P.height, v >= w};
  VI16 bestE0 = None(), bestO0 = None(), bestE1 = None(), bestO1 = None();
  for (int dir = 0; dir < 4; ++dir) {
    if (!valid[dir]) {
      continue;
    }
    VI16 e0, o0, e1, o1;
    SumDirection<U>(P, p, dir, e0, o0, e1, o1);
    Combine(P, dir, u, e0, o0, bestE0, bestO0);
    if (U > 1) {
      Combine(P, dir, u + N, e1, o1, bestE1, bestO1);
    }
  }
  StoreMap(bestE0, bestO0, count, out);
  if (U > 1) {
    StoreMap(bestE1, bestO1, count - N, out + N);
  }
}

void MatchSpanImpl(const Params &P, int v, int u0, int u1)
{
  const int N = static_cast<int>(hn::Lanes(D8()));
  int32_t *out = P.out + static_cast<std::ptrdiff_t>(v) * P.width;
  int u = u0;
  for (; u + 2 * N <= u1; u += 2 * N) {
    MatchBlock<2>(P, v, u, 2 * N, out + u);
  }
  for (; u < u1; u += N) {
    MatchBlock<1>(P, v, u, std::min(N, u1 - u), out + u);
  }
}

#endif // HWY_TARGET == HWY_SCALAR

// Symmetry centring (vpSSLRadiusEstimator): differences in 16-bit lanes (one vector holds a row of the disc of
// radius 8 on AVX-512), squared and summed pairwise into 32-bit lanes (a disc of radius 16 sums at most
// 400 * 255^2 < 2^31).
long SquaredDifferenceRowsImpl(const uint8_t *a, std::ptrdiff_t strideA, const uint8_t *b, std::ptrdiff_t strideB,
                               const int *first, const int *last, int nbRows, long bound)
{
  // At most 32 lanes (32 bytes loaded per row step), whatever the target, so that the caller's 64 bytes of padding
  // past each row are enough even for the widest (SVE) vectors.
  const hn::CappedTag<int16_t, 32> d16;
  const hn::RepartitionToWide<decltype(d16)> d32;
  const hn::Rebind<uint8_t, decltype(d16)> d8;
  const int N = static_cast<int>(hn::Lanes(d16));
  auto sum0 = hn::Zero(d32), sum1 = hn::Zero(d32);
  long e = 0;
  for (int r = 0; r < nbRows; ++r) {
    const uint8_t *pa = a + r * strideA + first[r], *pb = b + r * strideB + first[r];
    const int n = last[r] - first[r] + 1;
    for (int x = 0; x < n; x += N) {
      const auto va = hn::BitCast(d16, hn::PromoteTo(hn::RebindToUnsigned<decltype(d16)>(), hn::LoadU(d8, pa + x)));
      const auto vb = hn::BitCast(d16, hn::PromoteTo(hn::RebindToUnsigned<decltype(d16)>(), hn::LoadU(d8, pb + x)));
      const auto diff = hn::IfThenElseZero(hn::FirstN(d16, static_cast<size_t>(n - x)), hn::Sub(va, vb));
      sum0 = hn::ReorderWidenMulAccumulate(d32, diff, diff, sum0, sum1);
    }
    // The horizontal sum costs a few steps: the bound is checked every other row (where does not matter: a sum
    // above the bound is never the minimum).
    if ((r & 1) == 1 || r + 1 == nbRows) {
      e = static_cast<long>(hn::GetLane(hn::SumOfLanes(d32, hn::Add(sum0, sum1))));
      if (e > bound) {
        return bound + 1;
      }
    }
  }
  return e;
}

const char *TargetNameImpl()
{
  return hwy::TargetName(HWY_TARGET);
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
} // namespace HWY_NAMESPACE
} // namespace vpSSLMatchingKernel
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace vpSSLMatchingKernel {
HWY_EXPORT(MatchSpanImpl);
HWY_EXPORT(TargetNameImpl);
HWY_EXPORT(SquaredDifferenceRowsImpl);

// Two of the widest vectors Highway may use (2048-bit SVE): the right padding covers a whole block of pixels past
// the last one plus the window.
constexpr std::ptrdiff_t kBlockBytes = 2 * 256;

std::ptrdiff_t leftPad(int window)
{
  return (window + 63) / 64 * 64;
}

std::ptrdiff_t paddedStride(int width, int window)
{
  return (leftPad(window) + width + window + kBlockBytes + 63) / 64 * 64;
}

std::size_t paddedSize(int width, int height, int window)
{
  return static_cast<std::size_t>(paddedStride(width, window)) * static_cast<std::size_t>(height);
}

void matchSpan(const Params &params, int v, int u0, int u1)
{
  HWY_DYNAMIC_DISPATCH(MatchSpanImpl)(params, v, u0, u1);
}

long squaredDifferenceRows(const uint8_t *a, std::ptrdiff_t strideA, const uint8_t *b, std::ptrdiff_t strideB,
                           const int *first, const int *last, int nbRows, long bound)
{
  return HWY_DYNAMIC_DISPATCH(SquaredDifferenceRowsImpl)(a, strideA, b, strideB, first, last, nbRows, bound);
}

const char *targetName()
{
  return HWY_DYNAMIC_DISPATCH(TargetNameImpl)();
}
} // namespace vpSSLMatchingKernel
#endif
