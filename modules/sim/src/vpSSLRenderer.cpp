/*!
  \file vpSSLRenderer.cpp
  \brief Ray casting of a printed SSL target: exact pattern, box-filtered by supersampling.
*/
#include <visp3/ssl_sim/vpSSLRenderer.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <visp3/core/vpException.h>
#include <visp3/core/vpMeterPixelConversion.h>
#include <visp3/core/vpPixelMeterConversion.h>
#include <visp3/ssl/vpSSLPattern.h>

#include "vpSSLQuantise.h"
#include "vpSSLSurfaceKernel.h"

namespace {
// A ray whose direction has |dz| below this (in normalised units, |d| >= 1) is grazing the plane so
// closely that the hit point is farther than any target could be seen: treat it as parallel.
const double kParallelEps = 1e-12;

// Rings narrower than this fraction of the outer radius are left to vpSSLPattern's own evaluation.
const double kSmallestRing = 1e-8;

// Refractive index of sea water: water-to-air rays beyond asin(1 / 1.333) = 48.6 degrees from the normal are
// totally reflected.
const double kWaterIndex = 1.333;

// The sky seen from below through Snell's window, as a reflectance: as bright as white paper under the
// same light (it is brighter still in reality, but would only saturate the 8-bit image).
const double kSkyRadiance = 1.;

// Unpolarised Fresnel reflectance of the water-to-air interface for a ray at cos(incidence) = cosI.
double fresnelWaterToAir(double cosI)
{
  const double sinT2 = kWaterIndex * kWaterIndex * (1. - cosI * cosI);
  if (sinT2 >= 1.) {
    return 1.;
  }
  const double cosT = std::sqrt(1. - sinT2);
  const double rs = (kWaterIndex * cosI - cosT) / (kWaterIndex * cosI + cosT);
  const double rp = (cosI - kWaterIndex * cosT) / (cosI + kWaterIndex * cosT);
  return 0.5 * (rs * rs + rp * rp);
}

// Index i of an endless texture of n texels repeated by mirroring (..., 1, 0, 0, 1, ..., n-1, n-1, ...).
int mirrorIndex(long i, int n)
{
  if (i >= 0 && i < n) {
    return static_cast<int>(i);
  }
  if (i >= n && i < 2L * n) {
    return static_cast<int>(2L * n - 1 - i);
  }
  if (i < 0 && i >= -n) {
    return static_cast<int>(-1 - i);
  }
  long m = i % (2L * n);
  if (m < 0) {
    m += 2L * n;
  }
  return static_cast<int>(m < n ? m : 2L * n - 1 - m);
}

// Whether num / den can be > 0, for a den that is neither 0 nor NaN: only when both have the same strict sign (the
// quotient of those may still underflow to 0, which the caller's own test on it rejects). Zeros, NaN and opposite
// signs give a quotient that is <= 0 or NaN: the division, the slowest operation of a ray, is then left out.
inline bool maybePositiveQuotient(double num, double den)
{
  return (num > 0. && den > 0.) || (num < 0. && den < 0.);
}

// Margin of the open-water test of renderCore() (normalised image units, and surface-normal cosines): some 1e-4 px,
// and still some 1e10 times the rounding of the quantities it bounds.
const double kOpenWaterMargin = 1e-6;

// Sub-pixel offset from the pixel centre: the n x n grid that tiles the pixel's unit square.
inline double subOffset(unsigned int i, unsigned int n)
{
  return (i + 0.5) / n - 0.5;
}
} // namespace

vpSSLRenderer::vpSSLRenderer(const vpCameraParameters &cam, unsigned int width, unsigned int height)
    : m_cam(cam), m_width(width), m_height(height), m_supersampling(4), m_target(), m_black(0.), m_white(1.),
      m_background(0.5), m_aprilTag(false), m_tagSheet(), m_backdrop(), m_texelSize(0.01), m_oMb(), m_hasSurface(false),
      m_surface(), m_maxRange(std::numeric_limits<double>::infinity()), m_fovMinX(0.), m_fovMaxX(0.), m_fovMinY(0.),
      m_fovMaxY(0.)
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
  m_aprilTag = false;
}

void vpSSLRenderer::setAprilTagSheet(const vpSSLAprilTagSheet &sheet)
{
  m_tagSheet = sheet;
  m_aprilTag = true;
}

