#include <visp3/ssl/vpSSLBrightnessNormalizer.h>

#include <algorithm>
#include <cmath>

#include <visp3/core/vpException.h>

#include "vpSSLImageCheck.h"

vpSSLBrightnessNormalizer::vpSSLBrightnessNormalizer() : m_low(1.), m_high(99.), m_maxGain(10.) {}

void vpSSLBrightnessNormalizer::setPercentiles(double low, double high)
{
  if (!(low >= 0. && low < high && high <= 100.)) {
    throw vpException(vpException::badValue,
                      "vpSSLBrightnessNormalizer: percentiles %g, %g: need 0 <= low < high <= 100", low, high);
  }
  m_low = low;
  m_high = high;
}

void vpSSLBrightnessNormalizer::setMaxGain(double gain)
{
  if (!(gain >= 1.)) {
    throw vpException(vpException::badValue, "vpSSLBrightnessNormalizer: max gain %g < 1", gain);
  }
  m_maxGain = gain;
}

void vpSSLBrightnessNormalizer::apply(const vpImage<unsigned char> &I, vpImage<unsigned char> &O) const
{
  vpSSLImageCheck::kernel(I, "vpSSLBrightnessNormalizer::apply");
  O.resize(I.getHeight(), I.getWidth());
  const size_t n = static_cast<size_t>(I.getSize());
  if (n == 0) {
    return;
  }
  unsigned char lut[256];
  computeLut(I, lut, 1);
  const unsigned char *src = I.bitmap;
  unsigned char *dst = O.bitmap;
  for (size_t i = 0; i < n; ++i) {
    dst[i] = lut[src[i]];
  }
}

void vpSSLBrightnessNormalizer::computeLut(const vpImage<unsigned char> &I, unsigned char lut[256],
                                           unsigned int step) const
{
  if (step == 0) {
    throw vpException(vpException::badValue, "vpSSLBrightnessNormalizer::computeLut: step must be >= 1");
  }
  // The rows are read through I[v] and getWidth(): both must describe memory the image holds.
  vpSSLImageCheck::kernel(I, "vpSSLBrightnessNormalizer::computeLut");
  // Four interleaved histograms: consecutive equal pixels (flat areas) would otherwise serialise on one counter.
  unsigned int hist4[4][256] = {{0}};
  const unsigned int W = I.getWidth(), H = I.getHeight();
  for (unsigned int v = 0; v < H; v += step) {
    const unsigned char *row = I[v];
    unsigned int u = 0;
    if (step == 1) {
      for (; u + 4 <= W; u += 4) {
        ++hist4[0][row[u]];
        ++hist4[1][row[u + 1]];
        ++hist4[2][row[u + 2]];
        ++hist4[3][row[u + 3]];
      }
    }
    // Sparse rows: four samples per iteration, one per histogram.
    for (; u + 3 * step < W; u += 4 * step) {
      ++hist4[0][row[u]];
      ++hist4[1][row[u + step]];
      ++hist4[2][row[u + 2 * step]];
      ++hist4[3][row[u + 3 * step]];
    }
    for (; u < W; u += step) {
      ++hist4[0][row[u]];
    }
  }
  unsigned int hist[256];
  size_t n = 0;
  for (int g = 0; g < 256; ++g) {
    hist[g] = hist4[0][g] + hist4[1][g] + hist4[2][g] + hist4[3][g];
    n += hist[g];
  }
  const double nLow = m_low * 0.01 * static_cast<double>(n), nHigh = m_high * 0.01 * static_cast<double>(n);
  int lo = 0, hi = 255;
  double acc = 0.;
  bool haveLo = false;
  for (int g = 0; g < 256; ++g) {
    acc += hist[g];
    if (!haveLo && acc > nLow) {
      lo = g;
      haveLo = true;
    }
    if (acc >= nHigh) {
      hi = g;
      break;
    }
  }
  double gain = hi > lo ? 255. / (hi - lo) : m_maxGain;
  double offset = lo;
  if (gain > m_maxGain) {
    // Stretch about the middle of the range instead of amplifying noise without bound.
    gain = m_maxGain;
    offset = 0.5 * (lo + hi) - 127.5 / gain;
  }
  for (int g = 0; g < 256; ++g) {
    // std::round() (half away from zero) without its library call: x - floor(x) is exact, and below 0 both
    // clamp to 0.
    const double x = (g - offset) * gain, f = std::floor(x);
    const double value = x - f >= 0.5 ? f + 1. : f;
    lut[g] = static_cast<unsigned char>(std::min(255., std::max(0., value)));
  }
}
