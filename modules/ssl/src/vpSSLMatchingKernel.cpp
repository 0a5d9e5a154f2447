/*
  SIMD kernel of the matching function (paper Eq. 3 and 5), compiled once per Highway target and dispatched at
  run time (foreach_target.h + HWY_EXPORT + HWY_DYNAMIC_DISPATCH): one binary runs AVX-512, AVX2, SSE4, NEON or
  the scalar fallback, whichever the CPU has.

  The paper (Sec. 4) thought the non-sequential sample offsets ruled SIMD out. They do not: for a fixed xi the
  samples X + xi d, X + a_xi d and X + b_xi d of neighbouring pixels X along a row are neighbours too, so one
  vector of consecutive pixels needs three unaligned loads per xi and direction, in all four directions (the
  vertical ones read three other rows at the same columns). The horizontal directions go further: their absolute
  differences |I(y) - I(y + k)| depend on the gap k and the position only, so they are computed once per row and
  gap into a small buffer and shared by every xi with that gap and by +x and -x (SharedRows below). Terms with
  a_xi = b_xi are identically 0 and skipped.

  The absolute differences are taken on bytes (a full vector of pixels per instruction) and summed in 16-bit
  lanes, each holding an (even, odd) pair of pixels: `all` accumulates the pair's 16-bit value s_e + 256 s_o and
  `odd` accumulates s_o. Both wrap modulo 2^16, but each pixel's true sum lies within +-255 w <= +-32640, so the
  even sum all - 256 odd and the odd sum are exact once read as int16. Half as many loads as with pixels widened
  to 16 bits (see doc/kernel.md for what bounds each loop).
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
#include <cstring>

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
        sum += term(p[o[0]], p[o[1]], p[o[2]]);
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

/*
  GCC folds a loaded vector into each instruction that uses it, i.e. loads it twice; unaligned loads are what
  bounds the shared loop, so the vector is pinned in a register.
*/
HWY_INLINE V8 LoadOnce(const uint8_t *p)
{
  V8 v = hn::LoadU(D8(), p);
#if HWY_ARCH_X86 && HWY_TARGET != HWY_EMU128 && (HWY_COMPILER_GCC || HWY_COMPILER_CLANG)
  asm("" : "+v"(v.raw));
#endif
  return v;
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
HWY_INLINE void SumDirection(const Params &P, const uint8_t *p, int dir, const int *live, int nbLive, VI16 &e0,
                             VI16 &o0, VI16 &e1, VI16 &o1)
{
  const D8 d8;
  const D16 d16;
  const DI16 di16;
  const size_t N = hn::Lanes(d8);
  V16 all0 = hn::Zero(d16), odd0 = hn::Zero(d16), all1 = hn::Zero(d16), odd1 = hn::Zero(d16);
  for (int i = 0; i < nbLive; ++i) {
    const std::ptrdiff_t *o = P.offsets[dir][live[i]];
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
  Absolute differences shared by the horizontal directions. For +x, the term xi of pixel X reads the pair
  (X + xi, X + a_xi), i.e. D_k(X + a_xi) with D_k(y) = |I(y) - I(y + k)| and k = xi - a_xi; for -x it reads
  D_k(X - xi). So one row of D_k per distinct gap k (at most 21 of them for w = 40, p = 0.5) serves every xi with
  that gap, in both directions: each term then costs two loads from L1 instead of three loads and six byte
  operations. The rows are computed for a chunk of the span at a time, into a buffer on the stack.
*/
struct SharedRows
{
  int window = 0;                             // the plan's key: w and the offsets of +x
  std::ptrdiff_t key[kMaxWindow + 1][3] = {}; // copy of P.offsets[kPlusX][0 .. w]
  bool usable = false;                        // false: the buffer cannot hold two vectors of pixels
  int nbRows = 0;                             // distinct gaps k, one row of D_k each
  int gap[kMaxWindow + 1];
  std::ptrdiff_t rowBytes = 0; // L: bytes per row of the buffer, a multiple of the vector size
  int left = 0;                // R: the buffer's column 0 is column (chunk start - R) of the image
  int chunk = 0;               // pixels per chunk, a multiple of two vectors
  int nbTerms = 0;             // xi whose term is not identically 0, i.e. a_xi != b_xi
  int live[kMaxWindow];        // those xi
  std::ptrdiff_t stride = 0;   // P.stride, part of the key: vertical[t] = offsets of +y for xi = live[t]
  std::ptrdiff_t vertical[kMaxWindow][3];
  // terms[dir][t] = {offset of the a sample, offset of the b sample} in the buffer, relative to the chunk column
  std::ptrdiff_t terms[2][kMaxWindow][2];
};

// Stack buffer of the D_k rows: 21 rows of 640 bytes at w = 40 (13 KB); larger windows with too many gaps for it
// (e.g. w = 128, p = 0.3: about 90) read the image directly.
constexpr std::ptrdiff_t kSharedBytes = 32 * 1024;
constexpr int kMaxChunk = 512;

// Whether S was planned for the window and offsets of P (a memcmp of a few hundred bytes, once per span).
HWY_INLINE bool SamePlan(const Params &P, const SharedRows &S)
{
  return S.window == P.window && S.stride == P.stride &&
         std::memcmp(S.key, P.offsets[kPlusX], sizeof(S.key[0]) * static_cast<std::size_t>(P.window + 1)) == 0;
}

// Plans the rows and the term offsets for the window and offsets of P.
HWY_NOINLINE void PlanShared(const Params &P, SharedRows &S)
{
  const int N = static_cast<int>(hn::Lanes(D8()));
  const int w = P.window;
  S.window = w;
  S.stride = P.stride;
  std::memcpy(S.key, P.offsets[kPlusX], sizeof(S.key[0]) * static_cast<std::size_t>(w + 1));
  // The offsets of +x are {xi, a_xi, b_xi} (a step of one byte).
  const auto a = [&](int xi) { return static_cast<int>(S.key[xi][1]); };
  const auto b = [&](int xi) { return static_cast<int>(S.key[xi][2]); };
  // a_xi = b_xi gives |I(X + xi d) - I(X + a d)| - |I(X + xi d) - I(X + b d)| = 0 (xi = 1, 2, 3 for p = 0.5).
  S.nbTerms = 0;
  for (int xi = 1; xi <= w; ++xi) {
    if (a(xi) != b(xi)) {
      for (int j = 0; j < 3; ++j) {
        S.vertical[S.nbTerms][j] = P.offsets[kPlusY][xi][j];
      }
      S.live[S.nbTerms++] = xi;
    }
  }
  int rowOfGap[kMaxWindow + 1];
  std::fill(rowOfGap, rowOfGap + w + 1, -1);
  S.nbRows = 0;
  for (int i = 0; i < S.nbTerms; ++i) {
    const int xi = S.live[i];
    for (const int o : {a(xi), b(xi)}) {
      const int k = std::abs(xi - o);
      if (rowOfGap[k] < 0) {
        rowOfGap[k] = S.nbRows;
        S.gap[S.nbRows++] = k;
      }
    }
  }
  // R: a multiple of 64 so that the image loads of the rows are aligned when the chunk is (whole frames).
  S.left = (w + 63) / 64 * 64;
  S.chunk = kMaxChunk / (2 * N) * (2 * N);
  // The rows are computed up to 2 N + 2 w bytes past the last pixel: the right padding of the copy must cover it.
  S.usable = S.chunk > 0 && 2 * N + w <= kRightPadBytes;
  for (; S.usable; S.chunk -= 2 * N) {
    S.rowBytes = (S.left + S.chunk + w + N - 1) / N * N;
    if (S.nbRows * S.rowBytes <= kSharedBytes) {
      break;
    }
    S.usable = S.chunk > 2 * N;
  }
  for (int i = 0; i < S.nbTerms && S.usable; ++i) {
    const int xi = S.live[i], ai = a(xi), bi = b(xi);
    const std::ptrdiff_t ra = rowOfGap[std::abs(xi - ai)] * S.rowBytes, rb = rowOfGap[std::abs(xi - bi)] * S.rowBytes;
    // +x: the pair (X + xi, X + a) starts at X + min(xi, a); -x: (X - xi, X - a) starts at X - max(xi, a).
    S.terms[kPlusX][i][0] = ra + S.left + std::min(xi, ai);
    S.terms[kPlusX][i][1] = rb + S.left + std::min(xi, bi);
    S.terms[kMinusX][i][0] = ra + S.left - std::max(xi, ai);
    S.terms[kMinusX][i][1] = rb + S.left - std::max(xi, bi);
  }
}

// D_k for the `bytes` (a multiple of N) columns starting at `image`, row by row into buf. Column-major, so that
// the vector at column j is loaded once for all the gaps.
HWY_INLINE void ComputeShared(const SharedRows &S, const uint8_t *image, std::ptrdiff_t bytes, uint8_t *buf)
{
  const D8 d8;
  const std::ptrdiff_t N = static_cast<std::ptrdiff_t>(hn::Lanes(d8));
  for (std::ptrdiff_t j = 0; j < bytes; j += N) {
    const V8 c = LoadOnce(image + j);
    uint8_t *dst = buf + j;
    for (int r = 0; r < S.nbRows; ++r, dst += S.rowBytes) {
      hn::Store(AbsDiff8(c, LoadOnce(image + j + S.gap[r])), d8, dst);
    }
  }
}

/*
  Both vertical directions in one loop (same reason as SumSharedPair); -y reads the rows of +y mirrored about the
  pixel's row, i.e. the offsets negated.
*/
template <int U>
HWY_INLINE void SumVerticalPair(const SharedRows &S, const uint8_t *p, VI16 &e0, VI16 &o0, VI16 &e1, VI16 &o1, VI16 &f0,
                                VI16 &q0, VI16 &f1, VI16 &q1)
{
  const D16 d16;
  const DI16 di16;
  const size_t N = hn::Lanes(D8());
  V16 all0 = hn::Zero(d16), odd0 = all0, all1 = all0, odd1 = all0;
  V16 mall0 = all0, modd0 = all0, mall1 = all0, modd1 = all0;
  for (int i = 0; i < S.nbTerms; ++i) {
    const std::ptrdiff_t *o = S.vertical[i];
    AddTerm(p + o[0], p + o[1], p + o[2], all0, odd0);
    AddTerm(p - o[0], p - o[1], p - o[2], mall0, modd0);
    if (U > 1) {
      AddTerm(p + o[0] + N, p + o[1] + N, p + o[2] + N, all1, odd1);
      AddTerm(p - o[0] + N, p - o[1] + N, p - o[2] + N, mall1, modd1);
    }
  }
  e0 = hn::BitCast(di16, hn::Sub(all0, hn::ShiftLeft<8>(odd0)));
  o0 = hn::BitCast(di16, odd0);
  e1 = hn::BitCast(di16, hn::Sub(all1, hn::ShiftLeft<8>(odd1)));
  o1 = hn::BitCast(di16, odd1);
  f0 = hn::BitCast(di16, hn::Sub(mall0, hn::ShiftLeft<8>(modd0)));
  q0 = hn::BitCast(di16, modd0);
  f1 = hn::BitCast(di16, hn::Sub(mall1, hn::ShiftLeft<8>(modd1)));
  q1 = hn::BitCast(di16, modd1);
}

// all += s - t and odd += (s >> 8) - (t >> 8) for two vectors of shared differences (see AddTerm).
HWY_INLINE void AddShared(V8 s8, V8 t8, V16 &all, V16 &odd)
{
  const D16 d16;
  const V16 s = hn::BitCast(d16, s8), t = hn::BitCast(d16, t8);
  all = hn::Add(all, hn::Sub(s, t));
  odd = hn::Add(odd, hn::Sub(hn::ShiftRight<8>(s), hn::ShiftRight<8>(t)));
}

HWY_INLINE void FinishSums(V16 all, V16 odd, VI16 &e, VI16 &o)
{
  const DI16 di16;
  e = hn::BitCast(di16, hn::Sub(all, hn::ShiftLeft<8>(odd)));
  o = hn::BitCast(di16, odd);
}

// As SumDirection, for one horizontal direction, from the shared rows (base: the buffer at the block's column).
template <int U>
HWY_INLINE void SumShared(const SharedRows &S, const uint8_t *base, int dir, VI16 &e0, VI16 &o0, VI16 &e1, VI16 &o1)
{
  const D16 d16;
  const size_t N = hn::Lanes(D8());
  V16 all0 = hn::Zero(d16), odd0 = all0, all1 = all0, odd1 = all0;
  const std::ptrdiff_t(*t)[2] = S.terms[dir];
  for (int i = 0; i < S.nbTerms; ++i) {
    const uint8_t *pa = base + t[i][0], *pb = base + t[i][1];
    AddShared(LoadOnce(pa), LoadOnce(pb), all0, odd0);
    if (U > 1) {
      AddShared(LoadOnce(pa + N), LoadOnce(pb + N), all1, odd1);
    }
  }
  FinishSums(all0, odd0, e0, o0);
  FinishSums(all1, odd1, e1, o1);
}

// Both horizontal directions in one loop: twice the independent sums per iteration, one loop overhead.
template <int U>
HWY_INLINE void SumSharedPair(const SharedRows &S, const uint8_t *base, VI16 &e0, VI16 &o0, VI16 &e1, VI16 &o1,
                              VI16 &f0, VI16 &q0, VI16 &f1, VI16 &q1)
{
  const D16 d16;
  const size_t N = hn::Lanes(D8());
  V16 all0 = hn::Zero(d16), odd0 = all0, all1 = all0, odd1 = all0;
  V16 mall0 = all0, modd0 = all0, mall1 = all0, modd1 = all0;
  const std::ptrdiff_t(*t)[2] = S.terms[kPlusX];
  const std::ptrdiff_t(*m)[2] = S.terms[kMinusX];
  for (int i = 0; i < S.nbTerms; ++i) {
    const uint8_t *pa = base + t[i][0], *pb = base + t[i][1];
    const uint8_t *ma = base + m[i][0], *mb = base + m[i][1];
    AddShared(LoadOnce(pa), LoadOnce(pb), all0, odd0);
    AddShared(LoadOnce(ma), LoadOnce(mb), mall0, modd0);
    if (U > 1) {
      AddShared(LoadOnce(pa + N), LoadOnce(pb + N), all1, odd1);
      AddShared(LoadOnce(ma + N), LoadOnce(mb + N), mall1, modd1);
    }
  }
  FinishSums(all0, odd0, e0, o0);
  FinishSums(all1, odd1, e1, o1);
  FinishSums(mall0, modd0, f0, q0);
  FinishSums(mall1, modd1, f1, q1);
}

// One direction's sums over the block's one or two vectors (U), kept where they answer best.
template <int U>
HWY_INLINE void CombineBlock(const Params &P, int dir, int u, VI16 e0, VI16 o0, VI16 e1, VI16 o1, VI16 &bestE0,
                             VI16 &bestO0, VI16 &bestE1, VI16 &bestO1)
{
  Combine(P, dir, u, e0, o0, bestE0, bestO0);
  if (U > 1) {
    Combine(P, dir, u + static_cast<int>(hn::Lanes(D8())), e1, o1, bestE1, bestO1);
  }
}

/*
  M for the `count` (<= U N) pixels starting at column u of row v. A direction is computed when it is valid for
  at least one of them; the pixels for which it is not are masked out of the maximum (their loads still land in
  the padding of the copy, and pixels past `count` are never stored). With S, the horizontal directions read the
  shared rows at `shared` (the buffer at column u).
*/
template <int U>
HWY_INLINE void MatchBlock(const Params &P, const SharedRows &S, const uint8_t *shared, int v, int u, int count,
                           int32_t *out)
{
  const int N = static_cast<int>(hn::Lanes(D8()));
  const int w = P.window;
  const uint8_t *p = P.pixels + v * P.stride + u;
  const bool valid[4] = {u + w < P.width, u + count - 1 >= w, v + w < P.height, v >= w};
  VI16 bestE0 = None(), bestO0 = None(), bestE1 = None(), bestO1 = None();
  VI16 e0, o0, e1, o1;
  if (shared != nullptr && valid[kPlusX] && valid[kMinusX]) {
    VI16 f0, q0, f1, q1;
    SumSharedPair<U>(S, shared, e0, o0, e1, o1, f0, q0, f1, q1);
    CombineBlock<U>(P, kPlusX, u, e0, o0, e1, o1, bestE0, bestO0, bestE1, bestO1);
    CombineBlock<U>(P, kMinusX, u, f0, q0, f1, q1, bestE0, bestO0, bestE1, bestO1);
  } else {
    for (int dir = kPlusX; dir <= kMinusX; ++dir) {
      if (!valid[dir]) {
        continue;
      }
      if (shared != nullptr) {
        SumShared<U>(S, shared, dir, e0, o0, e1, o1);
      } else {
        SumDirection<U>(P, p, dir, S.live, S.nbTerms, e0, o0, e1, o1);
      }
      CombineBlock<U>(P, dir, u, e0, o0, e1, o1, bestE0, bestO0, bestE1, bestO1);
    }
  }
  if (valid[kPlusY] && valid[kMinusY]) {
    VI16 f0, q0, f1, q1;
    SumVerticalPair<U>(S, p, e0, o0, e1, o1, f0, q0, f1, q1);
    CombineBlock<U>(P, kPlusY, u, e0, o0, e1, o1, bestE0, bestO0, bestE1, bestO1);
    CombineBlock<U>(P, kMinusY, u, f0, q0, f1, q1, bestE0, bestO0, bestE1, bestO1);
  } else {
    for (int dir = kPlusY; dir <= kMinusY; ++dir) {
      if (!valid[dir]) {
        continue;
      }
      SumDirection<U>(P, p, dir, S.live, S.nbTerms, e0, o0, e1, o1);
      CombineBlock<U>(P, dir, u, e0, o0, e1, o1, bestE0, bestO0, bestE1, bestO1);
    }
  }
  StoreMap(bestE0, bestO0, count, out);
  if (U > 1) {
    StoreMap(bestE1, bestO1, count - N, out + N);
  }
}

// Pixels [u0, u1) of row v, in blocks of two vectors then single vectors.
HWY_INLINE void MatchRun(const Params &P, const SharedRows &S, const uint8_t *shared, int v, int u0, int u1)
{
  const int N = static_cast<int>(hn::Lanes(D8()));
  int32_t *out = P.out + static_cast<std::ptrdiff_t>(v) * P.width;
  int u = u0;
  for (; u + 2 * N <= u1; u += 2 * N) {
    MatchBlock<2>(P, S, shared == nullptr ? nullptr : shared + (u - u0), v, u, 2 * N, out + u);
  }
  for (; u < u1; u += N) {
    MatchBlock<1>(P, S, shared == nullptr ? nullptr : shared + (u - u0), v, u, std::min(N, u1 - u), out + u);
  }
}

void MatchSpanImpl(const Params &P, int v, int u0, int u1)
{
  const int N = static_cast<int>(hn::Lanes(D8()));
  const int w = P.window;
  // The plan depends on w, p and the stride only: planned once per thread, kept while they do not change.
  thread_local SharedRows S;
  if (!SamePlan(P, S)) {
    PlanShared(P, S);
  }
  // Without a valid horizontal direction in the span (narrow images) the rows would serve nothing.
  const bool horizontal = u0 + w < P.width || u1 - 1 >= w;
  if (!horizontal || !S.usable) {
    MatchRun(P, S, nullptr, v, u0, u1);
    return;
  }
  HWY_ALIGN uint8_t buf[kSharedBytes];
  const uint8_t *row = P.pixels + v * P.stride;
  for (int c = u0; c < u1; c += S.chunk) {
    const int c1 = std::min(u1, c + S.chunk);
    const int covered = (c1 - c + N - 1) / N * N; // pixels of the chunk's vectors
    ComputeShared(S, row + c - S.left, (S.left + covered + w + N - 1) / N * N, buf);
    MatchRun(P, S, buf, v, c, c1);
  }
}

#endif // HWY_TARGET == HWY_SCALAR

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

std::ptrdiff_t leftPad(int window)
{
  return (window + 63) / 64 * 64;
}

std::ptrdiff_t paddedStride(int width, int window)
{
  return (leftPad(window) + width + window + kRightPadBytes + 63) / 64 * 64;
}

std::size_t paddedSize(int width, int height, int window)
{
  return static_cast<std::size_t>(paddedStride(width, window)) * static_cast<std::size_t>(height);
}

void matchSpan(const Params &params, int v, int u0, int u1)
{
  HWY_DYNAMIC_DISPATCH(MatchSpanImpl)(params, v, u0, u1);
}

const char *targetName()
{
  return HWY_DYNAMIC_DISPATCH(TargetNameImpl)();
}
} // namespace vpSSLMatchingKernel
#endif
