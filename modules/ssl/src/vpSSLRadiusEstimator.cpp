#include <visp3/ssl/vpSSLRadiusEstimator.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <visp3/core/vpException.h>

namespace {
const double kCos[8] = {1., M_SQRT1_2, 0., -M_SQRT1_2, -1., -M_SQRT1_2, 0., M_SQRT1_2};
const double kSin[8] = {0., M_SQRT1_2, 1., M_SQRT1_2, 0., -M_SQRT1_2, -1., -M_SQRT1_2};
// Rings narrower than this (px) are blurred into their neighbours by any real lens: not read.
const double kMinRingWidth = 0.8;
// Rings closer to the centre than this (px) are dominated by the centre's sub-pixel uncertainty.
const double kMinRingRadius = 1.0;
// Grid ratio of the radius search; the best grid value is then refined by a parabola.
const double kGridRatio = 1.02;
// Smallest mean contrast (grey levels of the normalised image) between adjacent rings of a readable ray.
const double kMinPairContrast = 6.;
// Rings at least this wide (px) are read on any landmark that is in focus.
const double kClearRingWidth = 2.5;
// How far the outermost ring's level may stray from the inner black rings', relative to the ring contrast.
const double kInkTolerance = 0.3;
// Share of a solid ring's interior samples that must be on its side of the mid level.
const double kSolidRing = 0.85;
// Radius (px) of the disc compared with its half-turn to centre a candidate: the innermost rings, which
// every landmark has whatever its size.
const double kSymmetryRadius = 8.;
// Largest residual of that comparison, relative to the disc's variance (clutter is near 1).
const double kMaxAsymmetry = 0.6;
// Share of the best level's total score that an outer level needs to be taken for the landmark's.
const double kLevelShare = 0.7;
// Alternating ring pairs a ray must show, blur permitting (fewer only when fewer rings are resolvable).
const int kMinAlternations = 3;

// Largest relative distance of a ray's edge point from the fitted ellipse.
const double kMaxEllipseResidual = 0.08;

struct Ellipse
{
  double major = 0., minor = 0., theta = 0.;
  double a = 0., b = 0., c = 0.; // a x^2 + 2 b x y + c y^2 = 1
  //! Distance from the centre to the ellipse along the unit direction (x, y).
  double radiusAlong(double x, double y) const { return 1. / std::sqrt(a * x * x + 2. * b * x * y + c * y * y); }
  double worstResidual = 0.;
  int worstRay = -1;
};

// Least-squares ellipse centred at the origin, A x^2 + B x y + C y^2 = 1, through the points R[d] (cos, sin).
bool fitEllipse(const double R[8], const bool ok[8], Ellipse &e)
{
  double N[3][3] = {{0.}}, r[3] = {0.};
  unsigned int axes = 0;
  for (int d = 0; d < 8; ++d) {
    if (!ok[d]) {
      continue;
    }
    axes |= 1u << (d % 4);
    const double x = R[d] * kCos[d], y = R[d] * kSin[d];
    const double row[3] = {x * x, x * y, y * y};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        N[i][j] += row[i] * row[j];
      }
      r[i] += row[i];
    }
  }
  // Three distinct axes are needed to pin the three coefficients.
  if (((axes & 1) != 0) + ((axes & 2) != 0) + ((axes & 4) != 0) + ((axes & 8) != 0) < 3) {
    return false;
  }
  auto det3 = [](const double M[3][3]) {
    return M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
           M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
  };
  const double D = det3(N);
  if (!(std::fabs(D) > 1e-30)) {
    return false;
  }
  double sol[3];
  for (int k = 0; k < 3; ++k) {
    double Mk[3][3];
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        Mk[i][j] = (j == k) ? r[i] : N[i][j];
      }
    }
    sol[k] = det3(Mk) / D;
  }
  const double a = sol[0], b = 0.5 * sol[1], c = sol[2];
  const double tr = a + c, dt = a * c - b * b;
  if (!(a > 0. && dt > 0.)) {
    return false;
  }
  e.a = a;
  e.b = b;
  e.c = c;
  const double disc = std::sqrt(std::max(0., 0.25 * tr * tr - dt));
  const double l1 = 0.5 * tr - disc, l2 = 0.5 * tr + disc; // l1 <= l2: l1 along the major axis
  e.major = 1. / std::sqrt(l1);
  e.minor = 1. / std::sqrt(l2);
  const double theta = 0.5 * std::atan2(2. * b, a - c) + M_PI_2;
  e.theta = std::atan2(std::sin(theta), std::cos(theta));
  e.worstResidual = 0.;
  e.worstRay = -1;
  for (int d = 0; d < 8; ++d) {
    if (!ok[d]) {
      continue;
    }
    const double q = a * kCos[d] * kCos[d] + 2. * b * kCos[d] * kSin[d] + c * kSin[d] * kSin[d];
    const double residual = q > 0. ? std::fabs(R[d] * std::sqrt(q) - 1.) : 1e30;
    if (residual > e.worstResidual) {
      e.worstResidual = residual;
      e.worstRay = d;
    }
  }
  return true;
}

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
    : m_minRadius(4.), m_maxRadius(300.), m_minDirections(6), m_p(0.5), m_step(0.5), m_pixelScale(1.)
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

