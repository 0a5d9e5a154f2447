/*
  The ray reading of vpSSLRadiusEstimator in SIMD, compiled once per Highway target and dispatched at run time.

  The radius search scores a ray at every radius of a grid of ratio 1.02 over the whole range (about 220 radii
  from 4 to 300 px) and most candidates are clutter whose rays are read in full before they are given up: the
  bilinear samples of the rays and the scores of the grid were 70 % of a cluttered frame. Across the lanes of a
  vector:
  - sample(): consecutive samples of a ray, their four neighbours gathered as two 32-bit words at byte offsets
    (the low bytes are a pixel and its right neighbour);
  - screen(): consecutive radii of the grid, each lane computing the three outermost rings' mean levels from the
    ray's running integral (gathers) and the two tests on them that end almost every scalar rayScore() call.
  The arithmetic is the scalar code's, operation for operation, in doubles (the profile's differences in floats,
  as there); this file is compiled with -ffp-contract=off so that no multiply-add is fused: the results are those
  of the scalar code bit for bit on every target.
*/
#undef HWY_TARGET_INCLUDE
// foreach_target.h re-includes this file once per target; the path is relative to modules/ssl/include.
#define HWY_TARGET_INCLUDE "../src/vpSSLRayKernel.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include <hwy/highway.h>

#include <algorithm>

#include "vpSSLRayKernel.h"

