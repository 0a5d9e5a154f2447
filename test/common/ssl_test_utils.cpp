#include "ssl_test_utils.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <visp3/core/vpException.h>
#include <visp3/core/vpGaussRand.h>
#include <visp3/core/vpMath.h>
#include <visp3/core/vpMeterPixelConversion.h>
#include <visp3/core/vpPixelMeterConversion.h>
#include <visp3/core/vpRotationMatrix.h>
#include <visp3/core/vpThetaUVector.h>

#include <visp3/ssl/vpSSLPattern.h>

namespace {
unsigned char toGrey(double g)
{
  g = std::round(g);
  return static_cast<unsigned char>(g < 0. ? 0. : (g > 255. ? 255. : g));
}

// Bilinear interpolation with replicated borders.
double bilinear(const vpImage<unsigned char> &I, double u, double v)
{
  const double umax = I.getWidth() - 1., vmax = I.getHeight() - 1.;
  u = std::min(std::max(u, 0.), umax);
  v = std::min(std::max(v, 0.), vmax);
  const unsigned int u0 = static_cast<unsigned int>(u), v0 = static_cast<unsigned int>(v);
  const unsigned int u1 = std::min(u0 + 1, I.getWidth() - 1), v1 = std::min(v0 + 1, I.getHeight() - 1);
  const double a = u - u0, b = v - v0;
  return (1. - b) * ((1. - a) * I[v0][u0] + a * I[v0][u1]) + b * ((1. - a) * I[v1][u0] + a * I[v1][u1]);
}
} // namespace

namespace sslt {
vpHomogeneousMatrix lookAt(double distance, double tiltDeg, double tiltAxisDeg, double rollDeg)
{
  const double a = vpMath::rad(tiltAxisDeg), t = vpMath::rad(tiltDeg);
  vpRotationMatrix tilt(vpThetaUVector(t * std::cos(a), t * std::sin(a), 0.));
  vpRotationMatrix roll(vpThetaUVector(0., 0., vpMath::rad(rollDeg)));
  vpHomogeneousMatrix cMo;
  cMo.insert(tilt * roll);
  cMo.insert(vpTranslationVector(0., 0., distance));
  return cMo;
}

vpSSLTarget singleLandmarkTarget(double radius, double p)
{
  vpSSLTarget target;
  target.setName("single-landmark");
  vpSSLTargetLandmark l;
  l.name = "L";
  l.radius = radius;
  l.p = p;
  target.addLandmark(l);
  target.setSheet(5. * radius, 5. * radius, 0., 0.);
  return target;
}

void directionalBlur(vpImage<unsigned char> &I, double sigmaPx, double angleDeg)
{
  if (!(sigmaPx >= 0.)) {
    throw vpException(vpException::badValue, "directionalBlur: sigma %g px must be >= 0", sigmaPx);
  }
  if (sigmaPx == 0. || I.getSize() == 0) {
    return;
  }
  const double step = 0.5; // half-pixel steps keep a small sigma from being under-sampled
  const int K = static_cast<int>(std::ceil(3. * sigmaPx / step));
  std::vector<double> w(2 * K + 1);
  double sum = 0.;
  for (int k = -K; k <= K; ++k) {
    const double s = k * step;
    w[k + K] = std::exp(-0.5 * s * s / (sigmaPx * sigmaPx));
    sum += w[k + K];
  }
  const double cu = std::cos(vpMath::rad(angleDeg)) * step, cv = std::sin(vpMath::rad(angleDeg)) * step;
  vpImage<unsigned char> out(I.getHeight(), I.getWidth());
  for (unsigned int v = 0; v < I.getHeight(); ++v) {
    for (unsigned int u = 0; u < I.getWidth(); ++u) {
      double acc = 0.;
      for (int k = -K; k <= K; ++k) {
        acc += w[k + K] * bilinear(I, u + k * cu, v + k * cv);
      }
      out[v][u] = toGrey(acc / sum);
    }
  }
  I = out;
}

void addGaussianNoise(vpImage<unsigned char> &I, double sigma, long seed)
{
  vpGaussRand noise(sigma, 0., seed);
  for (unsigned int k = 0; k < I.getSize(); ++k) {
    I.bitmap[k] = toGrey(I.bitmap[k] + noise());
  }
}

void setContrast(vpImage<unsigned char> &I, double contrast, double mean)
{
  for (unsigned int k = 0; k < I.getSize(); ++k) {
    I.bitmap[k] = toGrey(mean + contrast * (I.bitmap[k] - 127.5));
  }
}

void occlude(vpImage<unsigned char> &I, const vpRect &rect, unsigned char value)
{
  const int u0 = std::max(0, static_cast<int>(std::ceil(rect.getLeft())));
  const int v0 = std::max(0, static_cast<int>(std::ceil(rect.getTop())));
  const int u1 = std::min(static_cast<int>(I.getWidth()) - 1, static_cast<int>(std::floor(rect.getRight())));
  const int v1 = std::min(static_cast<int>(I.getHeight()) - 1, static_cast<int>(std::floor(rect.getBottom())));
  for (int v = v0; v <= v1; ++v) {
    for (int u = u0; u <= u1; ++u) {
      I[v][u] = value;
    }
  }
}

void mirrorHorizontal(vpImage<unsigned char> &I)
{
  for (unsigned int v = 0; v < I.getHeight(); ++v) {
    std::reverse(I[v], I[v] + I.getWidth());
  }
}

vpImagePoint projectPoint(const vpCameraParameters &cam, const vpHomogeneousMatrix &cMo, double X, double Y, double Z)
{
  const double cX = cMo[0][0] * X + cMo[0][1] * Y + cMo[0][2] * Z + cMo[0][3];
  const double cY = cMo[1][0] * X + cMo[1][1] * Y + cMo[1][2] * Z + cMo[1][3];
  const double cZ = cMo[2][0] * X + cMo[2][1] * Y + cMo[2][2] * Z + cMo[2][3];
  if (!(cZ > 0.)) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return vpImagePoint(nan, nan);
  }
  double u, v;
  vpMeterPixelConversion::convertPoint(cam, cX / cZ, cY / cZ, u, v);
  return vpImagePoint(v, u);
}

