/*
  Symmetry centring of a candidate (vpSSLRadiusEstimator::symmetryCentre()): the sums of squared differences
  between a disc and its half-turn about each of the 13 x 13 half-pixel centres of the search window, compiled
  once per Highway target and dispatched at run time.

  E(s) = sum over the half disc d of (I(floor(s / 2) + d) - I(ceil(s / 2) - d))^2. For one offset d and one row of
  centres of the same parities (s = 2 a + parity), both pixels move by one column when a does: the centres are
  the vector lanes, so that every product lands in its centre's own 32-bit lane and no horizontal sum is needed
  (evaluating the centres one by one, with a horizontal sum for each early-out test, cost 6 us a call). The
  squares are summed in pairs by a 16-bit multiply-add (x86 pmaddwd), so each centre takes two 16-bit lanes:
  the offsets d and d + (1, 0). The image rows are first copied as pairs (I(x), I(x + 1)) for the first pixel and
  (I(x), I(x - 1)) for the second, so that a single load brings both pixels of both offsets for every centre.
  Integer sums are exact: any order of summation gives the energies of the scalar search, bit for bit.
*/
#undef HWY_TARGET_INCLUDE
// foreach_target.h re-includes this file once per target; the path is relative to modules/ssl/include.
#define HWY_TARGET_INCLUDE "../src/vpSSLSymmetryKernel.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "vpSSLSymmetryKernel.h"

#ifndef VP_SSL_SYMMETRY_KERNEL_LAYOUT
#define VP_SSL_SYMMETRY_KERNEL_LAYOUT
namespace vpSSLSymmetryKernel {
namespace {
// Side of the search window, in half-pixel centres.
const int kSide = 2 * kReach + 1;
// Centres of one parity along a row of the window (floor(s / 2) takes kReach + 1 values), rounded up to the
// lanes of the widest vector used (16 x 16 bits: 8 centres), and the pairs of one row of the copies.
const int kCentres = kReach + 1;
const int kLanes = 8;
int pairsPerRow(int radius)
{
  return (kLanes + 2 * radius + 1 + 7) / 8 * 8;
}
// Rows of each of the two copies (the disc's pixels and their half-turns).
int copyRows(int radius)
{
  return kCentres + radius;
}
// The energies as the vectors leave them: E(cu + i, cv + j) at energyIndex(), lanes of centres outside the window
// holding INT32_MAX.
const int kEnergies = kSide * 2 * kLanes;
int energyIndex(int cu, int i, int j)
{
  const int su = cu + i;
  return ((j + kReach) * 2 + (su & 1)) * kLanes + (su >> 1) - ((cu - kReach) >> 1);
}
} // namespace
} // namespace vpSSLSymmetryKernel
#endif

