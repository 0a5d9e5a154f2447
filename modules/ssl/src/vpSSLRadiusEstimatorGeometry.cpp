/*
  vpSSLRadiusEstimator, geometry: the symmetry centring of a candidate, the ring edges along a ray, the
  centre refinement from opposite edges and the ellipse fit (split from vpSSLRadiusEstimator.cpp).
*/
#include <visp3/ssl/vpSSLRadiusEstimator.h>

#include <algorithm>
#include <cmath>

#include "vpSSLRadiusEstimatorInternal.h"
#include "vpSSLSymmetryKernel.h"

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
  // The disc compared with its half-turn, and the search, are vpSSLSymmetryKernel's (SIMD, all the centres of the
  // window at once).
  const int radius = static_cast<int>(std::lround(kSymmetryRadius * m_pixelScale));
  if (m_symmetryRadius != radius) {
    vpSSLSymmetryKernel::halfDisc(radius, m_symmetryOffsets);
    m_symmetryRadius = radius;
  }
  return vpSSLSymmetryKernel::centre(I, radius, m_symmetryOffsets, kFlatVariance, m_symmetryPatch, u, v, asymmetry);
}