double apparentRadius(const vpCameraParameters &cam, const vpHomogeneousMatrix &cMo, double x, double y, double radius)
{
  std::vector<vpImagePoint> pts;
  for (int k = 0; k < 360; ++k) {
    const double a = vpMath::rad(k);
    vpImagePoint ip = projectPoint(cam, cMo, x + radius * std::cos(a), y + radius * std::sin(a));
    if (std::isnan(ip.get_u())) {
      throw vpException(vpException::badValue, "apparentRadius: the circle crosses the camera plane");
    }
    pts.push_back(ip);
  }
  double best = 0.;
  for (int k = 0; k < 720; ++k) {
    const double a = vpMath::rad(0.25 * k), cu = std::cos(a), cv = std::sin(a);
    double lo = std::numeric_limits<double>::max(), hi = -lo;
    for (const vpImagePoint &p : pts) {
      const double s = cu * p.get_u() + cv * p.get_v();
      lo = std::min(lo, s);
      hi = std::max(hi, s);
    }
    best = std::max(best, hi - lo);
  }
  return 0.5 * best;
}

vpImagePoint forwardDarknessCentroid(const vpCameraParameters &cam, const vpHomogeneousMatrix &cMo,
                                     const vpSSLTargetLandmark &l)
{
  const int nRho = 1500, nPhi = 360;
  const double h = 1e-4 * l.radius;
  double su = 0., sv = 0., sw = 0.;
  for (int i = 0; i < nRho; ++i) {
    const double rho = (i + 0.5) * l.radius / nRho;
    const double darkness = 1. - vpSSLPattern::circular(rho, 0., l.radius, l.p);
    if (darkness == 0.) {
      continue;
    }
    for (int j = 0; j < nPhi; ++j) {
      const double phi = 2. * M_PI * (j + 0.5) / nPhi;
      const double X = l.x + rho * std::cos(phi), Y = l.y + rho * std::sin(phi);
      const vpImagePoint p = projectPoint(cam, cMo, X, Y);
      const vpImagePoint px0 = projectPoint(cam, cMo, X - h, Y), px1 = projectPoint(cam, cMo, X + h, Y);
      const vpImagePoint py0 = projectPoint(cam, cMo, X, Y - h), py1 = projectPoint(cam, cMo, X, Y + h);
      const double jac = std::fabs((px1.get_u() - px0.get_u()) * (py1.get_v() - py0.get_v()) -
                                   (px1.get_v() - px0.get_v()) * (py1.get_u() - py0.get_u())) /
                         (4. * h * h);
      const double w = darkness * rho * jac;
      su += w * p.get_u();
      sv += w * p.get_v();
      sw += w;
    }
  }
  return vpImagePoint(sv / sw, su / sw);
}

