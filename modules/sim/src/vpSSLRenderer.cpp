/*!
  \file vpSSLRenderer.cpp
  \brief Ray casting of a printed SSL target: exact pattern, box-filtered by supersampling.
*/
#include <visp3/ssl/vpSSLRenderer.h>

#include <cmath>
#include <limits>
#include <sstream>

#include <visp3/core/vpException.h>
#include <visp3/core/vpMeterPixelConversion.h>
#include <visp3/core/vpPixelMeterConversion.h>
#include <visp3/ssl/vpSSLPattern.h>

namespace {
// A ray whose direction has |dz| below this (in normalised units, |d| >= 1) is grazing the plane so
// closely that the hit point is farther than any target could be seen: treat it as parallel.
const double kParallelEps = 1e-12;

// Rings narrower than this fraction of the outer radius are left to vpSSLPattern's own evaluation.
const double kSmallestRing = 1e-8;

// Sub-pixel offset from the pixel centre: the n x n grid that tiles the pixel's unit square.
inline double subOffset(unsigned int i, unsigned int n)
{
  return (i + 0.5) / n - 0.5;
}
} // namespace

vpSSLRenderer::vpSSLRenderer(const vpCameraParameters &cam, unsigned int width, unsigned int height)
    : m_cam(cam), m_width(width), m_height(height), m_supersampling(4), m_target(), m_black(0.), m_white(1.),
      m_background(0.5)
{
  if (width == 0 || height == 0) {
    throw vpException(vpException::dimensionError, "vpSSLRenderer: image size %ux%u has no pixel", width, height);
  }
  setTarget(vpSSLTarget::ssl3a3());
  updateRayCache();
}

void vpSSLRenderer::setTarget(const vpSSLTarget &target)
{
  if (!(target.getSheetWidth() > 0. && target.getSheetHeight() > 0.)) {
    std::ostringstream os;
    os << "vpSSLRenderer: target \"" << target.getName() << "\" has a " << target.getSheetWidth() << " x "
       << target.getSheetHeight() << " m sheet; set its sheet size (vpSSLTarget::setSheet)";
    throw vpException(vpException::badValue, os.str());
  }
  std::vector<Disc> discs;
  for (const vpSSLTargetLandmark &l : target.getLandmarks()) {
    if (l.z != 0.) {
      std::ostringstream os;
      os << "vpSSLRenderer: landmark " << l.name << " of target \"" << target.getName() << "\" has z = " << l.z
         << " m; the renderer draws a flat sheet (z = 0)";
      throw vpException(vpException::badValue, os.str());
    }
    Disc d{l.x, l.y, l.radius, l.radius * l.radius, l.p, {}};
    // Eq. 1 on rho^2 / R^2: ring k (black for even k) is p^(k+1) < rho^2 / R^2 <= p^k. Comparing squared
    // radii to these bounds replaces two logarithms and a square root per sample.
    for (double b = d.radius2; b > d.radius2 * kSmallestRing * kSmallestRing; b *= l.p) {
      d.ringRadius2.push_back(b);
    }
    discs.push_back(d);
  }
  m_target = target;
  m_discs = discs;
}

void vpSSLRenderer::setSupersampling(unsigned int n)
{
  if (n < 1 || n > 64) {
    throw vpException(vpException::badValue, "vpSSLRenderer: supersampling %u not in [1, 64]", n);
  }
  if (n != m_supersampling) {
    m_supersampling = n;
    updateRayCache();
  }
}

void vpSSLRenderer::setReflectances(double black, double white, double background)
{
  for (double r : {black, white, background}) {
    if (!(r >= 0. && r <= 1.)) {
      std::ostringstream os;
      os << "vpSSLRenderer: reflectances must be in [0, 1], got black " << black << ", white " << white
         << ", background " << background;
      throw vpException(vpException::badValue, os.str());
    }
  }
  m_black = black;
  m_white = white;
  m_background = background;
}

void vpSSLRenderer::setBackgroundImage(const vpImage<unsigned char> &I)
{
  if (I.getSize() != 0 && (I.getWidth() != m_width || I.getHeight() != m_height)) {
    throw vpException(vpException::dimensionError, "vpSSLRenderer: background image is %ux%u, the renderer %ux%u",
                      I.getWidth(), I.getHeight(), m_width, m_height);
  }
  m_backgroundImage = I;
}

