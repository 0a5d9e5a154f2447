#include <visp3/ssl/vpSSLRadiusEstimator.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <visp3/core/vpException.h>

#include "vpSSLImageCheck.h"

#include "vpSSLRadiusEstimatorInternal.h"
#include "vpSSLRayKernel.h"

using namespace vpSSLRadiusEstimatorInternal;

namespace {
// Rings narrower than this (px) are blurred into their neighbours by any real lens: not read.
const double kMinRingWidth = 0.8;
// Rings closer to the centre than this (px) are dominated by the centre's sub-pixel uncertainty.
const double kMinRingRadius = 1.0;
// Grid ratio of the radius search; the best grid value is then refined by a parabola.
const double kGridRatio = 1.02;
// Rings at least this wide (px) are read on any landmark that is in focus.
const double kClearRingWidth = 2.5;
// How far the outermost ring's level may stray from the inner black rings', relative to the ring contrast.
const double kInkTolerance = 0.3;
// The same on the dark side when fewer than two ring pairs are clearly resolvable.
const double kBlurredInkTolerance = 0.6;
// Share of a solid ring's interior samples that must be on its side of the mid level.
const double kSolidRing = 0.85;
// Largest residual of the half-turn comparison (symmetryCentre()), relative to the disc's variance (clutter
// is near 1).
const double kMaxAsymmetry = 0.6;
// Share of the best level's total score that an outer level needs to be taken for the landmark's.
const double kLevelShare = 0.7;
// Share of the pairs' mean contrast that the outermost pair needs.
const double kOuterShare = 0.6;
// So the outermost pair's contrast must be 0.6 kMinPairContrast (3.6) or more: below this (a margin for rounding) a
// radius is given up on at once.
const double kMinOuterContrast = 3.5;
// Alternating ring pairs a ray must show, blur permitting (fewer only when fewer rings are resolvable).
const int kMinAlternations = 3;

// Directions around the ellipse at which ringsAllAround() reads the two outer rings.
const int kAroundSamples = 32;
// Share of those samples that must be on their ring's side of the mid level (occlusion and glare allowed for).
const double kAroundShare = 0.78;

// Half-width (in p-levels) of the radius window of a tracked re-reading: 0.15 level is 11 % either way for
// p = 0.5, more than the apparent radius changes between frames; a landmark that changed more is read again
// from scratch (vpSSLDetector falls back to estimate()).
const double kTrackedWindow = 0.15;

// Largest relative distance of a ray's edge point from the fitted ellipse.
const double kMaxEllipseResidual = 0.08;

inline float bilinear(const vpImage<unsigned char> &I, double u, double v)
{
  const int u0 = static_cast<int>(u), v0 = static_cast<int>(v);
  const double fu = u - u0, fv = v - v0;
  const int u1 = std::min(u0 + 1, static_cast<int>(I.getWidth()) - 1);
  const int v1 = std::min(v0 + 1, static_cast<int>(I.getHeight()) - 1);
  const double top = (1. - fu) * I[v0][u0] + fu * I[v0][u1];
  const double bottom = (1. - fu) * I[v1][u0] + fu * I[v1][u1];
  return static_cast<float>((1. - fv) * top + fv * bottom);
}
} // namespace

vpSSLRadiusEstimator::vpSSLRadiusEstimator()
    : m_minRadius(4.), m_maxRadius(300.), m_minDirections(6), m_p(0.5), m_q(std::sqrt(0.5)), m_step(0.5),
      m_pixelScale(1.)
{
}

void vpSSLRadiusEstimator::setRadiusRange(double minRadius, double maxRadius)
{
  if (!(minRadius >= 2. && minRadius < maxRadius)) {
    throw vpException(vpException::badValue, "vpSSLRadiusEstimator: radius range [%g, %g] invalid", minRadius,
                      maxRadius);
  }
  m_minRadius = minRadius;
  m_maxRadius = maxRadius;
}

void vpSSLRadiusEstimator::setMinDirections(unsigned int n)
{
  if (n < 3 || n > 8) {
    throw vpException(vpException::badValue, "vpSSLRadiusEstimator: min directions %u not in [3, 8]", n);
  }
  m_minDirections = n;
}

void vpSSLRadiusEstimator::setPixelScale(double scale)
{
  if (!(scale >= 1.)) {
    throw vpException(vpException::badValue, "vpSSLRadiusEstimator: pixel scale %g < 1", scale);
  }
  m_pixelScale = scale;
}

