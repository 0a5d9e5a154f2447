#include "vpSSLCentreTone.h"

#include <algorithm>
#include <cmath>

namespace {
// Relative radii sampled across each band, and the fewest samples about one ellipse: about one sample per pixel of
// its perimeter beyond that, so that the mean of a band weighs its pixels nearly evenly.
const int kRadiiPerBand = 5;
const int kMinSamplesPerEllipse = 16;

// Mean level over the band [rho0, rho1] of relative radii; false if a sample leaves the image.
bool bandMean(const vpImage<unsigned char> &I, const vpSSLLandmark &l, double rho0, double rho1, double &mean)
{
  const double c = std::cos(l.theta), s = std::sin(l.theta);
  const double W = static_cast<double>(I.getWidth()), H = static_cast<double>(I.getHeight());
  double sum = 0.;
  long count = 0;
  for (int i = 0; i < kRadiiPerBand; ++i) {
    const double rho = rho0 + (rho1 - rho0) * i / (kRadiiPerBand - 1);
    const int n = std::max(kMinSamplesPerEllipse, static_cast<int>(2. * M_PI * rho * l.radius));
    // The angles 2 pi k / n by rotation: two sines per ellipse rather than per sample.
    const double cd = std::cos(2. * M_PI / n), sd = std::sin(2. * M_PI / n);
    double ca = 1., sa = 0.;
    for (int k = 0; k < n; ++k) {
      const double x = rho * l.radius * ca, y = rho * l.minorRadius * sa;
      const double next = ca * cd - sa * sd;
      sa = sa * cd + ca * sd;
      ca = next;
      const double u = l.u + c * x - s * y, v = l.v + s * x + c * y;
      if (!(u >= 0. && v >= 0. && u < W - 1. && v < H - 1.)) {
        return false;
      }
      const int u0 = static_cast<int>(u), v0 = static_cast<int>(v);
      const double fu = u - u0, fv = v - v0;
      const unsigned char *r0 = I[v0] + u0, *r1 = I[v0 + 1] + u0;
      sum += (1. - fv) * ((1. - fu) * r0[0] + fu * r0[1]) + fv * ((1. - fu) * r1[0] + fu * r1[1]);
      ++count;
    }
  }
  mean = sum / count;
  return true;
}
} // namespace

bool vpSSLCentreTone::measure(const vpImage<unsigned char> &I, const vpSSLLandmark &landmark, double p, double &tone)
{
  if (!(landmark.radius > 0. && landmark.minorRadius > 0. && std::isfinite(landmark.radius) &&
        std::isfinite(landmark.minorRadius) && std::isfinite(landmark.u) && std::isfinite(landmark.v) &&
        std::isfinite(landmark.theta) && p > 0. && p < 1.)) {
    return false;
  }
  const double sp = std::sqrt(p);
  double centre = 0., white = 0., black = 0.;
  if (!bandMean(I, landmark, 0., 0.85 * p * sp, centre) || !bandMean(I, landmark, 1.06 * p, 0.96 * sp, white) ||
      !bandMean(I, landmark, 1.05 * sp, 0.96, black) || std::fabs(white - black) < 1.) {
    return false;
  }
  tone = (centre - black) / (white - black);
  return true;
}
