/*
  vpSSLRadiusEstimator, geometry: the symmetry centring of a candidate, the ring edges along a ray, the
  centre refinement from opposite edges and the ellipse fit (split from vpSSLRadiusEstimator.cpp).
*/
#include <visp3/ssl/vpSSLRadiusEstimator.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "vpSSLMatchingKernel.h"
#include "vpSSLRadiusEstimatorInternal.h"

using namespace vpSSLRadiusEstimatorInternal;

namespace {
// Radius (px) of the disc compared with its half-turn to centre a candidate: the innermost rings, which
// every landmark has whatever its size.
const double kSymmetryRadius = 8.;
// Variance (grey levels^2) below which the disc is too flat for its symmetry to mean anything: a 15 grey
// level standard deviation, above the sensor noise of any usable image.
const double kFlatVariance = 225.;
} // namespace

bool vpSSLRadiusEstimatorInternal::fitEllipse(const double R[8], const bool ok[8], Ellipse &e)
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

bool vpSSLRadiusEstimator::ringEdge(int d, double expected, double halfWidth, double &position)
{
  const double q = std::sqrt(m_p);
  ray(d, expected / q + halfWidth + m_step);
  const std::vector<float> &P = m_profile[d];
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
  // Variance of the disc about pixel (pu, pv); n receives its number of pixels.
  auto discVariance = [&](int pu, int pv, double &sumOut, int &n) {
    double sum = 0., sum2 = 0.;
    n = 0;
    for (int dy = -radius; dy <= radius; ++dy) {
      const unsigned char *row = I[pv + dy];
      for (int dx = -radius; dx <= radius; ++dx) {
        if (dx * dx + dy * dy <= radius * radius) {
          const double g = row[pu + dx];
          sum += g;
          sum2 += g * g;
          ++n;
        }
      }
    }
    sumOut = sum;
    return sum2 / n - (sum / n) * (sum / n);
  };
  // Pixels p and q with p + q = 2 c, c = (su, sv) / 2: p = (su >> 1, sv >> 1) + (dx, dy) and
  // q = (su - p.u, sv - p.v). Half the disc (dy > 0, or dy = 0 and dx > 0) pairs every pixel once: row dy
  // of it spans dx in [m_symmetryOffsets[dy], rx], rx = m_symmetryOffsets[radius + 1 + dy].
  if (m_symmetryRadius != radius) {
    m_symmetryOffsets.assign(2 * (radius + 1), 0);
    for (int dy = 0; dy <= radius; ++dy) {
      int rx = 0;
      while ((rx + 1) * (rx + 1) + dy * dy <= radius * radius) {
        ++rx;
      }
      m_symmetryOffsets[dy] = dy == 0 ? 1 : -rx;
      m_symmetryOffsets[radius + 1 + dy] = rx;
    }
    m_symmetryRadius = radius;
  }
  const int *rowFirst = m_symmetryOffsets.data(), *rowLast = rowFirst + radius + 1;
  // Both halves are copied: p = (su >> 1, sv >> 1) + (dx, dy) as is, q - (dx, dy) turned by half a turn (it runs
  // backwards through the image), so that every row of the half disc is two contiguous byte runs compared in SIMD
  // (vpSSLMatchingKernel::squaredDifferenceRows()). The copies cover every centre of the search window: p in
  // [pu0, pu1] x [pv0, pv1] (p = floor(s / 2)), q in [qu0, qu1] x [qv0, qv1] (q = ceil(s / 2)); their rows are
  // padded for the vector loads past a row's end.
  const int pu0 = (cu - reach) >> 1, pv0 = (cv - reach) >> 1, pu1 = (cu + reach) >> 1, pv1 = (cv + reach) >> 1;
  const int qu0 = (cu - reach + 1) >> 1, qv0 = (cv - reach + 1) >> 1;
  const int qu1 = (cu + reach + 1) >> 1, qv1 = (cv + reach + 1) >> 1;
  const int kPad = 64;
  const int pw = std::max(pu1 - pu0, qu1 - qu0) + 1 + 2 * radius + kPad;
  const int phP = pv1 - pv0 + 1 + radius, phQ = qv1 - qv0 + 1 + radius;
  m_symmetryPatch.resize(static_cast<size_t>(pw) * (phP + phQ + 1));
  unsigned char *patchP = m_symmetryPatch.data(), *patchQ = patchP + static_cast<size_t>(pw) * phP;
  // patchP(y, x) = I(pv0 + y, pu0 - radius + x); patchQ(y, x) = I(qv1 - y, qu1 + radius - x), so that
  // I(q.v - dy, q.u - dx) is patchQ(qv1 - q.v + dy, qu1 + radius - q.u + dx).
  for (int y = 0; y < phP; ++y) {
    const unsigned char *src = I[pv0 + y] + pu0 - radius;
    std::copy(src, src + pu1 - pu0 + 1 + 2 * radius, patchP + static_cast<size_t>(y) * pw);
  }
  for (int y = 0; y < phQ; ++y) {
    const unsigned char *src = I[qv1 - y] + qu1 + radius;
    unsigned char *dst = patchQ + static_cast<size_t>(y) * pw;
    for (int x = 0; x <= qu1 - qu0 + 2 * radius; ++x) {
      dst[x] = src[-x];
    }
  }
  // Sum of squared differences (exact in integers) about the centre (su, sv) / 2, given up as soon as it
  // exceeds \e bound (returns bound + 1 then): only the minimum and its neighbours are needed. Where it is
  // given up does not matter: a value above the bound is never the minimum.
  auto energy = [&](int su, int sv, long bound) {
    const int pu = su >> 1, pv = sv >> 1, qu = (su >> 1) + (su & 1), qv = (sv >> 1) + (sv & 1);
    const unsigned char *p = patchP + static_cast<long>(pv - pv0) * pw + (pu - pu0 + radius);
    const unsigned char *q = patchQ + static_cast<long>(qv1 - qv) * pw + (qu1 + radius - qu);
    return vpSSLMatchingKernel::squaredDifferenceRows(p, pw, q, pw, rowFirst, rowLast, radius + 1, bound);
  };
  // The minimum over the search window, the first in row-major order on ties, whatever the order of evaluation.
  // The peak's own position is the likeliest minimum, and its neighbours the next likeliest: evaluated first
  // (nearest first), they let most others be given up early.
  if (m_symmetryOrder.empty()) {
    for (int j = -reach; j <= reach; ++j) {
      for (int i = -reach; i <= reach; ++i) {
        if (i != 0 || j != 0) {
          m_symmetryOrder.push_back((j + reach) * (2 * reach + 1) + (i + reach));
        }
      }
    }
    // Nearest first, row-major among equals (std::sort with a total order: std::stable_sort would take a buffer).
    std::sort(m_symmetryOrder.begin(), m_symmetryOrder.end(), [&](int a, int b) {
      const int ai = a % (2 * reach + 1) - reach, aj = a / (2 * reach + 1) - reach;
      const int bi = b % (2 * reach + 1) - reach, bj = b / (2 * reach + 1) - reach;
      const int da = ai * ai + aj * aj, db = bi * bi + bj * bj;
      return da < db || (da == db && a < b);
    });
  }
  const long unbounded = std::numeric_limits<long>::max() - 1;
  long bestE = energy(cu, cv, unbounded);
  int bi = 0, bj = 0;
  for (const int k : m_symmetryOrder) {
    const int i = k % (2 * reach + 1) - reach, j = k / (2 * reach + 1) - reach;
    const long e = energy(cu + i, cv + j, bestE);
    if (e < bestE || (e == bestE && (j < bj || (j == bj && i < bi)))) {
      bestE = e;
      bi = i;
      bj = j;
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
  double sum = 0.;
  int n = 0;
  const double variance = discVariance((cu + bi) >> 1, (cv + bj) >> 1, sum, n);
  // A nearly flat disc (the innermost rings of a large landmark blurred by water and lens into a grey
  // spot) says nothing either way: its residual is sensor noise. Only a contrasted disc is judged.
  asymmetry = variance < kFlatVariance ? 0. : b / (0.5 * n * 2. * variance);
  return true;
}