void vpSSLRadiusEstimator::setP(double p)
{
  if (!(p > 0. && p < 1.)) {
    throw vpException(vpException::badValue, "vpSSLRadiusEstimator: p = %g not in (0, 1)", p);
  }
  m_p = p;
  m_q = std::sqrt(p);
}

bool vpSSLRadiusEstimator::readRays(const vpImage<unsigned char> &I, double u, double v, double maxRadius)
{
  const double W = I.getWidth() - 1., H = I.getHeight() - 1.;
  if (!(u >= 0. && v >= 0. && u <= W && v <= H)) {
    return false;
  }
  if (m_rayImage == &I && m_rayU == u && m_rayV == v && m_rayMaxRadius == maxRadius) {
    return true; // the rays from this centre are still there
  }
  // A ray is read when first needed (ray()): most candidates are given up after a few rays.
  m_rayImage = &I;
  m_rayU = u;
  m_rayV = v;
  m_rayMaxRadius = maxRadius;
  for (int d = 0; d < 8; ++d) {
    m_rayRead[d] = false;
  }
  return true;
}

void vpSSLRadiusEstimator::ray(int d, double upTo)
{
  const vpImage<unsigned char> &I = *m_rayImage;
  const double W = I.getWidth() - 1., H = I.getHeight() - 1.;
  const double u = m_rayU, v = m_rayV;
  std::vector<float> &P = m_profile[d];
  std::vector<double> &C = m_prefix[d];
  // Sample i lies at rho = i m_step (exact: m_step is a power of two) while inside the search range and
  // the image; leaving either is final along a ray from an inside centre, so the ray's length is found by
  // bisection without reading it.
  auto inside = [&](size_t i) {
    const double rho = static_cast<double>(i) * m_step;
    const double x = u + rho * kCos[d], y = v + rho * kSin[d];
    return !(rho > m_rayMaxRadius || x < 0. || y < 0. || x > W || y > H);
  };
  if (!m_rayRead[d]) {
    m_rayRead[d] = true;
    P.clear();
    C.assign(1, 0.);
    m_mean3[d].clear();
    size_t lo = 0, hi = static_cast<size_t>(m_rayMaxRadius / m_step) + 2; // inside(lo), !inside(hi)
    while (hi - lo > 1) {
      const size_t mid = (lo + hi) / 2;
      (inside(mid) ? lo : hi) = mid;
    }
    m_raySamples[d] = lo + 1;
  }
  // Only the samples out to upTo (and two beyond, for interpolation) are read: the centre refinement
  // re-reads the rays near the landmark's radius only, and most candidates are given up on early.
  const size_t want = std::min(m_raySamples[d], static_cast<size_t>(std::max(0., upTo / m_step)) + 3);
  const size_t have = P.size();
  if (want <= have) {
    return;
  }
  // Storage only grows (no allocation once the longest ray has been read); plain stores rather than push_back.
  P.resize(want);
  C.resize(std::max<size_t>(1, want));
  float *p = P.data();
  double *c = C.data();
  const double halfStep = 0.5 * m_step;
  // The samples first (SIMD: they are independent of each other), then their running integral (a chain of
  // additions, in the order of the scalar loop).
  const vpSSLRayKernel::Ray r = {
      I.bitmap, static_cast<int>(I.getWidth()), static_cast<int>(I.getHeight()), u, v, kCos[d], kSin[d], m_step};
  vpSSLRayKernel::sample(r, have, want, p);
  // Trapezoidal integral of the profile from 0 to rho.
  double integral = c[have > 0 ? have - 1 : 0];
  for (size_t i = std::max<size_t>(have, 1); i < want; ++i) {
    integral = integral + halfStep * (p[i - 1] + p[i]);
    c[i] = integral;
  }
}

