#include <visp3/ssl_bench/vpSSLCorpusTexture.h>

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>
#include <visp3/core/vpException.h>

void vpSSLCorpusTexture::set(const cv::Mat &image, double x0, double y0, double pixelsPerMetre, Border border,
                             float pad)
{
  if (image.empty())
    throw vpException(vpException::badValue, "vpSSLCorpusTexture: empty image");
  if (image.type() != CV_32FC1 && image.type() != CV_32FC3)
    throw vpException(vpException::badValue, "vpSSLCorpusTexture: the image must be CV_32FC1 or CV_32FC3");
  if (!(pixelsPerMetre > 0.))
    throw vpException(vpException::badValue, "vpSSLCorpusTexture: the density must be positive");
  m_x0 = x0;
  m_y0 = y0;
  m_ppm = pixelsPerMetre;
  m_border = border;
  m_channels = image.channels();

  // Levels down to ~8 px on the short side; level 0 padded so that every halving is an exact 2x2 average (a
  // mirrored texture must halve exactly for its period to stay consistent, so it is not padded but must divide).
  int nbLevels = 1;
  while ((std::min(image.cols, image.rows) >> nbLevels) >= 8)
    ++nbLevels;
  const int factor = 1 << (nbLevels - 1);
  const int w = (image.cols + factor - 1) / factor * factor;
  const int h = (image.rows + factor - 1) / factor * factor;
  if (border == MIRROR && (w != image.cols || h != image.rows))
    throw vpException(vpException::badValue, "vpSSLCorpusTexture: a mirrored texture needs sides divisible by %d",
                      factor);
  m_levels.assign(1, cv::Mat());
  cv::copyMakeBorder(image, m_levels[0], 0, h - image.rows, 0, w - image.cols, cv::BORDER_CONSTANT,
                     cv::Scalar::all(pad));
  for (int l = 1; l < nbLevels; ++l) {
    cv::Mat next;
    cv::resize(m_levels.back(), next, cv::Size(m_levels.back().cols / 2, m_levels.back().rows / 2), 0., 0.,
               cv::INTER_AREA);
    m_levels.push_back(next);
  }
}

void vpSSLCorpusTexture::bilinear(size_t level, double c, double r, float *out) const
{
  const cv::Mat &m = m_levels[level];
  const int w = m.cols, h = m.rows;
  const double fc = std::floor(c), fr = std::floor(r);
  const float ac = static_cast<float>(c - fc), ar = static_cast<float>(r - fr);
  int c0 = static_cast<int>(fc), r0 = static_cast<int>(fr);
  int c1 = c0 + 1, r1 = r0 + 1;
  auto fix = [this](int i, int n) {
    if (m_border == CLAMP)
      return std::min(std::max(i, 0), n - 1);
    // Mirror: period 2n, i and 2n - 1 - i read the same pixel.
    int k = i % (2 * n);
    if (k < 0)
      k += 2 * n;
    return k < n ? k : 2 * n - 1 - k;
  };
  c0 = fix(c0, w);
  c1 = fix(c1, w);
  r0 = fix(r0, h);
  r1 = fix(r1, h);
  const float *row0 = m.ptr<float>(r0), *row1 = m.ptr<float>(r1);
  const int n = m_channels;
  for (int k = 0; k < n; ++k) {
    const float top = row0[c0 * n + k] + ac * (row0[c1 * n + k] - row0[c0 * n + k]);
    const float bottom = row1[c0 * n + k] + ac * (row1[c1 * n + k] - row1[c0 * n + k]);
    out[k] = top + ar * (bottom - top);
  }
}

double vpSSLCorpusTexture::level(double footprint) const
{
  // Level-0 pixels per sample; level l has 2^l times fewer. Level floor(log2(m / 0.75)) is minified by 0.75 to
  // 1.5, the next one by 0.375 to 0.75: blending them never minifies a level by more than 1.5.
  const double m = footprint * m_ppm;
  const double last = static_cast<double>(m_levels.size() - 1);
  return m > 0.75 ? std::min(last, std::log2(m / 0.75)) : 0.;
}

void vpSSLCorpusTexture::sampleLevel(double x, double y, double level, float *out) const
{
  const size_t last = m_levels.size() - 1;
  const size_t l0 = static_cast<size_t>(level);
  const double frac = level - static_cast<double>(l0);
  const double c = (x - m_x0) * m_ppm, r = (y - m_y0) * m_ppm; // level-0 pixel-edge coordinates
  auto at = [&](size_t l, float *o) {
    const double s = std::ldexp(1., -static_cast<int>(l));
    bilinear(l, c * s - 0.5, r * s - 0.5, o);
  };
  at(l0, out);
  if (frac > 1e-3 && l0 < last) {
    float other[3];
    at(l0 + 1, other);
    for (int k = 0; k < m_channels; ++k)
      out[k] += static_cast<float>(frac) * (other[k] - out[k]);
  }
}
