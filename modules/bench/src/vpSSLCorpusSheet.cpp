#include <visp3/ssl_bench/vpSSLCorpusSheet.h>

#include <algorithm>
#include <cmath>

#include <opencv2/aruco.hpp>
#include <visp3/core/vpException.h>

namespace {
// Ring index floor(2 log_p rho) of the square wave: even indices are inked (s_p = 0), odd ones white.
inline long ringIndex(double rho, double logP)
{
  return static_cast<long>(std::floor(2. * std::log(rho) / logP));
}

// Paper fraction of one landmark at normalised radius rho (0 < rho < 1): s_p(rho) = ringIndex mod 2.
inline double ringPaper(double rho, double logP)
{
  if (rho <= 0.)
    return 1. / 3.; // the centre: the rings' area average, p / (1 + p) for p = 0.5 (never hit by a sub-sample)
  return (ringIndex(rho, logP) & 1) ? 1. : 0.;
}
} // namespace

double vpSSLCorpusSheet::sslPaper(const vpSSLTarget &target, double x, double y)
{
  for (const vpSSLTargetLandmark &l : target.getLandmarks()) {
    const double rho = std::hypot(x - l.x, y - l.y) / l.radius;
    if (rho < 1.)
      return ringPaper(rho, std::log(l.p));
  }
  return 1.;
}

vpSSLCorpusSheet vpSSLCorpusSheet::sslTarget(const vpSSLTarget &target, double pixelsPerMetre)
{
  if (target.size() == 0)
    throw vpException(vpException::badValue, "vpSSLCorpusSheet: the target has no landmark");
  vpSSLCorpusSheet s;
  s.m_content = SSL_TARGET;
  s.m_width = target.getSheetWidth();
  s.m_height = target.getSheetHeight();
  s.m_left = target.getSheetCenterX() - 0.5 * s.m_width;
  s.m_top = target.getSheetCenterY() - 0.5 * s.m_height;
  const double ppm = pixelsPerMetre;
  const int w = static_cast<int>(std::ceil(s.m_width * ppm)), h = static_cast<int>(std::ceil(s.m_height * ppm));
  cv::Mat img(h, w, CV_32FC1, cv::Scalar(1.f));
  const double halfDiag = 0.7072 / ppm; // a pixel's half diagonal (m), a little more
  for (const vpSSLTargetLandmark &l : target.getLandmarks()) {
    const double logP = std::log(l.p);
    const double R = l.radius;
    const int c0 = std::max(0, static_cast<int>(std::floor((l.x - R - s.m_left) * ppm)) - 1);
    const int c1 = std::min(w - 1, static_cast<int>(std::ceil((l.x + R - s.m_left) * ppm)) + 1);
    const int r0 = std::max(0, static_cast<int>(std::floor((l.y - R - s.m_top) * ppm)) - 1);
    const int r1 = std::min(h - 1, static_cast<int>(std::ceil((l.y + R - s.m_top) * ppm)) + 1);
    for (int r = r0; r <= r1; ++r) {
      float *row = img.ptr<float>(r);
      const double y = s.m_top + (r + 0.5) / ppm;
      for (int c = c0; c <= c1; ++c) {
        const double x = s.m_left + (c + 0.5) / ppm;
        const double d = std::hypot(x - l.x, y - l.y);
        if (d - halfDiag >= R)
          continue; // wholly outside the disc: paper
        // A pixel whose nearest and farthest points lie in the same ring (and inside the disc) is that ring.
        if (d + halfDiag < R && d - halfDiag > 0. &&
            ringIndex((d - halfDiag) / R, logP) == ringIndex((d + halfDiag) / R, logP)) {
          row[c] = static_cast<float>(ringPaper(d / R, logP));
          continue;
        }
        const int n = (d < 4. / ppm) ? 16 : 4;
        double sum = 0.;
        for (int i = 0; i < n; ++i) {
          const double ys = s.m_top + (r + (i + 0.5) / n) / ppm;
          for (int j = 0; j < n; ++j) {
            const double xs = s.m_left + (c + (j + 0.5) / n) / ppm;
            const double rho = std::hypot(xs - l.x, ys - l.y) / R;
            sum += rho < 1. ? ringPaper(rho, logP) : 1.;
          }
        }
        row[c] = static_cast<float>(sum / (n * n));
      }
    }
  }
  s.m_texture.set(img, s.m_left, s.m_top, ppm, vpSSLCorpusTexture::CLAMP, 1.f);
  return s;
}