bool vpSSLRadiusEstimator::solidRings(int d, double radius)
{
  const std::vector<float> &P = m_profile[d];
  const double q = std::sqrt(m_p);
  // Mid level between the two outer rings, from their middle halves.
  double level[2];
  for (int k = 0; k < 2; ++k) {
    const double outer = k == 0 ? radius : radius * q, inner = outer * q, margin = 0.25 * (outer - inner);
    const size_t i0 = static_cast<size_t>(std::ceil((inner + margin) / m_step));
    const size_t i1 = std::min(P.size() - 1, static_cast<size_t>(std::floor((outer - margin) / m_step)));
    double sum = 0.;
    size_t n = 0;
    for (size_t i = i0; i <= i1; ++i, ++n) {
      sum += P[i];
    }
    level[k] = n > 0 ? sum / n : 0.;
  }
  const double mid = 0.5 * (level[0] + level[1]);
  // The two outer rings are printed solid: away from their blurred edges nearly every sample must be on
  // their side of the mid level. A neighbouring landmark's ring or the sheet's edge that happens to
  // darken part of the band beyond a landmark is not.
  for (int k = 0; k < 2; ++k) {
    const double outer = k == 0 ? radius : radius * q, inner = outer * q;
    const double margin = 0.25 * (outer - inner);
    const size_t i0 = static_cast<size_t>(std::ceil((inner + margin) / m_step)) + 1;
    const size_t i1 = std::min(P.size() - 2, static_cast<size_t>(std::floor((outer - margin) / m_step)));
    // Three neighbouring samples (1.5 px) so that sensor noise does not flip a sample. Their means are kept
    // with the ray: the dozen radii a tracked ray is read at share most of them.
    std::vector<double> &mean3 = m_mean3[d];
    if (i0 <= i1 && mean3.size() < i1 + 1) {
      size_t i = std::max<size_t>(1, mean3.size());
      mean3.resize(i1 + 1);
      for (; i <= i1; ++i) {
        mean3[i] = (P[i - 1] + P[i] + P[i + 1]) / 3.;
      }
    }
    size_t n = 0, right = 0;
    const double *value = mean3.data();
    for (size_t i = i0; i <= i1; ++i, ++n) {
      right += ((value[i] < mid) == (k == 0)) ? 1 : 0;
    }
    if (n > 0 && right < kSolidRing * n) {
      return false;
    }
  }
  return true;
}

