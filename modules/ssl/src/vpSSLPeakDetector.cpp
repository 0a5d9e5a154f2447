#include <visp3/ssl/vpSSLPeakDetector.h>

#include <algorithm>
#include <cmath>

#include <visp3/core/vpException.h>

#include "vpSSLImageCheck.h"

#include "vpSSLPeakKernel.h"

vpSSLPeakDetector::vpSSLPeakDetector() : m_threshold(0), m_minDistance(4), m_maxPeaks(64) {}

void vpSSLPeakDetector::setMinDistance(unsigned int d)
{
  if (d < 1) {
    throw vpException(vpException::badValue, "vpSSLPeakDetector: min distance must be >= 1");
  }
  m_minDistance = d;
}

void vpSSLPeakDetector::setMaxPeaks(unsigned int n)
{
  if (n < 1) {
    throw vpException(vpException::badValue, "vpSSLPeakDetector: max peaks must be >= 1");
  }
  m_maxPeaks = n;
}

namespace {
// Vertex of the parabola through (-1, a), (0, b), (1, c); 0 when flat.
double parabolaOffset(double a, double b, double c)
{
  const double den = a - 2. * b + c;
  if (den >= 0.) {
    return 0.;
  }
  return std::max(-0.5, std::min(0.5, 0.5 * (a - c) / den));
}
} // namespace

void vpSSLPeakDetector::scanRegion(const vpImage<int> &M, int u0, int v0, int u1, int v1)
{
  const int W = static_cast<int>(M.getWidth()), H = static_cast<int>(M.getHeight());
  u0 = std::max(u0, 0);
  v0 = std::max(v0, 0);
  u1 = std::min(u1, W - 1);
  v1 = std::min(v1, H - 1);
  if (u1 < u0) {
    return;
  }
  m_columns.resize(static_cast<size_t>(u1 - u0 + 1));
  int *columns = m_columns.data();
  // The first and last columns of the map, whose neighbours outside it are not compared (one-pixel maps included).
  auto borderMax = [&](int v, int u) {
    const int m = M[v][u];
    if (m < m_threshold) {
      return false;
    }
    for (int dv = -1; dv <= 1; ++dv) {
      const int vv = v + dv;
      if (vv < 0 || vv >= H) {
        continue;
      }
      for (int du = -1; du <= 1; ++du) {
        const int uu = u + du;
        if ((du == 0 && dv == 0) || uu < 0 || uu >= W) {
          continue;
        }
        // Strict on the later neighbours, loose on the earlier ones: one pixel per plateau.
        const int n = M[vv][uu];
        const bool later = dv > 0 || (dv == 0 && du > 0);
        if (later ? n >= m : n > m) {
          return false;
        }
      }
    }
    return true;
  };
  const int inner0 = std::max(u0, 1), inner1 = std::min(u1, W - 2);
  for (int v = v0; v <= v1; ++v) {
    const int *row = M[v];
    int nb = 0;
    if (u0 == 0 && borderMax(v, 0)) {
      columns[nb++] = 0;
    }
    if (inner0 <= inner1) {
      nb += vpSSLPeakKernel::localMaxima(v > 0 ? M[v - 1] : nullptr, row, v + 1 < H ? M[v + 1] : nullptr, inner0,
                                         inner1, m_threshold, columns + nb);
    }
    if (u1 == W - 1 && W > 1 && borderMax(v, W - 1)) {
      columns[nb++] = W - 1;
    }
    for (int k = 0; k < nb; ++k) {
      const int u = columns[k];
      const int m = row[u];
      vpSSLPeak p;
      p.value = m;
      p.u = u;
      p.v = v;
      if (u > 0 && u < W - 1) {
        p.u += parabolaOffset(row[u - 1], m, row[u + 1]);
      }
      if (v > 0 && v < H - 1) {
        p.v += parabolaOffset(M[v - 1][u], m, M[v + 1][u]);
      }
      m_candidates.push_back(p);
    }
  }
}

void vpSSLPeakDetector::detect(const vpImage<int> &M, std::vector<vpSSLPeak> &peaks, const std::vector<vpRect> &rois)
{
  vpSSLImageCheck::kernel(M, "vpSSLPeakDetector::detect");
  peaks.clear();
  m_candidates.clear();
  if (rois.empty()) {
    scanRegion(M, 0, 0, static_cast<int>(M.getWidth()) - 1, static_cast<int>(M.getHeight()) - 1);
  } else {
    for (const vpRect &r : rois) {
      scanRegion(M, static_cast<int>(std::ceil(r.getLeft())), static_cast<int>(std::ceil(r.getTop())),
                 static_cast<int>(std::floor(r.getRight())), static_cast<int>(std::floor(r.getBottom())));
    }
  }
  std::sort(m_candidates.begin(), m_candidates.end(),
            [](const vpSSLPeak &a, const vpSSLPeak &b) { return a.value > b.value; });
  const double d = m_minDistance;
  for (const vpSSLPeak &c : m_candidates) {
    bool suppressed = false;
    for (const vpSSLPeak &k : peaks) {
      if (std::fabs(k.u - c.u) <= d && std::fabs(k.v - c.v) <= d) {
        suppressed = true;
        break;
      }
    }
    if (!suppressed) {
      peaks.push_back(c);
      if (peaks.size() >= m_maxPeaks) {
        break;
      }
    }
  }
}
