/*
  The shading of vpSSLRenderer's rays that meet the water surface and nothing after it, compiled once per Highway
  target and dispatched at run time. In open water under a surface, those rays are most of the image's upper half,
  and each costs three divisions and two square roots on one dependency chain; here the lanes are a row's rays. Built
  with -ffp-contract=off: a fused multiply-add would round differently from the scalar expressions.
*/
#undef HWY_TARGET_INCLUDE
// foreach_target.h re-includes this file once per target; the path is relative to modules/sim/include.
#define HWY_TARGET_INCLUDE "../src/vpSSLSurfaceKernel.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/highway.h>

#include <cmath>

#include "vpSSLSurfaceKernel.h"

#if HWY_ONCE
namespace vpSSLSurfaceKernel {
double surfaceRay(const Surface &s, double dx, double dy, double dz, double &tw)
{
  const double dn = s.sn[0] * dx + s.sn[1] * dy + s.sn[2] * dz;
  tw = s.num / dn;
  const double dd = dx * dx + dy * dy + dz * dz;
  if (!(dn > s.parallelEps && s.num > 0.) || !(tw > 0. && tw < HUGE_VAL) || tw * tw * dd > s.maxRange2) {
    return -1.;
  }
  const double cosI = dn / std::sqrt(dd);
  const double sinT2 = s.waterIndex * s.waterIndex * (1. - cosI * cosI);
  if (sinT2 >= 1.) {
    return 1.;
  }
  const double cosT = std::sqrt(1. - sinT2);
  const double rs = (s.waterIndex * cosI - cosT) / (s.waterIndex * cosI + cosT);
  const double rp = (cosI - s.waterIndex * cosT) / (cosI + s.waterIndex * cosT);
  return 0.5 * (rs * rs + rp * rp);
}
} // namespace vpSSLSurfaceKernel
#endif

HWY_BEFORE_NAMESPACE();
namespace vpSSLSurfaceKernel {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void SurfaceRaysImpl(const Surface &s, const double *dx, const double *dy, const double *dz, size_t count,
                     double *fresnel, double *twOut)
{
  const hn::ScalableTag<double> d;
  const size_t N = hn::Lanes(d);
  const auto sn0 = hn::Set(d, s.sn[0]), sn1 = hn::Set(d, s.sn[1]), sn2 = hn::Set(d, s.sn[2]);
  const auto num = hn::Set(d, s.num), maxRange2 = hn::Set(d, s.maxRange2), eps = hn::Set(d, s.parallelEps);
  const auto index = hn::Set(d, s.waterIndex), n2 = hn::Set(d, s.waterIndex * s.waterIndex);
  const auto zero = hn::Zero(d), one = hn::Set(d, 1.), half = hn::Set(d, 0.5), inf = hn::Set(d, HUGE_VAL);
  const auto none = hn::Set(d, -1.);
  const bool below = s.num > 0.;
  size_t k = 0;
  for (; below && k + N <= count; k += N) {
    const auto x = hn::LoadU(d, dx + k), y = hn::LoadU(d, dy + k), z = hn::LoadU(d, dz + k);
    const auto dn = hn::Add(hn::Add(hn::Mul(sn0, x), hn::Mul(sn1, y)), hn::Mul(sn2, z));
    const auto tw = hn::Div(num, dn);
    hn::StoreU(tw, d, twOut + k);
    const auto dd = hn::Add(hn::Add(hn::Mul(x, x), hn::Mul(y, y)), hn::Mul(z, z));
    // Met: sn . d > eps, 0 < tw < infinity and not beyond the maximum range (a NaN fails a comparison: not met).
    const auto met = hn::And(hn::And(hn::Gt(dn, eps), hn::And(hn::Gt(tw, zero), hn::Lt(tw, inf))),
                             hn::Not(hn::Gt(hn::Mul(hn::Mul(tw, tw), dd), maxRange2)));
    if (hn::AllFalse(d, met)) {
      hn::StoreU(none, d, fresnel + k);
      continue;
    }
    const auto cosI = hn::Div(dn, hn::Sqrt(dd));
    const auto sinT2 = hn::Mul(n2, hn::Sub(one, hn::Mul(cosI, cosI)));
    const auto cosT = hn::Sqrt(hn::Sub(one, sinT2));
    const auto icosI = hn::Mul(index, cosI), icosT = hn::Mul(index, cosT);
    const auto rs = hn::Div(hn::Sub(icosI, cosT), hn::Add(icosI, cosT));
    const auto rp = hn::Div(hn::Sub(cosI, icosT), hn::Add(cosI, icosT));
    const auto partial = hn::Mul(half, hn::Add(hn::Mul(rs, rs), hn::Mul(rp, rp)));
    // Total reflection where sinT2 >= 1 (cosT is then NaN or 0 and is not used).
    const auto reflectance = hn::IfThenElse(hn::Ge(sinT2, one), one, partial);
    hn::StoreU(hn::IfThenElse(met, reflectance, none), d, fresnel + k);
  }
  for (; k < count; ++k) {
    fresnel[k] = surfaceRay(s, dx[k], dy[k], dz[k], twOut[k]);
  }
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
} // namespace HWY_NAMESPACE
} // namespace vpSSLSurfaceKernel
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace vpSSLSurfaceKernel {
HWY_EXPORT(SurfaceRaysImpl);

void surfaceRays(const Surface &surface, const double *dx, const double *dy, const double *dz, size_t count,
                 double *fresnel, double *tw)
{
  HWY_DYNAMIC_DISPATCH(SurfaceRaysImpl)(surface, dx, dy, dz, count, fresnel, tw);
}
} // namespace vpSSLSurfaceKernel
#endif