void vpSSLRadiusEstimator::rayCandidates(int d, double ref, std::vector<Candidate> &candidates)
{
  candidates.clear();
  ray(d, 0.);
  const double available = (m_raySamples[d] - 1) * m_step;
  const double rMax = std::min(m_maxRadius, available);
  std::vector<double> &grid = m_grid, &scores = m_scores;
  grid.clear();
  const double logStep = std::log(1. / m_p);
  if (m_fullGridMin != m_minRadius || m_fullGridMax != m_maxRadius) {
    m_fullGrid.clear();
    for (double r = m_minRadius; r <= m_maxRadius; r *= kGridRatio) {
      m_fullGrid.push_back(r);
    }
    m_fullGridMin = m_minRadius;
    m_fullGridMax = m_maxRadius;
  }
  // From the whole range, the grid is a prefix of the full one; given a first reading, only the p-similar levels
  // around it are worth a look.
  const double *g = m_fullGrid.data();
  size_t n = static_cast<size_t>(std::upper_bound(m_fullGrid.begin(), m_fullGrid.end(), rMax) - m_fullGrid.begin());
  if (ref > 0.) {
    auto first = m_fullGrid.begin();
    if (m_levelZeroOnly) {
      // Tracked: the grid below the previous level's window is not even looked at.
      first =
          std::lower_bound(m_fullGrid.begin(), m_fullGrid.end(), ref * std::exp(-(kTrackedWindow + 0.01) * logStep));
    }
    for (auto it = first; it != m_fullGrid.end(); ++it) {
      const double r = *it;
      if (r > rMax) {
        break;
      }
      const double x = std::log(r / ref) / logStep;
      if (m_levelZeroOnly && x > kTrackedWindow) {
        break; // tracked: the previous level only
      }
      if (std::fabs(x - std::round(x)) > 0.3 || (m_levelZeroOnly && x < -kTrackedWindow)) {
        continue;
      }
      grid.push_back(r);
    }
    g = grid.data();
    n = grid.size();
  }
  if (n > 0) {
    ray(d, g[n - 1]);
  }
  scores.assign(n, -1e30);
  // Each radius is compared with the printed rings in SIMD (vpSSLRayKernel): the screen runs the tests on the two
  // outermost ring pairs that almost every radius fails, then the rings of the radii left are all read. Walking
  // inwards from R, the rings must keep alternating until they blur into each other (the lens, the sampling): a
  // clear reversal means R is not the landmark's, a fading contrast ends the reading. Every clearly resolvable ring
  // must alternate (a handful of alternations at a geometric spacing happens in clutter, a full self-similar
  // sequence does not), and the outermost ring must stand out dark against the next one, which pins R against its
  // p-similar copies at R / p (white paper would pass for a missing black ring) and R sqrt(p) (anti-phase). All
  // black rings are printed with the same ink and seen at the same range: the outermost one must be as dark as
  // the inner ones, or a dark background beyond the white paper passes for one more ring and the landmark for one
  // twice its size. Only clearly resolved rings give the ink's level; thinner ones (a small landmark, three pairs
  // or more read) are greyed by the lens and the water's blur, lighter than the wider outermost ring, never darker.
  m_survivors.resize(n);
  m_passed.resize(n);
  m_passedScores.resize(n);
  const std::vector<float> &P = m_profile[d];
  const vpSSLRayKernel::Profile profile = {P.data(),
                                           m_prefix[d].data(),
                                           P.size(),
                                           m_step,
                                           1. / m_step,
                                           m_q,
                                           kMinRingWidth * m_pixelScale,
                                           kMinRingRadius * m_pixelScale,
                                           kMinOuterContrast};
  const vpSSLRayKernel::ScoreRules rules = {kClearRingWidth * m_pixelScale,
                                            kMinPairContrast,
                                            kOuterShare,
                                            kMinAlternations,
                                            kInkTolerance,
                                            kBlurredInkTolerance};
  const size_t nbSurvivors = n == 0 ? 0 : vpSSLRayKernel::screen(profile, g, n, m_survivors.data());
  const size_t nbPassed =
      vpSSLRayKernel::score(profile, rules, g, m_survivors.data(), nbSurvivors, m_passed.data(), m_passedScores.data());
  size_t nbScored = 0;
  for (size_t k = 0; k < nbPassed; ++k) {
    // The dearest test, last.
    if (solidRings(d, g[m_passed[k]])) {
      scores[m_passed[k]] = m_passedScores[k];
      m_passed[nbScored++] = m_passed[k];
    }
  }
  // Every local maximum is a candidate: the landmark's R, its p-similar inner copies R p^k, and whatever
  // the clutter around it makes of R / p. The rays decide together (estimate()). Only scored radii can be one.
  for (size_t k = 0; k < nbScored; ++k) {
    const size_t i = m_passed[k];
    const double b = scores[i];
    // Neighbours on the grid only (the level windows leave gaps in it).
    const bool left = i > 0 && g[i - 1] > g[i] / (1.5 * kGridRatio);
    const bool right = i + 1 < n && g[i + 1] < g[i] * 1.5 * kGridRatio;
    const double a = left ? scores[i - 1] : -1e30, c = right ? scores[i + 1] : -1e30;
    if (b <= -1e29 || a > b || c >= b) {
      continue;
    }
    Candidate cand;
    cand.radius = g[i];
    cand.score = b;
    if (a > -1e29 && c > -1e29) {
      const double den = a - 2. * b + c;
      if (den < 0.) {
        cand.radius *= std::pow(kGridRatio, std::max(-1., std::min(1., 0.5 * (a - c) / den)));
      }
    }
    candidates.push_back(cand);
  }
}