void vpSSLRenderer::setBackdrop(const vpImage<unsigned char> &texture, double texelSize)
{
  if (!(texelSize > 0. && std::isfinite(texelSize))) {
    throw vpException(vpException::badValue, "vpSSLRenderer: backdrop texel size %g m must be > 0", texelSize);
  }
  m_backdrop.clear();
  m_texelSize = texelSize;
  if (texture.getSize() == 0) {
    return;
  }
  m_backdrop.push_back(texture);
  while (m_backdrop.back().getWidth() > 1 || m_backdrop.back().getHeight() > 1) {
    const vpImage<unsigned char> &fine = m_backdrop.back();
    const unsigned int w = fine.getWidth(), h = fine.getHeight();
    vpImage<unsigned char> coarse((h + 1) / 2, (w + 1) / 2);
    for (unsigned int v = 0; v < coarse.getHeight(); ++v) {
      for (unsigned int u = 0; u < coarse.getWidth(); ++u) {
        const unsigned int u1 = std::min(2 * u + 1, w - 1), v1 = std::min(2 * v + 1, h - 1);
        coarse[v][u] =
            static_cast<unsigned char>((fine[2 * v][2 * u] + fine[2 * v][u1] + fine[v1][2 * u] + fine[v1][u1] + 2) / 4);
      }
    }
    m_backdrop.push_back(coarse);
  }
}

void vpSSLRenderer::setBackdropPose(const vpHomogeneousMatrix &oMb)
{
  m_oMb = oMb;
}

void vpSSLRenderer::setWaterSurface(const vpPlane &surface)
{
  const double A = surface.getA(), B = surface.getB(), C = surface.getC();
  if (!(A * A + B * B + C * C > 0.) || !std::isfinite(A + B + C + surface.getD())) {
    throw vpException(vpException::badValue, "vpSSLRenderer: water surface plane (%g, %g, %g, %g) has no normal", A, B,
                      C, surface.getD());
  }
  m_surface = surface;
  m_hasSurface = true;
}

void vpSSLRenderer::clearWaterSurface()
{
  m_hasSurface = false;
}

