/*
  The local-maximum test of the peak detector (vpSSLPeakDetector), compiled once per Highway target and dispatched
  at run time. Near a landmark most of the map is over the threshold (the rings and the paper around them), so the
  scalar test of eight neighbours per pixel, whose branches follow the map's texture, cost as much as a tenth of a
  detection. Here the lanes are consecutive columns: each neighbour is one unaligned load and one comparison for a
  whole vector, and the rare maxima are picked from the mask.
*/
#undef HWY_TARGET_INCLUDE
// foreach_target.h re-includes this file once per target; the path is relative to modules/ssl/include.
#define HWY_TARGET_INCLUDE "../src/vpSSLPeakKernel.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/highway.h>

#include <cstdint>

#include "vpSSLPeakKernel.h"

HWY_BEFORE_NAMESPACE();
namespace vpSSLPeakKernel {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

int LocalMaximaImpl(const int *above, const int *row, const int *below, int u0, int u1, int threshold, int *columns)
{
  // The test of one column, for the columns past the last vector.
  auto isMax = [&](int u) {
    const int m = row[u];
    if (m < threshold || row[u - 1] > m || row[u + 1] >= m) {
      return false;
    }
    if (above != nullptr && (above[u - 1] > m || above[u] > m || above[u + 1] > m)) {
      return false;
    }
    return below == nullptr || (below[u - 1] < m && below[u] < m && below[u + 1] < m);
  };
  const hn::ScalableTag<int32_t> d;
  const int N = static_cast<int>(hn::Lanes(d));
  const auto vThreshold = hn::Set(d, threshold);
  uint8_t bits[HWY_MAX_BYTES / 4 / 8 + 1];
  int nb = 0, u = u0;
  for (; u + N - 1 <= u1; u += N) {
    const auto m = hn::LoadU(d, row + u);
    auto keep = hn::Not(hn::Lt(m, vThreshold));
    if (hn::AllFalse(d, keep)) {
      continue; // most of the map
    }
    // Loose against the earlier neighbours (a larger one rejects), strict against the later ones.
    auto earlier = hn::Gt(hn::LoadU(d, row + u - 1), m);
    keep = hn::And(keep, hn::Gt(m, hn::LoadU(d, row + u + 1)));
    if (above != nullptr) {
      earlier =
          hn::Or(earlier, hn::Or(hn::Gt(hn::LoadU(d, above + u - 1), m),
                                 hn::Or(hn::Gt(hn::LoadU(d, above + u), m), hn::Gt(hn::LoadU(d, above + u + 1), m))));
    }
    if (below != nullptr) {
      keep =
          hn::And(keep, hn::And(hn::Gt(m, hn::LoadU(d, below + u - 1)),
                                hn::And(hn::Gt(m, hn::LoadU(d, below + u)), hn::Gt(m, hn::LoadU(d, below + u + 1)))));
    }
    keep = hn::AndNot(earlier, keep);
    if (hn::AllFalse(d, keep)) {
      continue;
    }
    hn::StoreMaskBits(d, keep, bits);
    for (int k = 0; k < N; ++k) {
      if ((bits[k / 8] >> (k % 8)) & 1) {
        columns[nb++] = u + k;
      }
    }
  }
  for (; u <= u1; ++u) {
    if (isMax(u)) {
      columns[nb++] = u;
    }
  }
  return nb;
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
} // namespace HWY_NAMESPACE
} // namespace vpSSLPeakKernel
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace vpSSLPeakKernel {
HWY_EXPORT(LocalMaximaImpl);

int localMaxima(const int *above, const int *row, const int *below, int u0, int u1, int threshold, int *columns)
{
  return HWY_DYNAMIC_DISPATCH(LocalMaximaImpl)(above, row, below, u0, u1, threshold, columns);
}
} // namespace vpSSLPeakKernel
#endif