HWY_BEFORE_NAMESPACE();
namespace vpSSLSymmetryKernel {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// E[energyIndex(cu, i, j)] = E(cu + i, cv + j); (best[0], best[1]) = (i, j) of the minimum, the first in
// row-major order on ties. image: rows of stride bytes, width pixels each; every pixel of every pair of the window
// lies inside it (the caller's border test).
void EnergiesImpl(const uint8_t *image, std::ptrdiff_t stride, int width, int cu, int cv, int radius, const int *spans,
                  int16_t *buffer, int32_t *E, int *best)
{
  const int *first = spans, *last = spans + radius + 1;
#if HWY_TARGET == HWY_SCALAR
  (void)width;
  (void)buffer;
  std::fill(E, E + kEnergies, std::numeric_limits<int32_t>::max());
  int32_t minimum = std::numeric_limits<int32_t>::max();
  for (int j = -kReach; j <= kReach; ++j) {
    for (int i = -kReach; i <= kReach; ++i) {
      const int su = cu + i, sv = cv + j;
      const int pu = su >> 1, pv = sv >> 1, qu = pu + (su & 1), qv = pv + (sv & 1);
      int32_t e = 0;
      for (int dy = 0; dy <= radius; ++dy) {
        const uint8_t *p = image + (pv + dy) * stride + pu, *q = image + (qv - dy) * stride + qu;
        for (int dx = first[dy]; dx <= last[dy]; ++dx) {
          const int d = p[dx] - q[-dx];
          e += d * d;
        }
      }
      E[energyIndex(cu, i, j)] = e;
      if (e < minimum) {
        minimum = e;
        best[0] = i;
        best[1] = j;
      }
    }
  }
#else
  // Centres s = (2 a + pu, 2 b + pv) for the parities pu, pv; a in [a0, a0 + kCentres), b in [b0, b0 + kCentres).
  const int a0 = (cu - kReach) >> 1, b0 = (cv - kReach) >> 1, c0 = (cv - kReach + 1) >> 1;
  // Copies of rows [b0, b0 + rows) (first pixels, going down from the centre) and [c0 - radius, c0 - radius + rows)
  // (second pixels, going up), as pairs of columns x in [x0, x0 + pairs): P(y, x) = (I(y, x), I(y, x + 1)) and
  // Q(y, x) = (I(y, x), I(y, x - 1)), 0 outside the image (only lanes of centres outside the window read those).
  const int rows = copyRows(radius), pairs = pairsPerRow(radius), x0 = a0 - radius;
  const std::ptrdiff_t rowStride = 2 * pairs;
  int16_t *P = buffer, *Q = buffer + rows * rowStride;
  {
    const hn::Full128<int16_t> d;
    const hn::Rebind<uint8_t, decltype(d)> d8;
    auto copy = [&](int y, int step, int16_t *dst) {
      const uint8_t *src = image + y * stride;
      if (x0 - 1 >= 0 && x0 + pairs + 1 <= width) {
        for (int k = 0; k < pairs; k += 8) {
          const auto a = hn::PromoteTo(d, hn::LoadU(d8, src + x0 + k));
          const auto b = hn::PromoteTo(d, hn::LoadU(d8, src + x0 + k + step));
          hn::StoreU(hn::InterleaveLower(a, b), d, dst + 2 * k);
          hn::StoreU(hn::InterleaveUpper(d, a, b), d, dst + 2 * k + 8);
        }
      } else {
        auto pixel = [&](int x) { return static_cast<int16_t>(x >= 0 && x < width ? src[x] : 0); };
        for (int k = 0; k < pairs; ++k) {
          dst[2 * k] = pixel(x0 + k);
          dst[2 * k + 1] = pixel(x0 + k + step);
        }
      }
    };
    for (int y = 0; y < rows; ++y) {
      copy(b0 + y, 1, P + y * rowStride);
      copy(c0 - radius + y, -1, Q + y * rowStride);
    }
  }

  const hn::CappedTag<int16_t, 2 * kLanes> d16;
  const hn::RepartitionToWide<decltype(d16)> d32;
  const int G = static_cast<int>(hn::Lanes(d32)); // centres per vector
  // A row of the half disc with an odd number of pixels ends with the pair (last, last + 1): its second lane out.
  const auto keepEven = hn::Eq(hn::And(hn::Iota(d16, 0), hn::Set(d16, 1)), hn::Zero(d16));
  const auto outside = hn::Set(d32, std::numeric_limits<int32_t>::max());
  for (int pv = 0; pv < 2; ++pv) {
    const int bMin = (cv - kReach - pv + 1) >> 1, bMax = (cv + kReach - pv) >> 1;
    for (int pu = 0; pu < 2; ++pu) {
      // Lanes l in [lMin, lMax] are the window's: |2 (a0 + l) + pu - cu| <= kReach.
      const auto lMin = hn::Set(d32, ((cu - kReach - pu + 1) >> 1) - a0);
      const auto lMax = hn::Set(d32, ((cu + kReach - pu) >> 1) - a0);
      for (int b = bMin; b <= bMax; ++b) {
        const int j = 2 * b + pv - cv;
        int32_t *row = E + ((j + kReach) * 2 + pu) * kLanes;
        for (int a = a0; a < a0 + kCentres; a += G) {
          // Two sets of sums, so that consecutive multiply-adds do not wait for each other.
          auto sum0 = hn::Zero(d32), sum1 = hn::Zero(d32), sum2 = hn::Zero(d32), sum3 = hn::Zero(d32);
          for (int dy = 0; dy <= radius; ++dy) {
            // Offsets (dx, dy), (dx + 1, dy): first pixels at P(b + dy, a + dx), second at Q(b + pv - dy, a + pu - dx).
            const int16_t *p = P + (b + dy - b0) * rowStride + 2 * (a + first[dy] - x0);
            const int16_t *q = Q + (b + pv - dy - (c0 - radius)) * rowStride + 2 * (a + pu - first[dy] - x0);
            int n = last[dy] - first[dy] + 1;
            for (; n >= 4; n -= 4, p += 8, q -= 8) {
              const auto diff0 = hn::Sub(hn::LoadU(d16, p), hn::LoadU(d16, q));
              const auto diff1 = hn::Sub(hn::LoadU(d16, p + 4), hn::LoadU(d16, q - 4));
              sum0 = hn::ReorderWidenMulAccumulate(d32, diff0, diff0, sum0, sum1);
              sum2 = hn::ReorderWidenMulAccumulate(d32, diff1, diff1, sum2, sum3);
            }
            if (n >= 2) {
              const auto diff = hn::Sub(hn::LoadU(d16, p), hn::LoadU(d16, q));
              sum0 = hn::ReorderWidenMulAccumulate(d32, diff, diff, sum0, sum1);
              n -= 2;
              p += 4;
              q -= 4;
            }
            if (n == 1) {
              const auto diff = hn::IfThenElseZero(keepEven, hn::Sub(hn::LoadU(d16, p), hn::LoadU(d16, q)));
              sum2 = hn::ReorderWidenMulAccumulate(d32, diff, diff, sum2, sum3);
            }
          }
          const auto e = hn::Add(hn::RearrangeToOddPlusEven(sum0, sum1), hn::RearrangeToOddPlusEven(sum2, sum3));
          const auto lane = hn::Iota(d32, a - a0);
          hn::StoreU(hn::IfThenElse(hn::Or(hn::Lt(lane, lMin), hn::Gt(lane, lMax)), outside, e), d32, row + (a - a0));
        }
      }
    }
  }
  // The minimum, then its first row j (row-major order), then its first centre i in that row (either parity).
  const hn::CappedTag<int32_t, kLanes> dE;
  const int NE = static_cast<int>(hn::Lanes(dE));
  auto m = hn::LoadU(dE, E);
  for (int k = NE; k < kEnergies; k += NE) {
    m = hn::Min(m, hn::LoadU(dE, E + k));
  }
  const auto minimum = hn::MinOfLanes(dE, m);
  for (int j = -kReach; j <= kReach; ++j) {
    int bestI = kReach + 1;
    for (int pu = 0; pu < 2; ++pu) {
      const int32_t *row = E + ((j + kReach) * 2 + pu) * kLanes;
      for (int l = 0; l < kLanes; l += NE) {
        const intptr_t found = hn::FindFirstTrue(dE, hn::Eq(hn::LoadU(dE, row + l), minimum));
        if (found >= 0) {
          bestI = std::min(bestI, 2 * (a0 + l + static_cast<int>(found)) + pu - cu);
          break;
        }
      }
    }
    if (bestI <= kReach) {
      best[0] = bestI;
      best[1] = j;
      return;
    }
  }
#endif
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
} // namespace HWY_NAMESPACE
} // namespace vpSSLSymmetryKernel
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace vpSSLSymmetryKernel {
HWY_EXPORT(EnergiesImpl);

void halfDisc(int radius, std::vector<int> &spans)
{
  spans.assign(2 * (radius + 1), 0);
  for (int dy = 0; dy <= radius; ++dy) {
    int rx = 0;
    while ((rx + 1) * (rx + 1) + dy * dy <= radius * radius) {
      ++rx;
    }
    spans[dy] = dy == 0 ? 1 : -rx;
    spans[radius + 1 + dy] = rx;
  }
}

bool centre(const vpImage<unsigned char> &I, int radius, const std::vector<int> &spans, double flatVariance,
            std::vector<int16_t> &buffer, double &u, double &v, double &asymmetry)
{
  // The landmark is point-symmetric, and stays so under any affine view, symmetric blur and noise: its centre
  // minimises the difference between the image and its half-turn about it. Centres on the half-pixel grid pair
  // whole pixels, so no interpolation is needed.
  const int W = static_cast<int>(I.getWidth()), H = static_cast<int>(I.getHeight());
  const int reach = kReach;
  // Beyond kMaxRadius the 32-bit sums could overflow; a centre that is not finite, or beyond any image, has no
  // integer half-pixel position (lround() of it is undefined).
  if (radius < 1 || radius > kMaxRadius || !(std::fabs(u) < 1e9) || !(std::fabs(v) < 1e9)) {
    asymmetry = 0.;
    return false;
  }
  const int cu = static_cast<int>(std::lround(2. * u)), cv = static_cast<int>(std::lround(2. * v));
  if (cu - reach < 2 * radius || cv - reach < 2 * radius || cu + reach > 2 * (W - 1 - radius) ||
      cv + reach > 2 * (H - 1 - radius)) {
    asymmetry = 0.;
    return false; // too close to the border to compare both halves: keep the peak
  }
  buffer.resize(static_cast<size_t>(2 * copyRows(radius) * 2 * pairsPerRow(radius)));
  HWY_ALIGN int32_t E[kEnergies];
  int best[2];
  HWY_DYNAMIC_DISPATCH(EnergiesImpl)(I.bitmap, W, W, cu, cv, radius, spans.data(), buffer.data(), E, best);
  const int bi = best[0], bj = best[1];
  auto energy = [&](int i, int j) { return static_cast<double>(E[energyIndex(cu, i, j)]); };
  double du = 0., dv = 0.;
  const double b = energy(bi, bj);
  if (bi > -reach && bi < reach) {
    const double a = energy(bi - 1, bj), c = energy(bi + 1, bj);
    const double den = a - 2. * b + c;
    du = den > 0. ? std::max(-0.5, std::min(0.5, 0.5 * (a - c) / den)) : 0.;
  }
  if (bj > -reach && bj < reach) {
    const double a = energy(bi, bj - 1), c = energy(bi, bj + 1);
    const double den = a - 2. * b + c;
    dv = den > 0. ? std::max(-0.5, std::min(0.5, 0.5 * (a - c) / den)) : 0.;
  }
  u = 0.5 * (cu + bi + du);
  v = 0.5 * (cv + bj + dv);
  // Residual relative to the disc's own contrast: 0 for a perfectly symmetric pattern, about 1 for clutter. The
  // variance of the disc about the best centre's first pixel, from exact integer sums.
  const int pu = (cu + bi) >> 1, pv = (cv + bj) >> 1;
  int64_t sum = 0, sum2 = 0;
  int n = 0;
  for (int dy = -radius; dy <= radius; ++dy) {
    const int rx = spans[radius + 1 + (dy < 0 ? -dy : dy)];
    const unsigned char *row = I[pv + dy] + pu;
    int32_t rowSum = 0, rowSum2 = 0; // at most 2 radius + 1 pixels: no overflow
    for (int dx = -rx; dx <= rx; ++dx) {
      const int32_t g = row[dx];
      rowSum += g;
      rowSum2 += g * g;
    }
    sum += rowSum;
    sum2 += rowSum2;
    n += 2 * rx + 1;
  }
  const double s = static_cast<double>(sum), s2 = static_cast<double>(sum2);
  const double variance = s2 / n - (s / n) * (s / n);
  // A nearly flat disc (the innermost rings of a large landmark blurred by water and lens into a grey spot) says
  // nothing either way: its residual is sensor noise. Only a contrasted disc is judged.
  asymmetry = variance < flatVariance ? 0. : b / (0.5 * n * 2. * variance);
  return true;
}
} // namespace vpSSLSymmetryKernel
#endif