void vpSSLRenderer::setMaxRange(double range)
{
  if (!(range > 0.)) {
    throw vpException(vpException::badValue, "vpSSLRenderer: maximum range %g m must be > 0", range);
  }
  m_maxRange = range;
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
  m_fovMinX = m_fovMinY = std::numeric_limits<double>::infinity();
  m_fovMaxX = m_fovMaxY = -std::numeric_limits<double>::infinity();
  auto extend = [this](double u, double v) {
    double x = 0., y = 0.;
    vpPixelMeterConversion::convertPoint(m_cam, u, v, x, y);
    m_fovMinX = std::min(m_fovMinX, x);
    m_fovMaxX = std::max(m_fovMaxX, x);
    m_fovMinY = std::min(m_fovMinY, y);
    m_fovMaxY = std::max(m_fovMaxY, y);
  };
  const double right = m_width - 0.5, bottom = m_height - 0.5;
  for (unsigned int u = 0; u <= m_width; ++u) {
    extend(u - 0.5, -0.5);
    extend(u - 0.5, bottom);
  }
  for (unsigned int v = 0; v <= m_height; ++v) {
    extend(-0.5, v - 0.5);
    extend(right, v - 0.5);
  }
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

struct vpSSLRenderer::Scene
{
  // Everything in the sheet frame, where the sheet is the rectangle of the plane Z = 0.
  double R[3][3]; // camera orientation: a ray through the normalised point (x, y) has direction R (x, y, 1)
  double o[3];    // camera centre
  double halfW, halfH, sheetX, sheetY;
  bool backdrop;
  double bo[3], be1[3], be2[3], bn[3]; // backdrop origin, texture axes and normal
  double subPixelAngle;                // angle between neighbour sub-pixel rays (rad), for the texture's footprint
  bool surface;
  double sn[3], sd; // water surface: points X with sn . X = sd; sn is the unit normal towards the air
};

vpHomogeneousMatrix vpSSLRenderer::sheetPose() const
{
  // getSheetToTag() is its own inverse: the pose of the sheet frame in the tag frame too.
  return m_aprilTag ? vpSSLAprilTagSheet::getSheetToTag() : vpHomogeneousMatrix();
}

vpSSLRenderer::Scene vpSSLRenderer::makeScene(const vpHomogeneousMatrix &cMo) const
{
  Scene s;
  const vpHomogeneousMatrix oMs = sheetPose();
  const vpHomogeneousMatrix sMc = (cMo * oMs).inverse();
  for (unsigned int r = 0; r < 3; ++r) {
    for (unsigned int c = 0; c < 3; ++c) {
      s.R[r][c] = sMc[r][c];
    }
    s.o[r] = sMc[r][3];
  }
  if (m_aprilTag) {
    s.halfW = 0.5 * m_tagSheet.getSheetWidth();
    s.halfH = 0.5 * m_tagSheet.getSheetHeight();
    s.sheetX = s.sheetY = 0.;
  } else {
    s.halfW = 0.5 * m_target.getSheetWidth();
    s.halfH = 0.5 * m_target.getSheetHeight();
    s.sheetX = m_target.getSheetCenterX();
    s.sheetY = m_target.getSheetCenterY();
  }
  s.backdrop = !m_backdrop.empty();
  s.subPixelAngle = 1. / (m_supersampling * std::min(m_cam.get_px(), m_cam.get_py()));
  const vpHomogeneousMatrix sMb = oMs.inverse() * m_oMb;
  for (unsigned int r = 0; r < 3; ++r) {
    s.bo[r] = sMb[r][3];
    s.be1[r] = sMb[r][0];
    s.be2[r] = sMb[r][1];
    s.bn[r] = sMb[r][2];
  }
  s.surface = m_hasSurface;
  if (m_hasSurface) {
    // A X_o + D = 0 with X_o = oRs X_s + ots: (oRs^T A) X_s + (A . ots + D) = 0.
    const double A[3] = {m_surface.getA(), m_surface.getB(), m_surface.getC()};
    const double norm = std::sqrt(A[0] * A[0] + A[1] * A[1] + A[2] * A[2]);
    double Ds = m_surface.getD();
    for (unsigned int c = 0; c < 3; ++c) {
      s.sn[c] = (oMs[0][c] * A[0] + oMs[1][c] * A[1] + oMs[2][c] * A[2]) / norm;
      Ds += A[c] * oMs[c][3];
    }
    s.sd = -Ds / norm;
  } else {
    s.sn[0] = s.sn[1] = s.sn[2] = s.sd = 0.;
  }
  return s;
}

double vpSSLRenderer::sheetValue(double X, double Y) const
{
  if (m_aprilTag) {
    const double cell = m_tagSheet.getCellSize();
    const double col = std::floor(X / cell + 4.), row = std::floor(Y / cell + 4.);
    if (col >= 0. && col < 8. && row >= 0. && row < 8.) {
      return m_tagSheet.getCells()[static_cast<size_t>(row) * 8 + static_cast<size_t>(col)] ? m_black : m_white;
    }
    return m_white;
  }
  for (const Disc &disc : m_discs) {
    const double ddx = X - disc.x, ddy = Y - disc.y;
    const double r2 = ddx * ddx + ddy * ddy;
    if (r2 <= disc.radius2) {
      const std::vector<double> &bound = disc.ringRadius2;
      size_t ring = 0;
      while (ring + 1 < bound.size() && r2 <= bound[ring + 1]) {
        ++ring;
      }
      int s = static_cast<int>(ring % 2);
      if (ring + 1 == bound.size()) {
        s = vpSSLPattern::circular(ddx, ddy, disc.radius, disc.p);
      }
      return s == 0 ? m_black : m_white;
    }
  }
  return m_white;
}

double vpSSLRenderer::backdropValue(double a, double b, double footprint) const
{
  // Bilinear sampling of the pyramid level whose texels are about the sub-pixel's footprint (floor of its
  // log2): the pixel's n x n samples then average a texture already smoothed to their spacing.
  const size_t level = footprint >= 2. * m_texelSize
                           ? std::min(static_cast<size_t>(std::ilogb(footprint / m_texelSize)), m_backdrop.size() - 1)
                           : 0;
  const vpImage<unsigned char> &T = m_backdrop[level];
  const int w = static_cast<int>(T.getWidth()), h = static_cast<int>(T.getHeight());
  // Level k's texels are 2^k level-0 texels (up to the rounding of odd sizes, invisible on a backdrop).
  const double perTexel = std::ldexp(1. / m_texelSize, -static_cast<int>(level));
  const double tu = a * perTexel + 0.5 * (w - 1), tv = b * perTexel + 0.5 * (h - 1);
  const double fu = std::floor(tu), fv = std::floor(tv);
  const int u0 = mirrorIndex(static_cast<long>(fu), w), u1 = mirrorIndex(static_cast<long>(fu) + 1, w);
  const int v0 = mirrorIndex(static_cast<long>(fv), h), v1 = mirrorIndex(static_cast<long>(fv) + 1, h);
  const double au = tu - fu, av = tv - fv;
  const double upper = (1. - au) * T[v0][u0] + au * T[v0][u1];
  const double lower = (1. - au) * T[v1][u0] + au * T[v1][u1];
  return ((1. - av) * upper + av * lower) / 255.;
}

double vpSSLRenderer::shade(const Scene &s, const double p[3], const double d[3], double background, bool surface,
                            double path0, double &t) const
{
  enum
  {
    MISS,
    SHEET,
    BACKDROP,
    SURFACE
  } what = MISS;
  double best = std::numeric_limits<double>::infinity();
  double X = 0., Y = 0., a = 0., b = 0., footprint = 0.;
  if (std::fabs(d[2]) > kParallelEps && maybePositiveQuotient(-p[2], d[2])) {
    const double ts = -p[2] / d[2];
    const double Xs = p[0] + ts * d[0], Ys = p[1] + ts * d[1];
    if (ts > 0. && std::fabs(Xs - s.sheetX) <= s.halfW && std::fabs(Ys - s.sheetY) <= s.halfH) {
      what = SHEET;
      best = ts;
      X = Xs;
      Y = Ys;
    }
  }
  if (s.backdrop) {
    const double den = s.bn[0] * d[0] + s.bn[1] * d[1] + s.bn[2] * d[2];
    const double num = s.bn[0] * (s.bo[0] - p[0]) + s.bn[1] * (s.bo[1] - p[1]) + s.bn[2] * (s.bo[2] - p[2]);
    if (std::fabs(den) > kParallelEps && maybePositiveQuotient(num, den)) {
      const double tb = num / den;
      if (tb > 0. && tb < best) {
        what = BACKDROP;
        best = tb;
        const double H[3] = {p[0] + tb * d[0] - s.bo[0], p[1] + tb * d[1] - s.bo[1], p[2] + tb * d[2] - s.bo[2]};
        a = s.be1[0] * H[0] + s.be1[1] * H[1] + s.be1[2] * H[2];
        b = s.be2[0] * H[0] + s.be2[1] * H[1] + s.be2[2] * H[2];
        // Width on the backdrop of the cone between neighbour sub-pixel rays: distance / cos(incidence).
        const double d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        footprint = (path0 + tb) * d2 * s.subPixelAngle / std::fabs(den);
      }
    }
  }
  double dn = 0.;
  if (surface && s.surface) {
    dn = s.sn[0] * d[0] + s.sn[1] * d[1] + s.sn[2] * d[2];
    const double num = s.sd - (s.sn[0] * p[0] + s.sn[1] * p[1] + s.sn[2] * p[2]);
    if (dn > kParallelEps && num > 0.) {
      const double tw = num / dn;
      if (tw > 0. && tw < best) {
        what = SURFACE;
        best = tw;
      }
    }
  }
  // Beyond the maximum range (path lengths in metres: t |d|), a miss.
  if (what != MISS &&
      (path0 + best) * (path0 + best) * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) > m_maxRange * m_maxRange) {
    what = MISS;
    best = std::numeric_limits<double>::infinity();
  }
  t = best;
  switch (what) {
  case SHEET:
    // Z points into the sheet: a ray from Z > 0 comes from behind and sees the blank back of the paper.
    return p[2] < 0. ? sheetValue(X, Y) : m_white;
  case BACKDROP:
    return backdropValue(a, b, footprint);
  case SURFACE: {
    const double q[3] = {p[0] + best * d[0], p[1] + best * d[1], p[2] + best * d[2]};
    const double r[3] = {d[0] - 2. * dn * s.sn[0], d[1] - 2. * dn * s.sn[1], d[2] - 2. * dn * s.sn[2]};
    const double reflectance = fresnelWaterToAir(dn / std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    double t2 = 0.;
    const double reflected = shade(s, q, r, background, false, path0 + best, t2);
    // The reflected path dominates what the pixel sees unless the sky does (inside Snell's window).
    t = reflectance >= 0.5 ? best + t2 : best;
    return reflectance * reflected + (1. - reflectance) * kSkyRadiance;
  }
  case MISS:
  default:
    return background;
  }
}

// Which pixels' rays can meet what, from the camera's centre (renderCore()'s rays without distortion): the sheet
// only if the ray's normalised point (x, y) lies in the sheet's projection, the convex quadrilateral of its corners'
// projections when all four are in front of the camera (nowhere when all four are behind it); the sheet after a
// reflection on the water surface only if (x, y) lies in the projection of the sheet's mirror image (the reflected ray
// is the mirror image of the ray's continuation); the surface only if sn . R (x, y, 1) > 0. Each test is a box or an
// affine bound, widened by far more than the rounding of the quantities shade() computes, so that a pixel said to miss
// does miss on every ray.
struct vpSSLRenderer::OpenWater
{
  bool enabled = false;               // the sheet's corners are all in front of the camera, or all behind it
  std::vector<unsigned char> colOff;  // per column and row: the pixel's rays all miss the sheet's box
  std::vector<unsigned char> rowOff;  //
  bool mirror = false;                // the same for the mirror image's corners
  std::vector<unsigned char> colOffM; // the same for the mirror image's box
  std::vector<unsigned char> rowOffM; //
  std::vector<double> colUp, rowUp;   // the largest column and row terms of sn . R (x, y, 1) over the pixel's rays
  double up = -1.;                    // its constant term (-1 without a surface seen from below)
  double num = 0.;                    // sd - sn . o, shade()'s numerator of the surface hit for these rays
};

namespace {
// Box [xMin, xMax] x [yMin, yMax] of the normalised projections of four points (sheet frame) seen from the camera at
// o with orientation R (rows: sheet axes), widened by the margin; an empty box when all four are behind the camera
// (the rays, whose points are all in front of it, meet nothing of their convex hull); false when some are in front
// and some not (or on the camera's plane).
bool projectedBox(const double R[3][3], const double o[3], const double P[4][3], double box[4])
{
  box[0] = box[2] = std::numeric_limits<double>::infinity();
  box[1] = box[3] = -box[0];
  int front = 0, behind = 0;
  for (int i = 0; i < 4; ++i) {
    double c[3];
    for (int k = 0; k < 3; ++k) {
      c[k] = R[0][k] * (P[i][0] - o[0]) + R[1][k] * (P[i][1] - o[1]) + R[2][k] * (P[i][2] - o[2]);
    }
    if (c[2] < -kOpenWaterMargin) {
      ++behind;
      continue;
    }
    if (!(c[2] > kOpenWaterMargin)) {
      return false;
    }
    ++front;
    box[0] = std::min(box[0], c[0] / c[2]);
    box[1] = std::max(box[1], c[0] / c[2]);
    box[2] = std::min(box[2], c[1] / c[2]);
    box[3] = std::max(box[3], c[1] / c[2]);
  }
  if (behind == 4) {
    return true;
  }
  if (front != 4) {
    return false;
  }
  box[0] -= kOpenWaterMargin;
  box[1] += kOpenWaterMargin;
  box[2] -= kOpenWaterMargin;
  box[3] += kOpenWaterMargin;
  return true;
}
} // namespace

void vpSSLRenderer::openWater(const Scene &s, OpenWater &open) const
{
  const unsigned int n = m_supersampling;
  double P[4][3], box[4];
  for (int i = 0; i < 4; ++i) {
    P[i][0] = s.sheetX + (i & 1 ? s.halfW : -s.halfW);
    P[i][1] = s.sheetY + (i & 2 ? s.halfH : -s.halfH);
    P[i][2] = 0.;
  }
  open.enabled = projectedBox(s.R, s.o, P, box);
  if (!open.enabled) {
    return;
  }
  // A pixel's rays span its first to its last sub-pixel column and row (m_subX and m_subY increase).
  auto offMasks = [&](const double bx[4], std::vector<unsigned char> &col, std::vector<unsigned char> &row) {
    col.resize(m_width);
    row.resize(m_height);
    for (unsigned int u = 0; u < m_width; ++u) {
      col[u] = m_subX[static_cast<size_t>(u) * n + n - 1] < bx[0] || m_subX[static_cast<size_t>(u) * n] > bx[1];
    }
    for (unsigned int v = 0; v < m_height; ++v) {
      row[v] = m_subY[static_cast<size_t>(v) * n + n - 1] < bx[2] || m_subY[static_cast<size_t>(v) * n] > bx[3];
    }
  };
  offMasks(box, open.colOff, open.rowOff);
  open.num = s.sd - (s.sn[0] * s.o[0] + s.sn[1] * s.o[1] + s.sn[2] * s.o[2]);
  const bool below = s.surface && open.num > 0.;
  double a = 0., b = 0.;
  open.up = -1.;
  open.mirror = false;
  if (below) {
    a = s.sn[0] * s.R[0][0] + s.sn[1] * s.R[1][0] + s.sn[2] * s.R[2][0];
    b = s.sn[0] * s.R[0][1] + s.sn[1] * s.R[1][1] + s.sn[2] * s.R[2][1];
    open.up = s.sn[0] * s.R[0][2] + s.sn[1] * s.R[1][2] + s.sn[2] * s.R[2][2];
    // The sheet's mirror image in the surface sn . X = sd.
    double M[4][3];
    for (int i = 0; i < 4; ++i) {
      const double h = s.sn[0] * P[i][0] + s.sn[1] * P[i][1] + s.sn[2] * P[i][2] - s.sd;
      for (int k = 0; k < 3; ++k) {
        M[i][k] = P[i][k] - 2. * h * s.sn[k];
      }
    }
    open.mirror = projectedBox(s.R, s.o, M, box);
    if (open.mirror) {
      offMasks(box, open.colOffM, open.rowOffM);
    }
  }
  open.colUp.resize(m_width);
  open.rowUp.resize(m_height);
  for (unsigned int u = 0; u < m_width; ++u) {
    open.colUp[u] = std::max(a * m_subX[static_cast<size_t>(u) * n], a * m_subX[static_cast<size_t>(u) * n + n - 1]);
  }
  for (unsigned int v = 0; v < m_height; ++v) {
    open.rowUp[v] = std::max(b * m_subY[static_cast<size_t>(v) * n], b * m_subY[static_cast<size_t>(v) * n + n - 1]);
  }
}

void vpSSLRenderer::renderCore(const vpHomogeneousMatrix &cMo, float *reflectance, float *range,
                               unsigned char *grey) const
{
  const Scene scene = makeScene(cMo);
  const unsigned int n = m_supersampling;
  const double invSamples = 1. / (n * n);
  const bool hasBackgroundImage = m_backgroundImage.getSize() != 0;
  const int height = static_cast<int>(m_height);
  // Without distortion a sub-pixel's normalised point is (m_subX[column], m_subY[row]) exactly (normalisedRay()'s
  // factor is 1 + 0 (x^2 + y^2) = 1 for the finite x^2 + y^2 of any camera), so the products of R (x, y, 1) are those
  // of its column and of its row: tabulated once per frame, each ray direction is then R[k][0] x + R[k][1] y + R[k][2]
  // summed in the same order from the same products.
  const bool separable = m_rayCache.empty() && m_kdu == 0.;
  std::vector<double> colProducts, rowProducts;
  if (separable) {
    colProducts.resize(3 * m_subX.size());
    rowProducts.resize(3 * m_subY.size());
    for (size_t c = 0; c < m_subX.size(); ++c) {
      for (unsigned int k = 0; k < 3; ++k) {
        colProducts[3 * c + k] = scene.R[k][0] * m_subX[c];
      }
    }
    for (size_t r = 0; r < m_subY.size(); ++r) {
      for (unsigned int k = 0; k < 3; ++k) {
        rowProducts[3 * r + k] = scene.R[k][1] * m_subY[r];
      }
    }
  }
  // Open water: the pixels whose rays can meet neither the sheet nor its mirror image in the surface (without a
  // backdrop) are the background, or the surface reflecting it, on every ray; their shading leaves out the tests that
  // cannot pass, and sums as the rays' loop below sums.
  OpenWater open;
  if (separable && !scene.backdrop) {
    openWater(scene, open);
  }
  // Without distortion a pixel's central normalised point (centralRange()) is (x of its column, y of its row).
  std::vector<double> centralX, centralY;
  if (open.enabled) {
    centralX.resize(m_width);
    centralY.resize(m_height);
    double unused = 0.;
    for (unsigned int u = 0; u < m_width; ++u) {
      vpPixelMeterConversion::convertPoint(m_cam, u, 0, centralX[u], unused);
    }
    for (unsigned int v = 0; v < m_height; ++v) {
      vpPixelMeterConversion::convertPoint(m_cam, 0, v, unused, centralY[v]);
    }
  }
  vpSSLSurfaceKernel::Surface surface;
  for (int k = 0; k < 3; ++k) {
    surface.sn[k] = scene.sn[k];
  }
  surface.num = open.num;
  surface.maxRange2 = m_maxRange * m_maxRange;
  surface.waterIndex = kWaterIndex;
  surface.parallelEps = kParallelEps;
  enum Kind : unsigned char
  {
    FULL,       // shade() on every ray
    BACKGROUND, // every ray misses everything
    SURFACE     // every ray meets at most the surface, and nothing after it
  };
#pragma omp parallel
  {
    // A row's surface rays, shaded together (vpSSLSurfaceKernel): first the pixels' n x n rays, then their central
    // rays for the range.
    std::vector<unsigned char> kind(m_width);
    // Room for every ray of a row and its central ones, written by index.
    const size_t room = open.enabled ? static_cast<size_t>(m_width) * (n * n + 1) : 0;
    std::vector<double> dx(room), dy(room), dz(room), fresnel(room), tw(room);
#pragma omp for schedule(dynamic, 4)
    for (int v = 0; v < height; ++v) {
      size_t nb = 0;
      for (unsigned int u = 0; u < m_width; ++u) {
        kind[u] = FULL;
        if (!open.enabled || !(open.colOff[u] || open.rowOff[v])) {
          continue;
        }
        if (open.colUp[u] + open.rowUp[v] + open.up < -kOpenWaterMargin) {
          kind[u] = BACKGROUND;
        } else if (open.mirror && (open.colOffM[u] || open.rowOffM[v])) {
          kind[u] = SURFACE;
          for (unsigned int j = 0; j < n; ++j) {
            const double *rp = &rowProducts[3 * (static_cast<size_t>(v) * n + j)];
            for (unsigned int i = 0; i < n; ++i) {
              const double *cp = &colProducts[3 * (static_cast<size_t>(u) * n + i)];
              dx[nb] = cp[0] + rp[0] + scene.R[0][2];
              dy[nb] = cp[1] + rp[1] + scene.R[1][2];
              dz[nb] = cp[2] + rp[2] + scene.R[2][2];
              ++nb;
            }
          }
        }
      }
      const size_t nbRays = nb;
      if (range) {
        for (unsigned int u = 0; u < m_width; ++u) {
          if (kind[u] == SURFACE) {
            const double x = centralX[u], y = centralY[v];
            dx[nb] = scene.R[0][0] * x + scene.R[0][1] * y + scene.R[0][2];
            dy[nb] = scene.R[1][0] * x + scene.R[1][1] * y + scene.R[1][2];
            dz[nb] = scene.R[2][0] * x + scene.R[2][1] * y + scene.R[2][2];
            ++nb;
          }
        }
      }
      if (nb > 0) {
        vpSSLSurfaceKernel::surfaceRays(surface, dx.data(), dy.data(), dz.data(), nb, fresnel.data(), tw.data());
      }
      size_t ray = 0, central = nbRays;
      for (unsigned int u = 0; u < m_width; ++u) {
        const double background = hasBackgroundImage ? m_backgroundImage[v][u] / 255. : m_background;
        const size_t idx = static_cast<size_t>(v) * m_width + u;
        double sum = 0.;
        if (kind[u] == FULL) {
          sum = shadePixel(scene, u, static_cast<unsigned int>(v), background, separable, colProducts, rowProducts);
        } else if (kind[u] == BACKGROUND) {
          for (unsigned int k = 0; k < n * n; ++k) {
            sum += background;
          }
        } else {
          // shade()'s mix for a ray that meets the surface and nothing after it, or the background.
          for (unsigned int k = 0; k < n * n; ++k, ++ray) {
            const double r = fresnel[ray];
            sum += r < 0. ? background : r * background + (1. - r) * kSkyRadiance;
          }
        }
        const double mean = sum * invSamples;
        if (reflectance) {
          reflectance[idx] = static_cast<float>(mean);
        }
        if (grey) {
          grey[idx] = vpSSLQuantise::quantise(255. * mean);
        }
        if (!range) {
          continue;
        }
        if (kind[u] == FULL) {
          range[idx] = centralRange(scene, u, static_cast<unsigned int>(v), background);
        } else if (kind[u] == BACKGROUND) {
          range[idx] = std::numeric_limits<float>::infinity();
        } else {
          // shade()'s path length: to the surface, plus the reflected ray's (infinite: it meets nothing) where the
          // reflection dominates.
          const double r = fresnel[central];
          const double t = r < 0. || r >= 0.5 ? std::numeric_limits<double>::infinity() : tw[central];
          range[idx] = rangeOf(centralX[u], centralY[v], t);
          ++central;
        }
      }
    }
  }
}

double vpSSLRenderer::shadePixel(const Scene &scene, unsigned int u, unsigned int v, double background, bool separable,
                                 const std::vector<double> &colProducts, const std::vector<double> &rowProducts) const
{
  const unsigned int n = m_supersampling;
  double sum = 0.;
  for (unsigned int j = 0; j < n; ++j) {
    for (unsigned int i = 0; i < n; ++i) {
      double t = 0.;
      if (separable) {
        const double *cp = &colProducts[3 * (static_cast<size_t>(u) * n + i)];
        const double *rp = &rowProducts[3 * (static_cast<size_t>(v) * n + j)];
        const double d[3] = {cp[0] + rp[0] + scene.R[0][2], cp[1] + rp[1] + scene.R[1][2],
                             cp[2] + rp[2] + scene.R[2][2]};
        sum += shade(scene, scene.o, d, background, true, 0., t);
        continue;
      }
      double x = 0., y = 0.;
      normalisedRay(u, static_cast<unsigned int>(v), i, j, x, y);
      const double d[3] = {scene.R[0][0] * x + scene.R[0][1] * y + scene.R[0][2],
                           scene.R[1][0] * x + scene.R[1][1] * y + scene.R[1][2],
                           scene.R[2][0] * x + scene.R[2][1] * y + scene.R[2][2]};
      sum += shade(scene, scene.o, d, background, true, 0., t);
    }
  }
  return sum;
}

float vpSSLRenderer::rangeOf(double x, double y, double t)
{
  // |R (x, y, 1)| = sqrt(x^2 + y^2 + 1): t scaled to metres along the ray.
  return std::isfinite(t) ? static_cast<float>(t * std::sqrt(x * x + y * y + 1.))
                          : std::numeric_limits<float>::infinity();
}

float vpSSLRenderer::centralRange(const Scene &scene, unsigned int u, unsigned int v, double background) const
{
  double x = 0., y = 0., t = 0.;
  if (!m_centralRayCache.empty()) {
    const size_t idx = static_cast<size_t>(v) * m_width + u;
    x = m_centralRayCache[2 * idx];
    y = m_centralRayCache[2 * idx + 1];
  } else {
    vpPixelMeterConversion::convertPoint(m_cam, u, v, x, y);
  }
  const double d[3] = {scene.R[0][0] * x + scene.R[0][1] * y + scene.R[0][2],
                       scene.R[1][0] * x + scene.R[1][1] * y + scene.R[1][2],
                       scene.R[2][0] * x + scene.R[2][1] * y + scene.R[2][2]};
  shade(scene, scene.o, d, background, true, 0., t);
  return rangeOf(x, y, t);
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
  std::vector<vpPoint> P;
  if (m_aprilTag) {
    P = m_tagSheet.getCorners();
  } else {
    P = m_target.getPoints();
  }
  std::vector<vpImagePoint> points;
  points.reserve(P.size());
  for (vpPoint &p : P) {
    p.changeFrame(cMo);
    if (!(p.get_Z() > 0.)) {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      points.emplace_back(nan, nan);
      continue;
    }
    double u, v;
    vpMeterPixelConversion::convertPoint(m_cam, p.get_X() / p.get_Z(), p.get_Y() / p.get_Z(), u, v);
    points.emplace_back(v, u);
  }
  return points;
}

bool vpSSLRenderer::isTargetInView(const vpHomogeneousMatrix &cMo) const
{
  const Scene s = makeScene(cMo);
  if (!(s.o[2] < 0.)) {
    return false; // behind the sheet or edge-on: no printed side in view
  }
  const vpHomogeneousMatrix cMs = cMo * sheetPose();
  const int nx = 16, ny = 12;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      const double X = s.sheetX + s.halfW * (2. * i / nx - 1.), Y = s.sheetY + s.halfH * (2. * j / ny - 1.);
      const double Xc = cMs[0][0] * X + cMs[0][1] * Y + cMs[0][3];
      const double Yc = cMs[1][0] * X + cMs[1][1] * Y + cMs[1][3];
      const double Zc = cMs[2][0] * X + cMs[2][1] * Y + cMs[2][3];
      if (!(Zc > 0.)) {
        continue;
      }
      const double x = Xc / Zc, y = Yc / Zc;
      if (x < m_fovMinX || x > m_fovMaxX || y < m_fovMinY || y > m_fovMaxY) {
        continue;
      }
      double u = 0., v = 0.;
      vpMeterPixelConversion::convertPoint(m_cam, x, y, u, v);
      if (u >= -0.5 && u <= m_width - 0.5 && v >= -0.5 && v <= m_height - 0.5) {
        return true;
      }
    }
  }
  return false;
}