bool vpSSLRadiusEstimator::selectRadii(const double *ref, double R[8], bool ok[8], double &scale)
{
  std::vector<Candidate> *candidates = m_candidates;
  // Opposite rays first, so that clutter is given up on after a few rays rather than all eight.
  const int order[8] = {0, 4, 2, 6, 1, 5, 3, 7};
  unsigned int empty = 0;
  for (int d : order) {
    if (!m_keepCandidates) {
      rayCandidates(d, ref ? ref[d] : 0., candidates[d]);
    }
    empty += candidates[d].empty() ? 1 : 0;
    if (empty > 8 - m_minDirections) {
      return false;
    }
  }
  if (ref == nullptr) {
    // From the matching peak, which may sit a few pixels off the centre for a landmark smaller than the
    // window: each ray's best reading, and the rays that disagree wildly with the others dropped.
    std::vector<double> &valid = m_valid;
    valid.clear();
    for (int d = 0; d < 8; ++d) {
      ok[d] = false;
      double best = -1.;
      for (const Candidate &c : candidates[d]) {
        if (c.score > best) {
          best = c.score;
          R[d] = c.radius;
          ok[d] = true;
        }
      }
      if (ok[d]) {
        valid.push_back(R[d]);
      }
    }
    if (valid.size() < m_minDirections) {
      return false;
    }
    // A dark background beyond the paper can make half the rays prefer R / p, while every ray still reads
    // R: first the scale most rays can read (within the factor 2 either way that a tilted landmark's rays
    // span), then the median of the rays' best readings at that scale.
    unsigned int bestSupport = 0;
    double bestTotal = -1., anchor = valid.front();
    for (double h : valid) {
      unsigned int support = 0;
      double total = 0.;
      for (int d = 0; d < 8; ++d) {
        double score = -1.;
        for (const Candidate &c : candidates[d]) {
          if (c.radius >= 0.55 * h && c.radius <= 1.8 * h) {
            score = std::max(score, c.score);
          }
        }
        if (score > 0.) {
          ++support;
          total += score;
        }
      }
      if (support > bestSupport || (support == bestSupport && total > bestTotal)) {
        bestSupport = support;
        bestTotal = total;
        anchor = h;
      }
    }
    valid.clear();
    for (int d = 0; d < 8; ++d) {
      double score = -1., radius = 0.;
      for (const Candidate &c : candidates[d]) {
        if (c.radius >= 0.55 * anchor && c.radius <= 1.8 * anchor && c.score > score) {
          score = c.score;
          radius = c.radius;
        }
      }
      if (score > 0.) {
        valid.push_back(radius);
      }
    }
    std::nth_element(valid.begin(), valid.begin() + valid.size() / 2, valid.end());
    scale = valid[valid.size() / 2];
    // Each ray then takes its reading nearest the median: a ray whose best reading is another level
    // (clutter extending the pattern, an inner copy, perspective) usually has this landmark's too.
    for (int d = 0; d < 8; ++d) {
      ok[d] = false;
      for (const Candidate &c : candidates[d]) {
        if (c.radius >= 0.6 * scale && c.radius <= 1.7 * scale &&
            (!ok[d] || std::fabs(std::log(c.radius / scale)) < std::fabs(std::log(R[d] / scale)))) {
          R[d] = c.radius;
          ok[d] = true;
        }
      }
    }
    return true;
  }
  // The p-similar copies of the landmark sit at R p^k along every ray, so each ray's candidates fall on
  // levels k relative to the first reading (ref: its ellipse, in this ray's direction). The inner copies
  // read fewer rings, so they score less than R; a level beyond R shows only where clutter (a
  // neighbour's ring, the sheet's edge) happens to extend the pattern, on a few rays. So the outermost
  // level whose rays together score nearly as much as the best level's is the landmark's.
  const double logStep = std::log(1. / m_p);
  const int minLevel = -3, maxLevel = 2;
  double total[maxLevel - minLevel + 1] = {0.};
  unsigned int support[maxLevel - minLevel + 1] = {0};
  double pick[maxLevel - minLevel + 1][8];
  double pickScore[maxLevel - minLevel + 1][8];
  for (int k = 0; k <= maxLevel - minLevel; ++k) {
    for (int d = 0; d < 8; ++d) {
      pickScore[k][d] = 0.;
    }
  }
  for (int d = 0; d < 8; ++d) {
    for (const Candidate &c : candidates[d]) {
      const double x = std::log(c.radius / ref[d]) / logStep;
      const int k = static_cast<int>(std::lround(x));
      // Within 19 %, or 2 camera pixels for a small landmark whose first reading is that coarse.
      const double tolerance = std::max(0.25, 2. * m_pixelScale / (ref[d] * std::pow(1. / m_p, k)) / logStep);
      if (k < minLevel || k > maxLevel || std::fabs(x - k) >= tolerance) {
        continue;
      }
      const int i = k - minLevel;
      if (c.score > pickScore[i][d]) {
        pickScore[i][d] = c.score;
        pick[i][d] = c.radius;
      }
    }
  }
  double best = 0.;
  unsigned int mostRays = 0;
  for (int i = 0; i <= maxLevel - minLevel; ++i) {
    for (int d = 0; d < 8; ++d) {
      if (pickScore[i][d] > 0.) {
        total[i] += pickScore[i][d];
        ++support[i];
      }
    }
    best = std::max(best, total[i]);
    mostRays = std::max(mostRays, support[i]);
  }
  // The landmark's own level is read by (nearly) every ray that reads anything; the paper's edge beyond a
  // landmark near the sheet's border, against darker water, extends the pattern by one level on the rays
  // that point at it only, and those rays can still score well.
  for (int i = maxLevel - minLevel; i >= 0; --i) {
    if (support[i] >= 3 && support[i] + 1 >= mostRays && total[i] >= kLevelShare * best) {
      for (int d = 0; d < 8; ++d) {
        ok[d] = pickScore[i][d] > 0.;
        R[d] = ok[d] ? pick[i][d] : 0.;
      }
      scale *= std::pow(1. / m_p, i + minLevel);
      return true;
    }
  }
  return false;
}