void vpSSLRadiusEstimator::ray(int d)
{
  if (m_rayRead[d]) {
    return;
  }
  m_rayRead[d] = true;
  const vpImage<unsigned char> &I = *m_rayImage;
  const double W = I.getWidth() - 1., H = I.getHeight() - 1.;
  const double u = m_rayU, v = m_rayV;
  std::vector<float> &P = m_profile[d];
  std::vector<double> &C = m_prefix[d];
  P.clear();
  C.assign(1, 0.);
  for (double rho = 0.;; rho += m_step) {
    const double x = u + rho * kCos[d], y = v + rho * kSin[d];
    if (rho > m_rayMaxRadius || x < 0. || y < 0. || x > W || y > H) {
      break;
    }
    P.push_back(bilinear(I, x, y));
    if (P.size() > 1) {
      // Trapezoidal integral of the profile from 0 to rho.
      C.push_back(C.back() + 0.5 * m_step * (P[P.size() - 2] + P.back()));
    }
  }
}

double vpSSLRadiusEstimator::rayScore(int d, double radius, double &outerContrast, int &nbPairsOut,
                                      int &nbExpected) const
{
  const std::vector<float> &P = m_profile[d];
  const std::vector<double> &C = m_prefix[d];
  const double q = std::sqrt(m_p);
  // Integral of the profile from 0 to rho, linear between samples.
  auto integral = [&](double rho) {
    const double k = rho / m_step;
    const size_t i = std::min(static_cast<size_t>(k), C.size() - 1);
    const double f = k - static_cast<double>(i);
    if (i + 1 >= P.size()) {
      return C[i];
    }
    const double pr = P[i] + 0.5 * f * (P[i + 1] - P[i]);
    return C[i] + f * m_step * pr;
  };
  // Contrast of each pair of adjacent rings, signed so that it is positive where the rings alternate
  // as printed: ring k is black for even k (the outermost ring is black), white for odd k.
  double contrast[64], level[65];
  int nb = 0;
  double previous = 0., outerEdge = radius, cmax = 0.;
  for (int k = 0; nb < 64; ++k) {
    const double innerEdge = outerEdge * q;
    if (outerEdge - innerEdge < kMinRingWidth * m_pixelScale || innerEdge < kMinRingRadius * m_pixelScale) {
      break;
    }
    const double mean = (integral(outerEdge) - integral(innerEdge)) / (outerEdge - innerEdge);
    level[k] = mean;
    if (k > 0) {
      contrast[nb] = ((k - 1) % 2 == 0) ? mean - previous : previous - mean;
      cmax = std::max(cmax, contrast[nb]);
      ++nb;
      // rayCandidates() needs the outermost pair's contrast at 0.6 kMinPairContrast (3.6) or more: below
      // 3.5 (a margin for rounding) nothing else need be read.
      if (nb == 1 && contrast[0] < 3.5) {
        nbPairsOut = 0;
        outerContrast = contrast[0];
        nbExpected = 0;
        return -1e30;
      }
    }
    previous = mean;
    outerEdge = innerEdge;
  }
  nbPairsOut = 0;
  outerContrast = nb > 0 ? contrast[0] : 0.;
  // Pairs whose inner ring is wide enough (kClearRingWidth) to survive a real lens: these must all alternate.
  nbExpected = 0;
  for (double r = radius * q; nbExpected < nb && r * (1. - q) >= kClearRingWidth * m_pixelScale; r *= q) {
    ++nbExpected;
  }
  // Walking inwards, the rings must keep alternating until they blur into each other (the lens, the
  // sampling): a clear reversal means this R is not the landmark's; a fading contrast ends the reading.
  double score = 0.;
  for (int i = 0; i < nb; ++i) {
    if (contrast[i] >= 0.25 * cmax) {
      score += contrast[i];
      ++nbPairsOut;
    } else if (contrast[i] <= -0.15 * cmax) {
      return -1e30;
    } else {
      break;
    }
  }
  if (nbPairsOut < 2) {
    return -1e30;
  }
  // All black rings are printed with the same ink and seen at the same range: the outermost one must be
  // as dark as the inner ones. Otherwise a dark background beyond the white paper passes for one more
  // ring, and the landmark for one twice its size.
  double black = 0., white = 0.;
  int nbBlack = 0, nbWhite = 0;
  // Only clearly resolved rings give the ink's level; thinner ones are greyed by the lens and sampling.
  const int nbLevels = std::min(nbPairsOut, std::max(2, nbExpected));
  for (int k = 1; k <= nbLevels; ++k) {
    if (k % 2 == 0) {
      black += level[k];
      ++nbBlack;
    } else {
      white += level[k];
      ++nbWhite;
    }
  }
  black /= nbBlack;
  white /= nbWhite;
  if (std::fabs(level[0] - black) > kInkTolerance * (white - black)) {
    return -1e30;
  }
  return score; // solidRings() is the caller's last test, the dearest
}