void vpSSLRenderer::normalisedRay(unsigned int u, unsigned int v, unsigned int i, unsigned int j, double &x,
                                  double &y) const
{
  const unsigned int n = m_supersampling;
  if (!m_rayCache.empty()) {
    size_t k = 2 * ((static_cast<size_t>(v) * n + j) * m_width * n + static_cast<size_t>(u) * n + i);
    x = m_rayCache[k];
    y = m_rayCache[k + 1];
    return;
  }
  // vpPixelMeterConversion::convertPoint of the perspective models, factored through the tables.
  const double xu = m_subX[u * n + i], yu = m_subY[v * n + j];
  const double f = 1. + m_kdu * (xu * xu + yu * yu);
  x = xu * f;
  y = yu * f;
}

void vpSSLRenderer::updateRayCache()
{
  const unsigned int n = m_supersampling;
  m_subX.resize(static_cast<size_t>(m_width) * n);
  m_subY.resize(static_cast<size_t>(m_height) * n);
  for (size_t c = 0; c < m_subX.size(); ++c) {
    m_subX[c] = (static_cast<double>(c / n) + subOffset(c % n, n) - m_cam.get_u0()) * m_cam.get_px_inverse();
  }
  for (size_t r = 0; r < m_subY.size(); ++r) {
    m_subY[r] = (static_cast<double>(r / n) + subOffset(r % n, n) - m_cam.get_v0()) * m_cam.get_py_inverse();
  }
  m_kdu = m_cam.get_projModel() == vpCameraParameters::perspectiveProjWithDistortion ? m_cam.get_kdu() : 0.;
  m_rayCache.clear();
  m_centralRayCache.clear();
  if (m_cam.get_projModel() != vpCameraParameters::ProjWithKannalaBrandtDistortion) {
    return;
  }
  // Kannala-Brandt pixel-to-meter conversion is an iterative inversion: do it once per camera and size.
  const size_t W = static_cast<size_t>(m_width) * n;
  const int H = static_cast<int>(m_height * n);
  std::vector<float> cache(2 * W * H);
#pragma omp parallel for schedule(static)
  for (int r = 0; r < H; ++r) {
    for (size_t c = 0; c < W; ++c) {
      double x = 0., y = 0.;
      vpPixelMeterConversion::convertPoint(m_cam, static_cast<double>(c / n) + subOffset(c % n, n),
                                           static_cast<double>(r / n) + subOffset(r % n, n), x, y);
      cache[2 * (r * W + c)] = static_cast<float>(x);
      cache[2 * (r * W + c) + 1] = static_cast<float>(y);
    }
  }
  std::vector<float> central(2 * static_cast<size_t>(m_width) * m_height);
  for (unsigned int v = 0; v < m_height; ++v) {
    for (unsigned int u = 0; u < m_width; ++u) {
      double x = 0., y = 0.;
      vpPixelMeterConversion::convertPoint(m_cam, u, v, x, y);
      central[2 * (static_cast<size_t>(v) * m_width + u)] = static_cast<float>(x);
      central[2 * (static_cast<size_t>(v) * m_width + u) + 1] = static_cast<float>(y);
    }
  }
  m_rayCache.swap(cache);
  m_centralRayCache.swap(central);
}