bool vpSSLRadiusEstimator::symmetricCentre(const vpImage<unsigned char> &I, double &u, double &v)
{
  double asymmetry = 0.;
  // Clutter is seldom point-symmetric: most matching peaks end here, before any ring is read. The peak
  // of a landmark smaller than the window can sit a few pixels off: follow the symmetry until it settles.
  for (int iter = 0; iter < 3; ++iter) {
    const double u0 = u, v0 = v;
    if (!symmetryCentre(I, u, v, asymmetry)) {
      break;
    }
    if (std::fabs(u - u0) < 2.5 && std::fabs(v - v0) < 2.5) {
      break;
    }
  }
  return asymmetry <= kMaxAsymmetry;
}

bool vpSSLRadiusEstimator::estimate(const vpImage<unsigned char> &I, vpSSLLandmark &landmark)
{
  vpSSLImageCheck::kernel(I, "vpSSLRadiusEstimator::estimate");
  if (!std::isfinite(landmark.u) || !std::isfinite(landmark.v)) {
    return false;
  }
  double u = landmark.u, v = landmark.v, scale = 0.;
  m_rayImage = nullptr; // the image may have changed in place since the last call
  m_symmetric = false;
  if (!symmetricCentre(I, u, v)) {
    return false;
  }
  m_symmetric = true;
  m_symmetricU = u;
  m_symmetricV = v;
  double R[8];
  bool ok[8];
  // 1. From the matching peak: a first reading of each ray, and the centre from the ring edges.
  if (!readRays(I, u, v, m_maxRadius) || !selectRadii(nullptr, R, ok, scale) ||
      !refineCentre(I, landmark.u, landmark.v, scale, u, v, R, ok)) {
    return false;
  }
  // 2. From the centre: the rays agree on the landmark's level, and the centre is refined again.
  Ellipse first;
  if (!fitEllipse(R, ok, first)) {
    return false;
  }
  double ref[8];
  for (int d = 0; d < 8; ++d) {
    ref[d] = first.radiusAlong(kCos[d], kSin[d]);
  }
  // The first reading's candidates are kept rather than read again from the refined centre: the centre moved by
  // a fraction of a pixel, far less than the levels' tolerance (19 %), and refineCentre() finds every ring edge
  // again from the refined centre. Reading and scoring all eight rays over the levels' windows again cost as much
  // as the first reading.
  m_keepCandidates = true;
  const bool levels = selectRadii(ref, R, ok, scale);
  m_keepCandidates = false;
  if (!levels || !refineCentre(I, landmark.u, landmark.v, scale, u, v, R, ok)) {
    return false;
  }
  return finish(I, u, v, R, ok, landmark);
}

bool vpSSLRadiusEstimator::estimate(const vpImage<unsigned char> &I, vpSSLLandmark &landmark,
                                    const vpSSLLandmark &prior)
{
  vpSSLImageCheck::kernel(I, "vpSSLRadiusEstimator::estimate");
  if (!std::isfinite(landmark.u) || !std::isfinite(landmark.v)) {
    return false;
  }
  if (!(prior.radius > 0. && prior.minorRadius > 0.)) {
    return estimate(I, landmark);
  }
  double u = landmark.u, v = landmark.v;
  m_rayImage = nullptr;
  if (!symmetricCentre(I, u, v)) {
    return false;
  }
  // The landmark was read in the previous frame: its ellipse gives each ray's level, so the first reading
  // (the radius search over the whole range, the dearest step) is skipped, and the second one searches only
  // around the previous radius (kTrackedWindow: about a tenth either way).
  const double c = std::cos(prior.theta), s = std::sin(prior.theta);
  double ref[8], R[8];
  bool ok[8];
  for (int d = 0; d < 8; ++d) {
    const double x = c * kCos[d] + s * kSin[d], y = -s * kCos[d] + c * kSin[d];
    ref[d] = 1. / std::sqrt(x * x / (prior.radius * prior.radius) + y * y / (prior.minorRadius * prior.minorRadius));
  }
  double scale = 0.5 * (prior.radius + prior.minorRadius);
  m_levelZeroOnly = true;
  const bool read = readRays(I, u, v, m_maxRadius) && selectRadii(ref, R, ok, scale) &&
                    refineCentre(I, landmark.u, landmark.v, scale, u, v, R, ok);
  m_levelZeroOnly = false;
  return read && finish(I, u, v, R, ok, landmark);
}