bool vpSSLRadiusEstimator::solidRings(int d, double radius) const
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
    size_t n = 0, right = 0;
    for (size_t i = i0; i <= i1; ++i, ++n) {
      // Three neighbouring samples (1.5 px) so that sensor noise does not flip a sample.
      const double value = (P[i - 1] + P[i] + P[i + 1]) / 3.;
      right += ((value < mid) == (k == 0)) ? 1 : 0;
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
  ray(d);
  const double available = (m_profile[d].size() - 1) * m_step;
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
  for (const double r : m_fullGrid) {
    if (r > rMax) {
      break;
    }
    // Given a first reading, only the p-similar levels around it are worth a look.
    if (ref > 0.) {
      const double x = std::log(r / ref) / logStep;
      if (std::fabs(x - std::round(x)) > 0.3) {
        continue;
      }
    }
    grid.push_back(r);
  }
  scores.assign(grid.size(), -1e30);
  for (size_t i = 0; i < grid.size(); ++i) {
    double outer;
    int nbPairs, nbExpected;
    const double s = rayScore(d, grid[i], outer, nbPairs, nbExpected);
    // Every clearly resolvable ring must alternate: a handful of alternations at a geometric spacing
    // happens in clutter, a full self-similar sequence does not.
    if (nbPairs < std::max(2, std::min(nbExpected - 1, kMinAlternations))) {
      continue;
    }
    // The outermost ring must stand out dark against the next one: this pins R against the p-similar
    // copies at R / p (white paper would pass for a missing black ring) and R * sqrt(p) (anti-phase).
    if (s < kMinPairContrast * nbPairs || outer < 0.6 * s / nbPairs || !solidRings(d, grid[i])) {
      continue;
    }
    scores[i] = s;
  }
  // Every local maximum is a candidate: the landmark's R, its p-similar inner copies R p^k, and whatever
  // the clutter around it makes of R / p. The rays decide together (estimate()).
  for (size_t i = 0; i < grid.size(); ++i) {
    const double b = scores[i];
    // Neighbours on the grid only (the level windows leave gaps in it).
    const bool left = i > 0 && grid[i - 1] > grid[i] / (1.5 * kGridRatio);
    const bool right = i + 1 < grid.size() && grid[i + 1] < grid[i] * 1.5 * kGridRatio;
    const double a = left ? scores[i - 1] : -1e30, c = right ? scores[i + 1] : -1e30;
    if (b <= -1e29 || a > b || c >= b) {
      continue;
    }
    Candidate cand;
    cand.radius = grid[i];
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

bool vpSSLRadiusEstimator::ringEdge(int d, double expected, double halfWidth, double &position)
{
  ray(d);
  const std::vector<float> &P = m_profile[d];
  const double q = std::sqrt(m_p);
  // Levels of the two rings that meet here, from their middle halves (away from the blurred edges).
  auto mean = [&](double a, double b) {
    const size_t i0 = static_cast<size_t>(std::max(0., std::ceil(a / m_step)));
    const size_t i1 = std::min(P.size() - 1, static_cast<size_t>(std::floor(b / m_step)));
    double sum = 0.;
    size_t n = 0;
    for (size_t i = i0; i <= i1; ++i, ++n) {
      sum += P[i];
    }
    return n > 0 ? sum / n : -1.;
  };
  const double outerWidth = expected / q - expected, innerWidth = expected - expected * q;
  const double levelOut = mean(expected + 0.25 * outerWidth, expected + 0.75 * outerWidth);
  const double levelIn = mean(expected - 0.75 * innerWidth, expected - 0.25 * innerWidth);
  if (levelOut < 0. || levelIn < 0. || std::fabs(levelOut - levelIn) < kMinPairContrast) {
    return false;
  }
  const double mid = 0.5 * (levelOut + levelIn);
  const long i0 = std::max(0L, static_cast<long>(std::floor((expected - halfWidth) / m_step)));
  const long i1 =
      std::min(static_cast<long>(P.size()) - 2, static_cast<long>(std::ceil((expected + halfWidth) / m_step)));
  double best = -1., bestDist = 1e30;
  for (long i = i0; i <= i1; ++i) {
    const double a = P[i] - mid, b = P[i + 1] - mid;
    if ((a < 0.) != (b < 0.) && a != b) {
      const double rho = (i + a / (a - b)) * m_step;
      if (std::fabs(rho - expected) < bestDist) {
        bestDist = std::fabs(rho - expected);
        best = rho;
      }
    }
  }
  if (best < 0.) {
    return false;
  }
  position = best;
  return true;
}

bool vpSSLRadiusEstimator::selectRadii(const double *ref, double R[8], bool ok[8], double &scale)
{
  std::vector<Candidate> *candidates = m_candidates;
  // Opposite rays first, so that clutter is given up on after a few rays rather than all eight.
  const int order[8] = {0, 4, 2, 6, 1, 5, 3, 7};
  unsigned int empty = 0;
  for (int d : order) {
    rayCandidates(d, ref ? ref[d] : 0., candidates[d]);
    empty += candidates[d].empty() ? 1 : 0;
    if (empty > 8 - m_minDirections) {
      return false;
    }
  }
  if (ref == nullptr) {
    // From the matching peak, which may sit a few pixels off the centre for a landmark smaller than the
    // window: each ray's best reading, and the rays that disagree wildly with the others dropped.
    std::vector<double> valid;
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
  for (int i = 0; i <= maxLevel - minLevel; ++i) {
    for (int d = 0; d < 8; ++d) {
      if (pickScore[i][d] > 0.) {
        total[i] += pickScore[i][d];
        ++support[i];
      }
    }
    best = std::max(best, total[i]);
  }
  for (int i = maxLevel - minLevel; i >= 0; --i) {
    if (support[i] >= 3 && total[i] >= kLevelShare * best) {
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

bool vpSSLRadiusEstimator::refineCentre(const vpImage<unsigned char> &I, double u0, double v0, double scale, double &u,
                                        double &v, double R[8], bool ok[8])
{
  const double q = std::sqrt(m_p);
  unsigned int nbOk = 0;
  // 2. Edges of the printed rings (not the outer edge, whose outside is unknown) locate the centre and
  // the radius to a fraction of a pixel: the midpoint of opposite edges is the centre of that ring's
  // ellipse. Under perspective the rings are not concentric (their centres drift with the square of
  // their radius), so the midpoints of successive rings are extrapolated to radius 0, the image of the
  // landmark's centre.
  const int maxEdges = 3;
  for (int iter = 0; iter < 6; ++iter) {
    double edge[8][maxEdges];
    int nbEdges[8];
    nbOk = 0;
    for (int d = 0; d < 8; ++d) {
      nbEdges[d] = 0;
      if (!ok[d]) {
        continue;
      }
      double expected = R[d] * q;
      for (int j = 0; j < maxEdges; ++j, expected *= q) {
        const double ringWidth = expected * (1. - q);
        // The first edge is needed; deeper ones only help the extrapolation when wide enough not to be blurred.
        const double minWidth = (j == 0 ? 1.2 : 3.) * m_pixelScale;
        if (ringWidth < minWidth || !ringEdge(d, expected, 0.3 * ringWidth, edge[d][j])) {
          break;
        }
        ++nbEdges[d];
      }
      // A ray whose rings are too thin for edges (a small landmark) keeps its pattern-fit radius.
      if (nbEdges[d] > 0) {
        R[d] = edge[d][0] / q;
      }
      ++nbOk;
    }
    if (nbOk < m_minDirections) {
      return false;
    }
    double A00 = 0., A01 = 0., A11 = 0., b0 = 0., b1 = 0.;
    for (int a = 0; a < 4; ++a) {
      const int n = std::min(nbEdges[a], nbEdges[a + 4]);
      if (n == 0) {
        continue;
      }
      // Offset of each ring's centre along this axis, against the ring's radius squared.
      double offset;
      if (n >= 2) {
        double sx = 0., sy = 0., sxx = 0., sxy = 0.;
        for (int j = 0; j < n; ++j) {
          const double r = 0.5 * (edge[a][j] + edge[a + 4][j]), x = r * r, y = 0.5 * (edge[a][j] - edge[a + 4][j]);
          sx += x;
          sy += y;
          sxx += x * x;
          sxy += x * y;
        }
        const double den = n * sxx - sx * sx;
        offset = den > 1e-9 ? (sy * sxx - sx * sxy) / den : sy / n;
      } else {
        offset = 0.5 * (edge[a][0] - edge[a + 4][0]);
      }
      A00 += kCos[a] * kCos[a];
      A01 += kCos[a] * kSin[a];
      A11 += kSin[a] * kSin[a];
      b0 += offset * kCos[a];
      b1 += offset * kSin[a];
    }
    const double det = A00 * A11 - A01 * A01;
    if (det < 1e-6) {
      break;
    }
    const double du = (A11 * b0 - A01 * b1) / det, dv = (A00 * b1 - A01 * b0) / det;
    if (std::fabs(du) < 0.01 && std::fabs(dv) < 0.01) {
      break;
    }
    u += du;
    v += dv;
    // A matching peak sits near the centre; rays that pull it far away read some other pattern.
    if (std::hypot(u - u0, v - v0) > std::max(2., 0.25 * scale)) {
      return false;
    }
    for (int d = 0; d < 8; ++d) {
      R[d] -= du * kCos[d] + dv * kSin[d];
    }
    if (!readRays(I, u, v, m_maxRadius)) {
      return false;
    }
  }
  return true;
}

bool vpSSLRadiusEstimator::symmetryCentre(const vpImage<unsigned char> &I, double &u, double &v, double &asymmetry)
{
  // The landmark is point-symmetric, and stays so under any affine view, symmetric blur and noise: its
  // centre minimises the difference between the image and its half-turn about it. Centres on the
  // half-pixel grid pair whole pixels, so no interpolation is needed.
  const int radius = static_cast<int>(std::lround(kSymmetryRadius * m_pixelScale));
  const int W = static_cast<int>(I.getWidth()), H = static_cast<int>(I.getHeight());
  const int reach = 6; // half pixels searched either way
  const int cu = static_cast<int>(std::lround(2. * u)), cv = static_cast<int>(std::lround(2. * v));
  if (cu - reach < 2 * radius || cv - reach < 2 * radius || cu + reach > 2 * (W - 1 - radius) ||
      cv + reach > 2 * (H - 1 - radius)) {
    asymmetry = 0.;
    return false; // too close to the border to compare both halves: keep the peak
  }
  // Pixels p and q with p + q = 2 c, c = (su, sv) / 2: p = (su >> 1, sv >> 1) + (dx, dy) and
  // q = (su - p.u, sv - p.v). Half the disc (dy > 0, or dy = 0 and dx > 0) pairs every pixel once.
  if (m_symmetryRadius != radius || m_symmetryWidth != W) {
    m_symmetryOffsets.clear();
    for (int dy = 0; dy <= radius; ++dy) {
      for (int dx = -radius; dx <= radius; ++dx) {
        if (dx * dx + dy * dy <= radius * radius && (dy > 0 || dx > 0)) {
          m_symmetryOffsets.push_back(dy * W + dx);
        }
      }
    }
    m_symmetryRadius = radius;
    m_symmetryWidth = W;
  }
  const int *offsets = m_symmetryOffsets.data();
  const int nbOffsets = static_cast<int>(m_symmetryOffsets.size());
  const unsigned char *bitmap = I.bitmap;
  // Sum of squared differences (exact in integers) about the centre (su, sv) / 2, given up as soon as it
  // exceeds \e bound (returns bound + 1 then): only the minimum and its neighbours are needed.
  auto energy = [&](int su, int sv, long bound) {
    const unsigned char *p = bitmap + static_cast<long>(sv >> 1) * W + (su >> 1);
    const unsigned char *q = bitmap + static_cast<long>((sv >> 1) + (sv & 1)) * W + (su >> 1) + (su & 1);
    long e = 0;
    for (int k = 0; k < nbOffsets;) {
      const int end = std::min(nbOffsets, k + 16);
      int partial = 0;
      for (; k < end; ++k) {
        const int diff = static_cast<int>(p[offsets[k]]) - static_cast<int>(q[-offsets[k]]);
        partial += diff * diff;
      }
      e += partial;
      if (e > bound) {
        return bound + 1;
      }
    }
    return e;
  };
  // The minimum over the search window, the first in row-major order on ties. The peak's own position
  // is the likeliest minimum: evaluated first, it lets most others be given up early.
  const long unbounded = std::numeric_limits<long>::max() - 1;
  long bestE = energy(cu, cv, unbounded);
  int bi = 0, bj = 0;
  for (int j = -reach; j <= reach; ++j) {
    for (int i = -reach; i <= reach; ++i) {
      if (i == 0 && j == 0) {
        continue;
      }
      const long e = energy(cu + i, cv + j, bestE);
      if (e < bestE || (e == bestE && (j < bj || (j == bj && i < bi)))) {
        bestE = e;
        bi = i;
        bj = j;
      }
    }
  }
  auto E = [&](int i, int j) { return static_cast<double>(energy(cu + i, cv + j, unbounded)); };
  double du = 0., dv = 0.;
  const double b = static_cast<double>(bestE);
  if (bi > -reach && bi < reach) {
    const double a = E(bi - 1, bj), c = E(bi + 1, bj);
    const double den = a - 2. * b + c;
    du = den > 0. ? std::max(-0.5, std::min(0.5, 0.5 * (a - c) / den)) : 0.;
  }
  if (bj > -reach && bj < reach) {
    const double a = E(bi, bj - 1), c = E(bi, bj + 1);
    const double den = a - 2. * b + c;
    dv = den > 0. ? std::max(-0.5, std::min(0.5, 0.5 * (a - c) / den)) : 0.;
  }
  u = 0.5 * (cu + bi + du);
  v = 0.5 * (cv + bj + dv);
  // Residual relative to the disc's own contrast: 0 for a perfectly symmetric pattern, about 1 for clutter.
  double sum = 0., sum2 = 0.;
  int n = 0;
  const int pu = (cu + bi) >> 1, pv = (cv + bj) >> 1;
  for (int dy = -radius; dy <= radius; ++dy) {
    for (int dx = -radius; dx <= radius; ++dx) {
      if (dx * dx + dy * dy <= radius * radius) {
        const double g = I[pv + dy][pu + dx];
        sum += g;
        sum2 += g * g;
        ++n;
      }
    }
  }
  const double variance = sum2 / n - (sum / n) * (sum / n);
  asymmetry = b / (0.5 * n * 2. * std::max(variance, 1.));
  return true;
}

bool vpSSLRadiusEstimator::estimate(const vpImage<unsigned char> &I, vpSSLLandmark &landmark)
{
  double u = landmark.u, v = landmark.v, scale = 0., asymmetry = 0.;
  m_rayImage = nullptr; // the image may have changed in place since the last call
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
  if (asymmetry > kMaxAsymmetry) {
    return false;
  }
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
  if (!readRays(I, u, v, m_maxRadius) || !selectRadii(ref, R, ok, scale) ||
      !refineCentre(I, landmark.u, landmark.v, scale, u, v, R, ok)) {
    return false;
  }
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
