/*
  The sensor-noise arithmetic of vpSSLWaterModel::apply(), compiled once per Highway target and dispatched at run
  time. Scalar, each pixel's three square roots and each pair's division and square root of the polar method sat on
  a chain of dependent long-latency operations, one pixel after the other; here the lanes are consecutive pixels (or
  pairs). Built with -ffp-contract=off: a fused multiply-add would round differently from the scalar expressions.
*/
#undef HWY_TARGET_INCLUDE
// foreach_target.h re-includes this file once per target; the path is relative to modules/sim/include.
#define HWY_TARGET_INCLUDE "../src/vpSSLNoiseKernel.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "vpSSLNoiseKernel.h"
#include "vpSSLQuantise.h"

HWY_BEFORE_NAMESPACE();
namespace vpSSLNoiseKernel {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void PolarFactorsImpl(const double *rsq, const double *logRsq, size_t n, double *fac)
{
  const hn::ScalableTag<double> d;
  const size_t N = hn::Lanes(d);
  const auto minusTwo = hn::Set(d, -2.);
  size_t i = 0;
  for (; i + N <= n; i += N) {
    hn::StoreU(hn::Sqrt(hn::Div(hn::Mul(minusTwo, hn::LoadU(d, logRsq + i)), hn::LoadU(d, rsq + i))), d, fac + i);
  }
  for (; i < n; ++i) {
    fac[i] = std::sqrt(-2. * logRsq[i] / rsq[i]);
  }
}

void ExposeQuantiseImpl(const float *red, const float *green, const float *blue, const double *deviates, size_t nb,
                        double gain, double a, double b, unsigned char *rgba)
{
  const float *planes[3] = {red, green, blue};
  // One pixel as the scalar expressions give it: the tail, and vectors holding a NaN (which the quantisation maps
  // to 0).
  auto scalarPixel = [&](size_t k) {
    for (int c = 0; c < 3; ++c) {
      const double y = gain * planes[c][k];
      const double sd = std::sqrt(std::max(0., a * y + b));
      rgba[4 * k + c] = vpSSLQuantise::quantise(255. * (y + sd * deviates[3 * k + c]));
    }
    rgba[4 * k + 3] = 255;
  };
  const hn::ScalableTag<double> d;
  const hn::Rebind<float, decltype(d)> df;
  const hn::Rebind<int32_t, decltype(d)> di;
  const size_t N = hn::Lanes(d);
  const auto vGain = hn::Set(d, gain), vA = hn::Set(d, a), vB = hn::Set(d, b);
  const auto zero = hn::Zero(d), half = hn::Set(d, 0.5), one = hn::Set(d, 1.), v255 = hn::Set(d, 255.);
  int32_t q[3][HWY_MAX_BYTES / sizeof(double)];
  size_t k = 0;
  for (; k + N <= nb; k += N) {
    hn::Vec<decltype(d)> dev[3];
    hn::LoadInterleaved3(d, deviates + 3 * k, dev[0], dev[1], dev[2]);
    bool nan = false;
    for (int c = 0; c < 3; ++c) {
      const auto y = hn::Mul(vGain, hn::PromoteTo(d, hn::LoadU(df, planes[c] + k)));
      const auto s = hn::Add(hn::Mul(vA, y), vB);
      // std::max(0., s): s where 0 < s, else 0 (NaN included).
      const auto sd = hn::Sqrt(hn::IfThenElse(hn::Lt(zero, s), s, zero));
      const auto v = hn::Mul(v255, hn::Add(y, hn::Mul(sd, dev[c])));
      if (!hn::AllFalse(d, hn::Ne(v, v))) {
        nan = true;
        break;
      }
      // vpSSLQuantise::quantise: in [0, 255) the integer part plus one from a fraction of one half; the clamp
      // maps everything else (the infinities too: their fraction is NaN) to 0 or 255.
      const auto t = hn::Trunc(v);
      const auto r = hn::IfThenElse(hn::Ge(hn::Sub(v, t), half), hn::Add(t, one), t);
      hn::StoreU(hn::DemoteTo(di, hn::Min(hn::Max(r, zero), v255)), di, q[c]);
    }
    if (nan) {
      for (size_t j = 0; j < N; ++j) {
        scalarPixel(k + j);
      }
      continue;
    }
    for (size_t j = 0; j < N; ++j) {
      unsigned char *p = rgba + 4 * (k + j);
      p[0] = static_cast<unsigned char>(q[0][j]);
      p[1] = static_cast<unsigned char>(q[1][j]);
      p[2] = static_cast<unsigned char>(q[2][j]);
      p[3] = 255;
    }
  }
  for (; k < nb; ++k) {
    scalarPixel(k);
  }
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
} // namespace HWY_NAMESPACE
} // namespace vpSSLNoiseKernel
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace vpSSLNoiseKernel {
HWY_EXPORT(PolarFactorsImpl);
HWY_EXPORT(ExposeQuantiseImpl);

void polarFactors(const double *rsq, const double *logRsq, size_t n, double *fac)
{
  HWY_DYNAMIC_DISPATCH(PolarFactorsImpl)(rsq, logRsq, n, fac);
}

void exposeQuantise(const float *red, const float *green, const float *blue, const double *deviates, size_t nb,
                    double gain, double a, double b, unsigned char *rgba)
{
  HWY_DYNAMIC_DISPATCH(ExposeQuantiseImpl)(red, green, blue, deviates, nb, gain, a, b, rgba);
}
} // namespace vpSSLNoiseKernel
#endif