vpImagePoint darknessCentroid(const vpImage<unsigned char> &I, const vpImagePoint &centre, double radius)
{
  double su = 0., sv = 0., sw = 0.;
  const int v0 = std::max(0, static_cast<int>(std::floor(centre.get_v() - radius)));
  const int v1 = std::min(static_cast<int>(I.getHeight()) - 1, static_cast<int>(std::ceil(centre.get_v() + radius)));
  const int u0 = std::max(0, static_cast<int>(std::floor(centre.get_u() - radius)));
  const int u1 = std::min(static_cast<int>(I.getWidth()) - 1, static_cast<int>(std::ceil(centre.get_u() + radius)));
  for (int v = v0; v <= v1; ++v) {
    for (int u = u0; u <= u1; ++u) {
      const double du = u - centre.get_u(), dv = v - centre.get_v();
      if (du * du + dv * dv <= radius * radius) {
        const double w = 255. - I[v][u];
        su += w * u;
        sv += w * v;
        sw += w;
      }
    }
  }
  if (sw <= 0.) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return vpImagePoint(nan, nan);
  }
  return vpImagePoint(sv / sw, su / sw);
}

vpCameraParameters cameraWithDistortion(double px, double py, double u0, double v0, double kud, unsigned int width,
                                        unsigned int height, double *maxMismatchPx)
{
  // For each pixel of a grid, the undistorted point m (kud model inverted by fixed point), then the
  // kdu minimising sum |m - md (1 + kdu rd^2)|^2: linear least squares in kdu.
  struct Sample
  {
    double xd, yd, x, y;
  };
  std::vector<Sample> samples;
  for (unsigned int v = 0; v < height; v += 8) {
    for (unsigned int u = 0; u < width; u += 8) {
      const double xd = (u - u0) / px, yd = (v - v0) / py;
      double x = xd, y = yd;
      for (int it = 0; it < 100; ++it) {
        const double f = 1. + kud * (x * x + y * y);
        x = xd / f;
        y = yd / f;
      }
      samples.push_back({xd, yd, x, y});
    }
  }
  double num = 0., den = 0.;
  for (const Sample &s : samples) {
    const double rd2 = s.xd * s.xd + s.yd * s.yd;
    num += s.xd * rd2 * (s.x - s.xd) + s.yd * rd2 * (s.y - s.yd);
    den += s.xd * rd2 * s.xd * rd2 + s.yd * rd2 * s.yd * rd2;
  }
  const double kdu = den > 0. ? num / den : 0.;
  vpCameraParameters cam;
  cam.initPersProjWithDistortion(px, py, u0, v0, kud, kdu);
  if (maxMismatchPx) {
    double worst = 0.;
    for (const Sample &s : samples) {
      double x, y, u, v;
      vpPixelMeterConversion::convertPoint(cam, u0 + s.xd * px, v0 + s.yd * py, x, y);
      vpMeterPixelConversion::convertPoint(cam, x, y, u, v);
      worst = std::max(worst, std::hypot(u - (u0 + s.xd * px), v - (v0 + s.yd * py)));
    }
    *maxMismatchPx = worst;
  }
  return cam;
}

double median(std::vector<double> v)
{
  if (v.empty())
    return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

} // namespace sslt