vpSSLCorpusSheet vpSSLCorpusSheet::aprilTag(int id, double tagSize, double tagX, double tagY, double width,
                                            double height, double sheetX, double sheetY, double pixelsPerMetre)
{
  cv::Ptr<cv::aruco::Dictionary> dict = cv::aruco::getPredefinedDictionary(cv::aruco::DICT_APRILTAG_36h11);
  if (id < 0 || id >= dict->bytesList.rows)
    throw vpException(vpException::badValue, "vpSSLCorpusSheet: AprilTag 36h11 id %d is not in the family", id);
  // 36h11: 6x6 code cells inside a one-cell black border, 8 cells across the black square; the sheet around it
  // must leave the one-cell white border the detector needs.
  const double cell = tagSize / 8.;
  if (std::fabs(tagX - sheetX) + 0.5 * tagSize + cell > 0.5 * width + 1e-9 ||
      std::fabs(tagY - sheetY) + 0.5 * tagSize + cell > 0.5 * height + 1e-9)
    throw vpException(vpException::badValue, "vpSSLCorpusSheet: the tag and its white border do not fit the sheet");
  cv::Mat bits;
  dict->drawMarker(id, 8, bits, 1);
  vpSSLCorpusSheet s;
  s.m_content = APRILTAG;
  s.m_width = width;
  s.m_height = height;
  s.m_left = sheetX - 0.5 * width;
  s.m_top = sheetY - 0.5 * height;
  s.m_tagSize = tagSize;
  s.m_tagX = tagX;
  s.m_tagY = tagY;
  s.m_tagId = id;
  const double ppm = pixelsPerMetre;
  const int w = static_cast<int>(std::ceil(width * ppm)), h = static_cast<int>(std::ceil(height * ppm));
  cv::Mat img(h, w, CV_32FC1, cv::Scalar(1.f));
  const double tx0 = tagX - 0.5 * tagSize, ty0 = tagY - 0.5 * tagSize;
  auto paperAt = [&](double x, double y) {
    const int i = static_cast<int>(std::floor((y - ty0) / cell)), j = static_cast<int>(std::floor((x - tx0) / cell));
    if (i < 0 || j < 0 || i >= 8 || j >= 8)
      return 1.;
    return bits.at<unsigned char>(i, j) ? 1. : 0.;
  };
  const int c0 = std::max(0, static_cast<int>(std::floor((tx0 - s.m_left) * ppm)) - 1);
  const int c1 = std::min(w - 1, static_cast<int>(std::ceil((tx0 + tagSize - s.m_left) * ppm)) + 1);
  const int r0 = std::max(0, static_cast<int>(std::floor((ty0 - s.m_top) * ppm)) - 1);
  const int r1 = std::min(h - 1, static_cast<int>(std::ceil((ty0 + tagSize - s.m_top) * ppm)) + 1);
  for (int r = r0; r <= r1; ++r) {
    float *row = img.ptr<float>(r);
    for (int c = c0; c <= c1; ++c) {
      double sum = 0.;
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
          sum += paperAt(s.m_left + (c + (j + 0.5) / 4.) / ppm, s.m_top + (r + (i + 0.5) / 4.) / ppm);
      row[c] = static_cast<float>(sum / 16.);
    }
  }
  s.m_texture.set(img, s.m_left, s.m_top, ppm, vpSSLCorpusTexture::CLAMP, 1.f);
  return s;
}