HWY_BEFORE_NAMESPACE();
namespace vpSSLRayKernel {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void SampleImpl(const Ray &ray, std::size_t i0, std::size_t i1, float *out)
{
  const int lastU = ray.width - 1, lastV = ray.height - 1;
  // The scalar reading, for the lanes past the last vector and next to the image's end.
  auto one = [&](std::size_t i) {
    const double rho = static_cast<double>(i) * ray.step;
    const double x = ray.u + rho * ray.cd, y = ray.v + rho * ray.sd;
    const int u0 = static_cast<int>(x), v0 = static_cast<int>(y);
    const double fu = x - u0, fv = y - v0;
    const int u1 = std::min(u0 + 1, lastU), v1 = std::min(v0 + 1, lastV);
    const uint8_t *r0 = ray.bitmap + static_cast<std::ptrdiff_t>(v0) * ray.width,
                  *r1 = ray.bitmap + static_cast<std::ptrdiff_t>(v1) * ray.width;
    const double top = (1. - fu) * r0[u0] + fu * r0[u1];
    const double bottom = (1. - fu) * r1[u0] + fu * r1[u1];
    out[i] = static_cast<float>((1. - fv) * top + fv * bottom);
  };
  const hn::ScalableTag<double> d;
  const hn::Rebind<int32_t, decltype(d)> di;
  const hn::Rebind<float, decltype(d)> df;
  const std::size_t N = hn::Lanes(d);
  // A gathered word reads the pixel and the three bytes after it: words that would end past the image are read
  // by the scalar code. Rows are below the first one's (o1 >= o0).
  const int32_t lastWord = ray.width * ray.height - 4;
  const auto vStep = hn::Set(d, ray.step), vu = hn::Set(d, ray.u), vv = hn::Set(d, ray.v);
  const auto vcd = hn::Set(d, ray.cd), vsd = hn::Set(d, ray.sd), vOne = hn::Set(d, 1.);
  const auto vLastV = hn::Set(di, lastV), vWidth = hn::Set(di, ray.width);
  const auto iOne = hn::Set(di, 1), vLastWord = hn::Set(di, lastWord), byteMask = hn::Set(di, 0xFF);
  const int32_t *words = reinterpret_cast<const int32_t *>(ray.bitmap);
  std::size_t i = i0;
  for (; i + N <= i1; i += N) {
    const auto rho = hn::Mul(hn::Iota(d, static_cast<double>(i)), vStep);
    const auto x = hn::Add(vu, hn::Mul(rho, vcd)), y = hn::Add(vv, hn::Mul(rho, vsd));
    const auto u0 = hn::DemoteTo(di, x), v0 = hn::DemoteTo(di, y); // truncation: x, y >= 0
    const auto fu = hn::Sub(x, hn::PromoteTo(d, u0)), fv = hn::Sub(y, hn::PromoteTo(d, v0));
    const auto v1 = hn::Min(hn::Add(v0, iOne), vLastV);
    // One word per row brings the pixel and the next one. Where the next column is clamped (u0 = lastU), x = lastU
    // exactly (samples lie inside the image), so fu = 0 and the byte read past the row's end weighs 0 exactly.
    const auto o0 = hn::Add(hn::Mul(v0, vWidth), u0), o1 = hn::Add(hn::Mul(v1, vWidth), u0);
    if (!hn::AllFalse(di, hn::Gt(o1, vLastWord))) {
      for (std::size_t k = i; k < i + N; ++k) {
        one(k);
      }
      continue;
    }
    const auto w0 = hn::GatherOffset(di, words, o0), w1 = hn::GatherOffset(di, words, o1);
    auto byte = [&](decltype(w0) w) { return hn::PromoteTo(d, hn::And(w, byteMask)); };
    const auto a = byte(w0), b = byte(hn::ShiftRight<8>(w0)), c = byte(w1), e = byte(hn::ShiftRight<8>(w1));
    const auto gu = hn::Sub(vOne, fu);
    const auto top = hn::Add(hn::Mul(gu, a), hn::Mul(fu, b));
    const auto bottom = hn::Add(hn::Mul(gu, c), hn::Mul(fu, e));
    const auto value = hn::Add(hn::Mul(hn::Sub(vOne, fv), top), hn::Mul(fv, bottom));
    hn::StoreU(hn::DemoteTo(df, value), df, out + i);
  }
  for (; i < i1; ++i) {
    one(i);
  }
}

std::size_t ScreenImpl(const Profile &profile, const double *radii, std::size_t n, uint32_t *survivors)
{
  const hn::ScalableTag<double> d;
  const hn::Rebind<int32_t, decltype(d)> di;
  const hn::Rebind<int64_t, decltype(d)> dl;
  const hn::Rebind<float, decltype(d)> df;
  using V = hn::Vec<decltype(d)>;
  const std::size_t N = hn::Lanes(d);
  const auto vInvStep = hn::Set(d, profile.invStep), vStep = hn::Set(d, profile.step), vHalf = hn::Set(d, 0.5);
  const auto vLast = hn::Set(di, static_cast<int32_t>(profile.n - 1));
  const auto vLastD = hn::Set(d, static_cast<double>(profile.n - 1));
  const auto iOne = hn::Set(di, 1);
  // vpSSLRadiusEstimator::rayScore()'s integral(): the running integral, linear between samples.
  auto integral = [&](V rho) {
    const V k = hn::Mul(rho, vInvStep);
    const auto i = hn::Min(hn::DemoteTo(di, k), vLast); // truncation: rho >= 0
    const V fi = hn::PromoteTo(d, i);
    const V f = hn::Sub(k, fi);
    const auto i1 = hn::Min(hn::Add(i, iOne), vLast);
    const auto p0 = hn::GatherIndex(df, profile.p, i), p1 = hn::GatherIndex(df, profile.p, i1);
    const V ci = hn::GatherIndex(d, profile.c, hn::PromoteTo(dl, i));
    const V pr = hn::Add(hn::PromoteTo(d, p0), hn::Mul(hn::Mul(vHalf, f), hn::PromoteTo(d, hn::Sub(p1, p0))));
    const V inside = hn::Add(ci, hn::Mul(hn::Mul(f, vStep), pr));
    // The last sample: no interpolation past it.
    return hn::IfThenElse(hn::Eq(fi, vLastD), ci, inside);
  };
  const auto vq = hn::Set(d, profile.q), vMinWidth = hn::Set(d, profile.minWidth);
  const auto vMinRadius = hn::Set(d, profile.minRadius), vMinContrast = hn::Set(d, profile.minContrast);
  const auto vQuarter = hn::Set(d, 0.25);
  // The lanes past the last radius repeat it; their results are dropped.
  HWY_ALIGN double tail[HWY_MAX_BYTES / sizeof(double)];
  uint8_t bits[8];
  std::size_t count = 0;
  for (std::size_t j = 0; j < n; j += N) {
    V e0;
    if (j + N <= n) {
      e0 = hn::LoadU(d, radii + j);
    } else {
      for (std::size_t k = 0; k < N; ++k) {
        tail[k] = radii[std::min(j + k, n - 1)];
      }
      e0 = hn::Load(d, tail);
    }
    const V e1 = hn::Mul(e0, vq), e2 = hn::Mul(e1, vq), e3 = hn::Mul(e2, vq);
    // rayScore() stops at the first ring narrower than minWidth or closer than minRadius to the centre; with fewer
    // than three rings it has fewer than two pairs and fails.
    const auto readable = hn::And(hn::And(hn::Ge(hn::Sub(e0, e1), vMinWidth), hn::Ge(hn::Sub(e1, e2), vMinWidth)),
                                  hn::And(hn::And(hn::Ge(hn::Sub(e2, e3), vMinWidth), hn::Ge(e1, vMinRadius)),
                                          hn::And(hn::Ge(e2, vMinRadius), hn::Ge(e3, vMinRadius))));
    if (hn::AllFalse(d, readable)) {
      continue;
    }
    const V i0 = integral(e0), i1 = integral(e1), i2 = integral(e2), i3 = integral(e3);
    const V m0 = hn::Div(hn::Sub(i0, i1), hn::Sub(e0, e1));
    const V m1 = hn::Div(hn::Sub(i1, i2), hn::Sub(e1, e2));
    const V m2 = hn::Div(hn::Sub(i2, i3), hn::Sub(e2, e3));
    // The outermost ring is black, the next white, the third black: contrasts white minus black.
    const V c0 = hn::Sub(m1, m0), c1 = hn::Sub(m1, m2);
    const V cmax = hn::Max(c0, c1);
    const auto pass = hn::And(readable, hn::And(hn::Ge(c0, vMinContrast), hn::Ge(c1, hn::Mul(vQuarter, cmax))));
    hn::StoreMaskBits(d, pass, bits);
    for (std::size_t k = 0; k < N && j + k < n; ++k) {
      if ((bits[k / 8] >> (k % 8)) & 1) {
        survivors[count++] = static_cast<uint32_t>(j + k);
      }
    }
  }
  return count;
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
} // namespace HWY_NAMESPACE
} // namespace vpSSLRayKernel
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace vpSSLRayKernel {
HWY_EXPORT(SampleImpl);
HWY_EXPORT(ScreenImpl);

void sample(const Ray &ray, std::size_t i0, std::size_t i1, float *out)
{
  HWY_DYNAMIC_DISPATCH(SampleImpl)(ray, i0, i1, out);
}

std::size_t screen(const Profile &profile, const double *radii, std::size_t n, uint32_t *survivors)
{
  return HWY_DYNAMIC_DISPATCH(ScreenImpl)(profile, radii, n, survivors);
}
} // namespace vpSSLRayKernel
#endif