void vpSSLRenderer::renderCore(const vpHomogeneousMatrix &cMo, float *reflectance, float *range,
                               unsigned char *grey) const
{
  // Solve in the target frame: the plane is Z = 0 there, the camera centre is o and a ray through the
  // normalised point (x, y) has direction oRc (x, y, 1).
  const vpHomogeneousMatrix oMc = cMo.inverse();
  double R[3][3], o[3];
  for (unsigned int r = 0; r < 3; ++r) {
    for (unsigned int c = 0; c < 3; ++c) {
      R[r][c] = oMc[r][c];
    }
    o[r] = oMc[r][3];
  }
  // Z points into the sheet: a camera at o_z > 0 is behind it and sees the blank back of the paper.
  const bool frontSide = o[2] < 0.;
  const double halfW = 0.5 * m_target.getSheetWidth(), halfH = 0.5 * m_target.getSheetHeight();
  const double sheetX = m_target.getSheetCenterX(), sheetY = m_target.getSheetCenterY();
  const unsigned int n = m_supersampling;
  const double invSamples = 1. / (n * n);
  const bool hasBackgroundImage = m_backgroundImage.getSize() != 0;
  const Disc *discs = m_discs.data();
  const size_t nbDiscs = m_discs.size();

  // Ray parameter t of the hit with the sheet (t > 0, on the sheet), or a negative value on a miss.
  auto hit = [&](double x, double y, double &X, double &Y) -> double {
    const double dx = R[0][0] * x + R[0][1] * y + R[0][2];
    const double dy = R[1][0] * x + R[1][1] * y + R[1][2];
    const double dz = R[2][0] * x + R[2][1] * y + R[2][2];
    if (!(std::fabs(dz) > kParallelEps)) {
      return -1.;
    }
    const double t = -o[2] / dz;
    if (!(t > 0.)) {
      return -1.;
    }
    X = o[0] + t * dx;
    Y = o[1] + t * dy;
    if (!(std::fabs(X - sheetX) <= halfW && std::fabs(Y - sheetY) <= halfH)) {
      return -1.;
    }
    return t;
  };

  const int height = static_cast<int>(m_height);
#pragma omp parallel for schedule(dynamic, 4)
  for (int v = 0; v < height; ++v) {
    for (unsigned int u = 0; u < m_width; ++u) {
      const double background = hasBackgroundImage ? m_backgroundImage[v][u] / 255. : m_background;
      double sum = 0.;
      for (unsigned int j = 0; j < n; ++j) {
        for (unsigned int i = 0; i < n; ++i) {
          double x = 0., y = 0., X = 0., Y = 0.;
          normalisedRay(u, static_cast<unsigned int>(v), i, j, x, y);
          if (hit(x, y, X, Y) < 0.) {
            sum += background;
            continue;
          }
          double value = m_white;
          if (frontSide) {
            for (size_t k = 0; k < nbDiscs; ++k) {
              const double ddx = X - discs[k].x, ddy = Y - discs[k].y;
              const double r2 = ddx * ddx + ddy * ddy;
              if (r2 <= discs[k].radius2) {
                const std::vector<double> &bound = discs[k].ringRadius2;
                size_t ring = 0;
                while (ring + 1 < bound.size() && r2 <= bound[ring + 1]) {
                  ++ring;
                }
                int s = static_cast<int>(ring % 2);
                if (ring + 1 == bound.size()) {
                  s = vpSSLPattern::circular(ddx, ddy, discs[k].radius, discs[k].p);
                }
                value = s == 0 ? m_black : m_white;
                break;
              }
            }
          }
          sum += value;
        }
      }
      const double mean = sum * invSamples;
      const size_t idx = static_cast<size_t>(v) * m_width + u;
      if (reflectance) {
        reflectance[idx] = static_cast<float>(mean);
      }
      if (grey) {
        const double g = std::round(255. * mean);
        grey[idx] = static_cast<unsigned char>(g < 0. ? 0. : (g > 255. ? 255. : g));
      }
      if (range) {
        double x = 0., y = 0., X = 0., Y = 0.;
        if (!m_centralRayCache.empty()) {
          x = m_centralRayCache[2 * idx];
          y = m_centralRayCache[2 * idx + 1];
        } else {
          vpPixelMeterConversion::convertPoint(m_cam, u, v, x, y);
        }
        const double t = hit(x, y, X, Y);
        // |oRc (x, y, 1)| = sqrt(x^2 + y^2 + 1): t scaled to metres along the ray.
        range[idx] =
            t < 0. ? std::numeric_limits<float>::infinity() : static_cast<float>(t * std::sqrt(x * x + y * y + 1.));
      }
    }
  }
}

void vpSSLRenderer::render(const vpHomogeneousMatrix &cMo, vpImage<unsigned char> &I) const
{
  I.resize(m_height, m_width);
  renderCore(cMo, nullptr, nullptr, I.bitmap);
}

void vpSSLRenderer::render(const vpHomogeneousMatrix &cMo, vpImage<float> &reflectance, vpImage<float> &range) const
{
  reflectance.resize(m_height, m_width);
  range.resize(m_height, m_width);
  renderCore(cMo, reflectance.bitmap, range.bitmap, nullptr);
}

std::vector<vpImagePoint> vpSSLRenderer::projectLandmarks(const vpHomogeneousMatrix &cMo) const
{
  std::vector<vpImagePoint> points;
  points.reserve(m_target.size());
  for (const vpSSLTargetLandmark &l : m_target.getLandmarks()) {
    const double X = cMo[0][0] * l.x + cMo[0][1] * l.y + cMo[0][2] * l.z + cMo[0][3];
    const double Y = cMo[1][0] * l.x + cMo[1][1] * l.y + cMo[1][2] * l.z + cMo[1][3];
    const double Z = cMo[2][0] * l.x + cMo[2][1] * l.y + cMo[2][2] * l.z + cMo[2][3];
    if (!(Z > 0.)) {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      points.emplace_back(nan, nan);
      continue;
    }
    double u, v;
    vpMeterPixelConversion::convertPoint(m_cam, X / Z, Y / Z, u, v);
    points.emplace_back(v, u);
  }
  return points;
}