bool vpSSLRadiusEstimator::finish(const vpImage<unsigned char> &I, double u, double v, double R[8], bool ok[8],
                                  vpSSLLandmark &landmark)
{
  // The rays' edge points lie on one ellipse centred on the landmark; a ray that strays from it read
  // something else (occluder, clutter) and is dropped, and a candidate without a consistent ellipse is no
  // landmark.
  Ellipse e;
  for (;;) {
    unsigned int nb = 0;
    for (int d = 0; d < 8; ++d) {
      nb += ok[d] ? 1 : 0;
    }
    if (nb < m_minDirections || !fitEllipse(R, ok, e)) {
      return false;
    }
    if (e.worstResidual <= kMaxEllipseResidual) {
      landmark.nbDirections = nb;
      break;
    }
    if (e.worstRay < 0) {
      return false;
    }
    ok[e.worstRay] = false;
  }
  if (!ringsAllAround(I, u, v, e)) {
    return false;
  }
  for (int d = 0; d < 8; ++d) {
    landmark.directionalRadius[d] = ok[d] ? R[d] : 0.;
  }
  landmark.u = u;
  landmark.v = v;
  landmark.radius = e.major;
  landmark.minorRadius = e.minor;
  landmark.theta = e.theta;
  return true;
}

bool vpSSLRadiusEstimator::ringsAllAround(const vpImage<unsigned char> &I, double u, double v, const Ellipse &e) const
{
  // The eight rays see eight lines through the candidate: a chessboard or a periodic texture can show a
  // ring sequence along each of them. Printed rings are closed: all around the ellipse, the middle of the
  // outermost (black) ring must be darker than the middle of the next (white) one.
  const double q = std::sqrt(m_p);
  const double sBlack = 0.5 * (1. + q), sWhite = 0.5 * (q + m_p);
  const double W = I.getWidth() - 1., H = I.getHeight() - 1.;
  float black[kAroundSamples], white[kAroundSamples];
  int n = 0;
  double sumBlack = 0., sumWhite = 0.;
  for (int k = 0; k < kAroundSamples; ++k) {
    const double angle = 2. * M_PI * k / kAroundSamples, x = std::cos(angle), y = std::sin(angle);
    const double r = e.radiusAlong(x, y);
    const double ub = u + sBlack * r * x, vb = v + sBlack * r * y, uw = u + sWhite * r * x, vw = v + sWhite * r * y;
    if (!(ub >= 0. && vb >= 0. && ub <= W && vb <= H)) {
      continue; // outside the image: not seen, neither for nor against
    }
    black[n] = bilinear(I, ub, vb);
    white[n] = bilinear(I, uw, vw);
    sumBlack += black[n];
    sumWhite += white[n];
    ++n;
  }
  if (n < kAroundSamples / 2) {
    return true; // too little of the landmark in view to judge: the rays decided
  }
  const double mid = 0.5 * (sumBlack + sumWhite) / n;
  int right = 0;
  for (int k = 0; k < n; ++k) {
    right += (black[k] < mid ? 1 : 0) + (white[k] > mid ? 1 : 0);
  }
  return right >= kAroundShare * 2 * n;
}

unsigned int vpSSLRadiusEstimator::sweep(const vpImage<unsigned char> &I, const vpSSLMatchingFunction &match, int u,
                                         int v, unsigned int maxWindow, std::vector<int> &S)
{
  match.cumulative(I, u, v, vpSSL_PLUS_X, maxWindow, S);
  unsigned int best = 0;
  for (unsigned int w = 2; w < S.size(); ++w) {
    if (best == 0 || S[w] > S[best]) {
      best = w;
    }
  }
  return best;
}
