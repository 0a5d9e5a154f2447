/*
  The ray reading of vpSSLRadiusEstimator in SIMD, compiled once per Highway target and dispatched at run time.

  The radius search scores a ray at every radius of a grid of ratio 1.02 over the whole range (about 220 radii
  from 4 to 300 px) and most candidates are clutter whose rays are read in full before they are given up: the
  bilinear samples of the rays and the scores of the grid were 70 % of a cluttered frame. Across the lanes of a
  vector:
  - sample(): consecutive samples of a ray, their four neighbours gathered as two 32-bit words at byte offsets
    (the low bytes are a pixel and its right neighbour);
  - screen(): consecutive radii of the grid, each lane computing the three outermost rings' mean levels from the
    ray's running integral (gathers) and the two tests on them that settle almost every radius (test_ring_kernels holds
    the plain scalar version as its reference);
  - score(): the radii that pass, each lane reading every ring of its radius and the tests on the whole reading,
    lanes that finish at different rings held under masks.
  The arithmetic is that of the scalar reference, operation for operation, in doubles (the profile's differences in
  floats, as there); this file is compiled with -ffp-contract=off so that no multiply-add is fused: the results are
  those of the scalar reference bit for bit on every target.
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

// The scalar ring test's integral: the running integral of the profile from 0 to rho, linear between samples. A
// function rather than an object holding its constants: vectors of scalable targets (SVE) cannot be members.
template <class D> HWY_INLINE hn::Vec<D> IntegralAt(D d, const Profile &profile, hn::Vec<D> rho)
{
  using V = hn::Vec<D>;
  const hn::Rebind<int32_t, D> di;
  const hn::Rebind<int64_t, D> dl;
  const hn::Rebind<float, D> df;
  const auto last = hn::Set(di, static_cast<int32_t>(profile.n - 1));
  const V k = hn::Mul(rho, hn::Set(d, profile.invStep));
  const auto i = hn::Min(hn::DemoteTo(di, k), last); // truncation: rho >= 0
  const V fi = hn::PromoteTo(d, i);
  const V f = hn::Sub(k, fi);
  const auto i1 = hn::Min(hn::Add(i, hn::Set(di, 1)), last);
  const auto p0 = hn::GatherIndex(df, profile.p, i), p1 = hn::GatherIndex(df, profile.p, i1);
  const V ci = hn::GatherIndex(d, profile.c, hn::PromoteTo(dl, i));
  const V pr = hn::Add(hn::PromoteTo(d, p0), hn::Mul(hn::Mul(hn::Set(d, 0.5), f), hn::PromoteTo(d, hn::Sub(p1, p0))));
  const V inside = hn::Add(ci, hn::Mul(hn::Mul(f, hn::Set(d, profile.step)), pr));
  // The last sample: no interpolation past it.
  return hn::IfThenElse(hn::Eq(fi, hn::Set(d, static_cast<double>(profile.n - 1))), ci, inside);
}

std::size_t ScreenImpl(const Profile &profileIn, const double *radii, std::size_t n, uint32_t *survivors)
{
  // A local copy: the stores below cannot alias it, so its constants stay in registers.
  const Profile profile = profileIn;
  const hn::ScalableTag<double> d;
  using V = hn::Vec<decltype(d)>;
  const std::size_t N = hn::Lanes(d);
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
    // The ring test stops at the first ring narrower than minWidth or closer than minRadius to the centre; with fewer
    // than three rings it has fewer than two pairs and fails.
    const auto readable = hn::And(hn::And(hn::Ge(hn::Sub(e0, e1), vMinWidth), hn::Ge(hn::Sub(e1, e2), vMinWidth)),
                                  hn::And(hn::And(hn::Ge(hn::Sub(e2, e3), vMinWidth), hn::Ge(e1, vMinRadius)),
                                          hn::And(hn::Ge(e2, vMinRadius), hn::Ge(e3, vMinRadius))));
    if (hn::AllFalse(d, readable)) {
      continue;
    }
    const V i0 = IntegralAt(d, profile, e0), i1 = IntegralAt(d, profile, e1), i2 = IntegralAt(d, profile, e2),
            i3 = IntegralAt(d, profile, e3);
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

std::size_t ScoreImpl(const Profile &profileIn, const ScoreRules &rules, const double *radii, const uint32_t *indices,
                      std::size_t n, uint32_t *passed, double *scores)
{
  // A local copy: the stores below cannot alias it, so its constants stay in registers.
  const Profile profile = profileIn;
  const hn::ScalableTag<double> d;
  using V = hn::Vec<decltype(d)>;
  using M = hn::Mask<decltype(d)>;
  const std::size_t N = hn::Lanes(d);
  const V zero = hn::Zero(d), one = hn::Set(d, 1.), two = hn::Set(d, 2.);
  const V vq = hn::Set(d, profile.q), vMinWidth = hn::Set(d, profile.minWidth),
          vMinRadius = hn::Set(d, profile.minRadius);
  const V vOneMinusQ = hn::Set(d, 1. - profile.q), vClearWidth = hn::Set(d, rules.clearWidth);
  const V vQuarter = hn::Set(d, 0.25), vReversal = hn::Set(d, -0.15), vMinPair = hn::Set(d, rules.minPairContrast);
  const V vOuterShare = hn::Set(d, rules.outerShare), vAlternations = hn::Set(d, rules.minAlternations);
  const V vInk = hn::Set(d, rules.inkTolerance), vBlurredInk = hn::Set(d, rules.blurredInkTolerance);
  const V vMaxPairs = hn::Set(d, 64.);
  // Ring levels and pair contrasts, lane by lane, as the scalar ring test kept them (at most 64 pairs).
  constexpr std::size_t kMaxLanes = HWY_MAX_BYTES / sizeof(double);
  HWY_ALIGN double level[65 * kMaxLanes], contrast[64 * kMaxLanes], lanes[kMaxLanes];
  uint8_t bits[8];
  std::size_t count = 0;
  for (std::size_t j = 0; j < n; j += N) {
    // The lanes past the last radius repeat it; their results are dropped.
    for (std::size_t k = 0; k < N; ++k) {
      lanes[k] = radii[indices[std::min(j + k, n - 1)]];
    }
    const V radius = hn::Load(d, lanes);
    // The rings, out to the first one too thin or too close to the centre (the scalar test's loop; the screen has
    // passed its two early exits).
    V outerEdge = radius, outerIntegral = IntegralAt(d, profile, radius), previous = zero, cmax = zero, nb = zero;
    M alive = hn::Eq(zero, zero);
    int rings = 0;
    for (int k = 0; k < 65; ++k) {
      alive = hn::And(alive, hn::Lt(nb, vMaxPairs));
      const V innerEdge = hn::Mul(outerEdge, vq);
      const V width = hn::Sub(outerEdge, innerEdge);
      alive = hn::And(alive, hn::And(hn::Ge(width, vMinWidth), hn::Ge(innerEdge, vMinRadius)));
      if (hn::AllFalse(d, alive)) {
        break;
      }
      const V innerIntegral = IntegralAt(d, profile, innerEdge);
      const V mean = hn::Div(hn::Sub(outerIntegral, innerIntegral), width);
      hn::Store(mean, d, level + k * N);
      if (k > 0) {
        // Positive where the rings alternate as printed: ring k is black for even k.
        const V c = ((k - 1) % 2 == 0) ? hn::Sub(mean, previous) : hn::Sub(previous, mean);
        hn::Store(c, d, contrast + (k - 1) * N);
        cmax = hn::IfThenElse(alive, hn::Max(cmax, c), cmax);
        nb = hn::IfThenElse(alive, hn::Add(nb, one), nb);
      }
      outerIntegral = innerIntegral;
      previous = mean;
      outerEdge = innerEdge;
      rings = k + 1;
    }
    // Pairs clear enough to be resolved by any lens.
    V nbExpected = zero, r = hn::Mul(radius, vq);
    for (int k = 0; k < rings; ++k) {
      const M more = hn::And(hn::Lt(nbExpected, nb), hn::Ge(hn::Mul(r, vOneMinusQ), vClearWidth));
      if (hn::AllFalse(d, more)) {
        break;
      }
      nbExpected = hn::IfThenElse(more, hn::Add(nbExpected, one), nbExpected);
      r = hn::IfThenElse(more, hn::Mul(r, vq), r);
    }
    // The alternating pairs from the outermost one inwards: a clear reversal fails the radius, a fading pair ends
    // the count.
    V score = zero, nbPairs = zero;
    M counting = hn::Eq(zero, zero), failed = hn::Lt(one, zero);
    const V weak = hn::Mul(vQuarter, cmax), reversed = hn::Mul(vReversal, cmax);
    for (int i = 0; i + 1 < rings; ++i) {
      counting = hn::And(counting, hn::Lt(hn::Set(d, static_cast<double>(i)), nb));
      if (hn::AllFalse(d, counting)) {
        break;
      }
      const V c = hn::Load(d, contrast + i * N);
      const M strong = hn::Ge(c, weak);
      failed = hn::Or(failed, hn::And(hn::AndNot(strong, counting), hn::Le(c, reversed)));
      const M add = hn::And(counting, strong);
      score = hn::IfThenElse(add, hn::Add(score, c), score);
      nbPairs = hn::IfThenElse(add, hn::Add(nbPairs, one), nbPairs);
      counting = add;
    }
    failed = hn::Or(failed, hn::Lt(nbPairs, two));
    // The black rings' ink, from the clearly resolved rings: the outermost ring must be as dark.
    const V nbLevels = hn::Min(nbPairs, hn::Max(two, nbExpected));
    V black = zero, white = zero, nbBlack = zero, nbWhite = zero;
    for (int k = 1; k < rings; ++k) {
      const M in = hn::Le(hn::Set(d, static_cast<double>(k)), nbLevels);
      if (hn::AllFalse(d, in)) {
        break;
      }
      const V l = hn::Load(d, level + k * N);
      if (k % 2 == 0) {
        black = hn::IfThenElse(in, hn::Add(black, l), black);
        nbBlack = hn::IfThenElse(in, hn::Add(nbBlack, one), nbBlack);
      } else {
        white = hn::IfThenElse(in, hn::Add(white, l), white);
        nbWhite = hn::IfThenElse(in, hn::Add(nbWhite, one), nbWhite);
      }
    }
    // Lanes that failed above may have no level of a colour: their quotient is not used.
    black = hn::Div(black, hn::Max(nbBlack, one));
    white = hn::Div(white, hn::Max(nbWhite, one));
    const V outer = hn::Load(d, level);
    const V dark = hn::IfThenElse(hn::Or(hn::Ge(nbExpected, two), hn::Lt(nbPairs, hn::Set(d, 3.))), vInk, vBlurredInk);
    const V range = hn::Sub(white, black);
    failed = hn::Or(failed, hn::Or(hn::Gt(hn::Sub(outer, black), hn::Mul(vInk, range)),
                                   hn::Gt(hn::Sub(black, outer), hn::Mul(dark, range))));
    // rayCandidates(): every clearly resolvable pair must alternate, the pairs must be strong on average and the
    // outermost one with them.
    const V needed = hn::Max(two, hn::Min(hn::Sub(nbExpected, one), vAlternations));
    const V outerContrast = hn::Load(d, contrast);
    failed = hn::Or(failed, hn::Or(hn::Lt(nbPairs, needed), hn::Lt(score, hn::Mul(vMinPair, nbPairs))));
    failed = hn::Or(failed, hn::Lt(outerContrast, hn::Div(hn::Mul(vOuterShare, score), nbPairs)));
    hn::StoreMaskBits(d, hn::Not(failed), bits);
    hn::Store(score, d, lanes);
    for (std::size_t k = 0; k < N && j + k < n; ++k) {
      if ((bits[k / 8] >> (k % 8)) & 1) {
        passed[count] = indices[j + k];
        scores[count] = lanes[k];
        ++count;
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
HWY_EXPORT(ScoreImpl);

void sample(const Ray &ray, std::size_t i0, std::size_t i1, float *out)
{
  HWY_DYNAMIC_DISPATCH(SampleImpl)(ray, i0, i1, out);
}

std::size_t screen(const Profile &profile, const double *radii, std::size_t n, uint32_t *survivors)
{
  return HWY_DYNAMIC_DISPATCH(ScreenImpl)(profile, radii, n, survivors);
}

std::size_t score(const Profile &profile, const ScoreRules &rules, const double *radii, const uint32_t *indices,
                  std::size_t n, uint32_t *passed, double *scores)
{
  return HWY_DYNAMIC_DISPATCH(ScoreImpl)(profile, rules, radii, indices, n, passed, scores);
}
} // namespace vpSSLRayKernel
#endif
