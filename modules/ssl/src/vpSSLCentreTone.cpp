#include "vpSSLCentreTone.h"

#include <algorithm>
#include <cmath>

namespace {
// Relative radii sampled across each band, and the fewest samples about one ellipse: about one sample per pixel of
// its perimeter beyond that, so that the mean of a band weighs its pixels nearly evenly.
const int kRadiiPerBand = 5;
const int kMinSamplesPerEllipse = 16;
// Sectors whose means give the spread of a band's level about the landmark (kMinSamplesPerEllipse / kSectors samples
// each on every ellipse at least).
const int kSectors = 8;

// Mean level over the band [rho0, rho1] of relative radii and, if error is given, the spread (standard deviation) of
// its kSectors sectors' means over sqrt(kSectors) (each ellipse's samples cut by their parametric angle); false if a
// sample leaves the image.
bool bandMean(const vpImage<unsigned char> &I, const vpSSLLandmark &l, double rho0, double rho1, double &mean,
              double *error = nullptr)
{
  const double c = std::cos(l.theta), s = std::sin(l.theta);
  const double W = static_cast<double>(I.getWidth()), H = static_cast<double>(I.getHeight());
  double sum = 0., sectorSum[kSectors] = {0.};
  long count = 0, sectorCount[kSectors] = {0};
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
      const double g = (1. - fv) * ((1. - fu) * r0[0] + fu * r0[1]) + fv * ((1. - fu) * r1[0] + fu * r1[1]);
      sum += g;
      ++count;
      const int q = k * kSectors / n;
      sectorSum[q] += g;
      ++sectorCount[q];
    }
  }
  mean = sum / count;
  if (error != nullptr) {
    double m = 0., mm = 0.;
    for (int q = 0; q < kSectors; ++q) {
      const double g = sectorSum[q] / sectorCount[q];
      m += g;
      mm += g * g;
    }
    m /= kSectors;
    *error = std::sqrt(std::max(0., (mm / kSectors - m * m) / (kSectors - 1)));
  }
  return true;
}
} // namespace

bool vpSSLCentreTone::measure(const vpImage<unsigned char> &I, const vpSSLLandmark &landmark, double p,
                              Reading &reading)
{
  if (!(landmark.radius > 0. && landmark.minorRadius > 0. && std::isfinite(landmark.radius) &&
        std::isfinite(landmark.minorRadius) && std::isfinite(landmark.u) && std::isfinite(landmark.v) &&
        std::isfinite(landmark.theta) && p > 0. && p < 1.)) {
    return false;
  }
  const double sp = std::sqrt(p);
  double white = 0., black = 0.;
  if (!bandMean(I, landmark, 1.06 * p, 0.96 * sp, white) || !bandMean(I, landmark, 1.05 * sp, 0.96, black) ||
      std::fabs(white - black) < 1.) {
    return false;
  }
  const double coreRho = 0.85 * p * p * p;
  double centre = 0., core = 0., edge = 0., coreError = 0., edgeError = 0.;
  if (!bandMean(I, landmark, 0., 0.85 * p * sp, centre) || !bandMean(I, landmark, 0., coreRho, core, &coreError) ||
      !bandMean(I, landmark, 0.8 * p * p, 1.2 * p * p, edge, &edgeError)) {
    return false;
  }
  reading.tone = (centre - black) / (white - black);
  reading.rise = (edge - core) / (white - black);
  reading.riseError = std::hypot(coreError, edgeError) / std::fabs(white - black);
  reading.coreMinor = coreRho * landmark.minorRadius;
  return true;
}
