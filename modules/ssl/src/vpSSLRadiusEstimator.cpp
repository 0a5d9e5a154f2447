#include <visp3/ssl/vpSSLRadiusEstimator.h>

#include <algorithm>
#include <cmath>

#include <visp3/core/vpException.h>

namespace
{
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

// Largest relative distance of a ray's edge point from the fitted ellipse.
const double kMaxEllipseResidual = 0.08;

struct Ellipse
{
  double major = 0., minor = 0., theta = 0.;
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
    const double residual = std::fabs(R[d] * std::sqrt(q) - 1.);
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
  : m_minRadius(4.), m_maxRadius(300.), m_minDirections(6), m_p(0.5), m_step(0.5)
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
  for (int d = 0; d < 8; ++d) {
    std::vector<float> &P = m_profile[d];
    std::vector<double> &C = m_prefix[d];
    P.clear();
    C.assign(1, 0.);
    for (double rho = 0.;; rho += m_step) {
      const double x = u + rho * kCos[d], y = v + rho * kSin[d];
      if (rho > maxRadius || x < 0. || y < 0. || x > W || y > H) {
        break;
      }
      P.push_back(bilinear(I, x, y));
      if (P.size() > 1) {
        // Trapezoidal integral of the profile from 0 to rho.
        C.push_back(C.back() + 0.5 * m_step * (P[P.size() - 2] + P.back()));
      }
    }
  }
  return true;
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
  double contrast[64];
  int nb = 0;
  double previous = 0., outerEdge = radius, cmax = 0.;
  for (int k = 0; nb < 64; ++k) {
    const double innerEdge = outerEdge * q;
    if (outerEdge - innerEdge < kMinRingWidth || innerEdge < kMinRingRadius) {
      break;
    }
    const double mean = (integral(outerEdge) - integral(innerEdge)) / (outerEdge - innerEdge);
    if (k > 0) {
      contrast[nb] = ((k - 1) % 2 == 0) ? mean - previous : previous - mean;
      cmax = std::max(cmax, contrast[nb]);
      ++nb;
    }
    previous = mean;
    outerEdge = innerEdge;
  }
  nbPairsOut = 0;
  outerContrast = nb > 0 ? contrast[0] : 0.;
  // Pairs whose inner ring is wide enough (kClearRingWidth) to survive a real lens: these must all alternate.
  nbExpected = 0;
  for (double r = radius * q; nbExpected < nb && r * (1. - q) >= kClearRingWidth; r *= q) {
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
  return nbPairsOut >= 2 ? score : -1e30;
}

bool vpSSLRadiusEstimator::fitRay(int d, double &radius) const
{
  const double available = (m_profile[d].size() - 1) * m_step;
  const double rMax = std::min(m_maxRadius, available);
  if (rMax < m_minRadius) {
    return false;
  }
  double bestScore = -1e30, bestR = 0.;
  std::vector<double> grid;
  for (double r = m_minRadius; r <= rMax; r *= kGridRatio) {
    grid.push_back(r);
  }
  std::vector<double> scores(grid.size(), -1e30);
  size_t best = grid.size();
  for (size_t i = 0; i < grid.size(); ++i) {
    double outer;
    int nbPairs, nbExpected;
    const double s = rayScore(d, grid[i], outer, nbPairs, nbExpected);
    // Every clearly resolvable ring must alternate: a handful of alternations at a geometric spacing
    // happens in clutter, a full self-similar sequence does not.
    if (nbPairs < std::max(2, nbExpected - 1)) {
      continue;
    }
    // The outermost ring must stand out dark against the next one: this pins R against the p-similar
    // copies at R / p (white paper would pass for a missing black ring) and R * sqrt(p) (anti-phase).
    if (s < kMinPairContrast * nbPairs || outer < 0.6 * s / nbPairs) {
      continue;
    }
    scores[i] = s;
    if (s > bestScore) {
      bestScore = s;
      best = i;
    }
  }
  if (best == grid.size()) {
    return false;
  }
  bestR = grid[best];
  if (best > 0 && best + 1 < grid.size() && scores[best - 1] > -1e29 && scores[best + 1] > -1e29) {
    const double a = scores[best - 1], b = scores[best], c = scores[best + 1];
    const double den = a - 2. * b + c;
    if (den < 0.) {
      const double t = std::max(-1., std::min(1., 0.5 * (a - c) / den));
      bestR *= std::pow(kGridRatio, t);
    }
  }
  radius = bestR;
  return true;
}

bool vpSSLRadiusEstimator::ringEdge(int d, double expected, double halfWidth, double &position) const
{
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
  const long i1 = std::min(static_cast<long>(P.size()) - 2, static_cast<long>(std::ceil((expected + halfWidth) / m_step)));
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

bool vpSSLRadiusEstimator::estimate(const vpImage<unsigned char> &I, vpSSLLandmark &landmark)
{
  const double q = std::sqrt(m_p);
  double u = landmark.u, v = landmark.v;
  double R[8];
  bool ok[8];
  unsigned int nbOk = 0;
  // 1. Read the rings along each ray from the matching peak: which rays show the pattern, and how large.
  if (!readRays(I, u, v, m_maxRadius)) {
    return false;
  }
  for (int d = 0; d < 8; ++d) {
    ok[d] = fitRay(d, R[d]);
    nbOk += ok[d] ? 1 : 0;
  }
  if (nbOk < m_minDirections) {
    return false;
  }
  // Rays that disagree wildly with the others read a ring pattern that is not this landmark's.
  std::vector<double> valid;
  for (int d = 0; d < 8; ++d) {
    if (ok[d]) {
      valid.push_back(R[d]);
    }
  }
  std::nth_element(valid.begin(), valid.begin() + valid.size() / 2, valid.end());
  const double median = valid[valid.size() / 2];
  for (int d = 0; d < 8; ++d) {
    if (ok[d] && (R[d] < 0.6 * median || R[d] > 1.7 * median)) {
      ok[d] = false;
    }
  }
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
        if (ringWidth < 1.2 || !ringEdge(d, expected, 0.3 * ringWidth, edge[d][j])) {
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
    if (std::hypot(u - landmark.u, v - landmark.v) > std::max(2., 0.25 * median)) {
      return false;
    }
    for (int d = 0; d < 8; ++d) {
      R[d] -= du * kCos[d] + dv * kSin[d];
    }
    if (!readRays(I, u, v, m_maxRadius)) {
      return false;
    }
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
