#include <visp3/ssl/vpSSLDetector.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include <visp3/core/vpException.h>
#include <visp3/core/vpPixelMeterConversion.h>

namespace {
// Window of the small-landmark mode on the twice upsampled image: 1.25 times the 16 px that an 8 px
// landmark measures there (the response fades once w exceeds about 1.4 R, Eq. 2).
const unsigned int kSmallModeWindow = 20;
// Smallest apparent radius read (px): below it the rings are thinner than a pixel.
const double kMinRadius = 4.;

// Twice the resolution, bilinear, pixel centres kept: output (u, v) samples input ((u + 0.5) / 2 - 0.5, ...).
void upsample2(const vpImage<unsigned char> &I, vpImage<unsigned char> &O)
{
  const int W = static_cast<int>(I.getWidth()), H = static_cast<int>(I.getHeight());
  O.resize(2 * H, 2 * W);
  for (int v = 0; v < 2 * H; ++v) {
    const int v0 = (v - 1) >> 1, v1 = std::min(H - 1, v0 + 1);
    const int wv1 = (v & 1) ? 3 : 1; // weight of row v0 in quarters
    const unsigned char *top = I[std::max(0, v0)], *bottom = I[v1];
    unsigned char *out = O[v];
    // Column 0 repeats column 0; odd columns weigh 3:1, even ones 1:3 the pair (u0, u0 + 1).
    for (int u = 0; u < 2 * W; ++u) {
      const int u0 = (u - 1) >> 1, u1 = std::min(W - 1, u0 + 1);
      const int wu1 = (u & 1) ? 3 : 1;
      const int c0 = std::max(0, u0);
      const int t = wu1 * top[c0] + (4 - wu1) * top[u1];
      const int b = wu1 * bottom[c0] + (4 - wu1) * bottom[u1];
      out[u] = static_cast<unsigned char>((wv1 * t + (4 - wv1) * b + 8) >> 4);
    }
  }
}

double elapsedMs(std::chrono::steady_clock::time_point &t)
{
  const auto now = std::chrono::steady_clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - t).count();
  t = now;
  return ms;
}
} // namespace

vpSSLDetector::vpSSLDetector(const vpSSLTarget &target)
    : vpDetectorBase(), m_normalizer(), m_match(40, target.getP()), m_peakDetector(), m_radiusEstimator(),
      m_identifier(target), m_normalize(true), m_upsample(false), m_window(40), m_maxRadius(300.), m_threshold(0.12),
      m_rois(), m_noRois(), m_fullSearchPeriod(10), m_roiCalls(0), m_lastSearchWasFull(true)
{
  m_radiusEstimator.setP(target.getP());
}

void vpSSLDetector::setWindow(unsigned int w)
{
  m_match.setWindow(w);
  m_window = w;
  if (m_upsample) {
    m_match.setWindow(kSmallModeWindow);
  }
}

void vpSSLDetector::setSmallLandmarkMode(bool enable)
{
  m_upsample = enable;
  m_match.setWindow(enable ? kSmallModeWindow : m_window);
}

void vpSSLDetector::setRegionsOfInterest(const std::vector<vpRect> &rois)
{
  if (m_rois.empty() && !rois.empty()) {
    m_roiCalls = 0; // tracking starts: the period counts from here
  }
  m_rois.assign(rois.begin(), rois.end());
}

void vpSSLDetector::setThreshold(double threshold)
{
  if (!(threshold >= 0. && threshold <= 1.)) {
    throw vpException(vpException::badValue, "vpSSLDetector: threshold %g not in [0, 1]", threshold);
  }
  m_threshold = threshold;
}

void vpSSLDetector::setMaxRadius(double r)
{
  if (!(r > kMinRadius)) {
    throw vpException(vpException::badValue, "vpSSLDetector: max radius %g must be > %g px", r, kMinRadius);
  }
  m_maxRadius = r;
}

bool vpSSLDetector::detect(const vpImage<unsigned char> &I)
{
  auto t0 = std::chrono::steady_clock::now();
  auto t = t0;
  // Containers are cleared, not freed: their storage is reused from frame to frame (issue 4: no heap
  // allocation in steady state).
  m_nb_objects = 0;
  m_landmarks.clear();
  m_targetMatch.detection.assign(getTarget().size(), -1);
  m_targetMatch.found = false;
  m_targetMatch.nbMatched = 0;
  m_targetMatch.residual = 0.;
  m_times = vpSSLDetectorTimes();
  if (I.getSize() == 0) {
    m_polygon.clear();
    m_message.clear();
    throw vpException(vpException::dimensionError, "vpSSLDetector::detect: empty image");
  }

  // The rings are read on the camera's grey levels: the stretch that helps the matching function can
  // clip a dark background to the ink's black, and the outermost ring is told from the background by
  // its level (vpSSLRadiusEstimator).
  const vpImage<unsigned char> *raw = &I;
  // Paper Sec. 4.1: with regions of interest, every n-th frame still searches the whole image, so that a
  // landmark the tracker has lost (or never predicted) is picked up again.
  m_lastSearchWasFull = true;
  if (!m_rois.empty()) {
    ++m_roiCalls;
    m_lastSearchWasFull = m_fullSearchPeriod > 0 && m_roiCalls % m_fullSearchPeriod == 0;
  }
  const std::vector<vpRect> *rois = m_lastSearchWasFull ? &m_noRois : &m_rois;
  const double scale = m_upsample ? 2. : 1.;
  if (m_upsample) {
    upsample2(I, m_upsampled);
    raw = &m_upsampled;
    m_scaledRois.clear();
    for (const vpRect &r : *rois) {
      m_scaledRois.push_back(
          vpRect(2. * r.getLeft() + 0.5, 2. * r.getTop() + 0.5, 2. * r.getWidth(), 2. * r.getHeight()));
    }
    rois = &m_scaledRois;
  }
  const vpImage<unsigned char> *In = raw;
  if (m_normalize) {
    m_normalizer.apply(*raw, m_normalized);
    In = &m_normalized;
  }
  m_times.normalization = elapsedMs(t);

  if (rois->empty()) {
    m_match.compute(*In, m_map);
  } else {
    m_match.compute(*In, *rois, m_map);
  }
  m_times.matching = elapsedMs(t);

  const int maxValue = m_match.getMaxValue();
  m_peakDetector.setThreshold(std::max(1, static_cast<int>(std::ceil(m_threshold * maxValue))));
  m_peakDetector.detect(m_map, m_peaks, *rois);
  m_times.peaks = elapsedMs(t);

  m_radiusEstimator.setRadiusRange(kMinRadius * scale, m_maxRadius * scale);
  m_radiusEstimator.setPixelScale(scale);
  // The white paper just outside the outermost black ring continues the pattern by one ring (out to
  // R / sqrt(p), vpSSLRadiusEstimator), so the matching map has a ridge of peaks there too.
  const double margin = 1. / std::sqrt(getTarget().getP());
  const double margin2 = margin * margin;
  for (const vpSSLPeak &peak : m_peaks) {
    // Landmarks do not overlap, so a peak inside one already found or on its paper ring (peaks come
    // strongest first) is on its rings, not another landmark's centre: most peaks are, and reading their
    // rays is the dearest stage. Another landmark's centre is at least R + r from this one's, so it can
    // only lie within R / sqrt(p) if its radius r is below (1 / sqrt(p) - 1) R, 0.41 R for p = 0.5, and it
    // touches this one's outer ring: printed landmarks are separated by a margin.
    const double pu = m_upsample ? 0.5 * (peak.u + 0.5) - 0.5 : peak.u;
    const double pv = m_upsample ? 0.5 * (peak.v + 0.5) - 0.5 : peak.v;
    bool inside = false;
    for (const vpSSLLandmark &k : m_landmarks) {
      const double c = std::cos(k.theta), s = std::sin(k.theta), du = pu - k.u, dv = pv - k.v;
      const double x = (c * du + s * dv) / k.radius, y = (c * dv - s * du) / k.minorRadius;
      if (x * x + y * y < margin2) {
        inside = true;
        break;
      }
    }
    if (inside) {
      continue;
    }
    vpSSLLandmark l;
    l.u = peak.u;
    l.v = peak.v;
    l.score = std::min(1., static_cast<double>(peak.value) / maxValue);
    if (!m_radiusEstimator.estimate(*raw, l)) {
      continue;
    }
    l.radiusEq7 = vpSSLRadiusEstimator::sweep(*In, m_match, static_cast<int>(std::lround(l.u)),
                                              static_cast<int>(std::lround(l.v)),
                                              static_cast<unsigned int>(1.5 * scale * m_maxRadius), m_sweep);
    if (m_upsample) {
      l.u = 0.5 * (l.u + 0.5) - 0.5;
      l.v = 0.5 * (l.v + 0.5) - 0.5;
      l.radius *= 0.5;
      l.minorRadius *= 0.5;
      l.radiusEq7 *= 0.5;
      for (double &r : l.directionalRadius) {
        r *= 0.5;
      }
    }
    // Two peaks on the same landmark: keep the stronger one (peaks come strongest first).
    bool duplicate = false;
    for (const vpSSLLandmark &k : m_landmarks) {
      if (std::hypot(k.u - l.u, k.v - l.v) < 0.5 * std::min(k.minorRadius, l.minorRadius)) {
        duplicate = true;
        break;
      }
    }
    if (duplicate) {
      continue;
    }
    m_landmarks.push_back(l);
  }
  // Stable insertion sort, best score first: a handful of landmarks, and std::stable_sort would allocate
  // a buffer every frame.
  for (size_t i = 1; i < m_landmarks.size(); ++i) {
    for (size_t j = i; j > 0 && m_landmarks[j - 1].score < m_landmarks[j].score; --j) {
      std::swap(m_landmarks[j - 1], m_landmarks[j]);
    }
  }
  m_times.radius = elapsedMs(t);

  m_identifier.identify(m_landmarks, m_targetMatch);
  m_times.identification = elapsedMs(t);

  fillObjects();
  m_times.total = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return !m_landmarks.empty();
}

void vpSSLDetector::fillObjects()
{
  const vpSSLTarget &target = getTarget();
  // Resized, not rebuilt: the polygons and the short messages keep their storage between frames.
  m_polygon.resize(m_landmarks.size());
  m_message.resize(m_landmarks.size());
  for (std::string &m : m_message) {
    m.assign("ssl");
  }
  for (size_t k = 0; k < m_targetMatch.detection.size(); ++k) {
    if (m_targetMatch.detection[k] >= 0) {
      std::string &m = m_message[m_targetMatch.detection[k]];
      m.assign(target.getName());
      m.append(" ");
      m.append(target.getLandmark(k).name);
    }
  }
  const int nbVertices = 16;
  for (size_t i = 0; i < m_landmarks.size(); ++i) {
    const vpSSLLandmark &l = m_landmarks[i];
    std::vector<vpImagePoint> &polygon = m_polygon[i];
    polygon.resize(nbVertices);
    const double c = std::cos(l.theta), s = std::sin(l.theta);
    const double b = l.minorRadius > 0. ? l.minorRadius : l.radius;
    for (int k = 0; k < nbVertices; ++k) {
      const double a = 2. * M_PI * k / nbVertices;
      const double x = l.radius * std::cos(a), y = b * std::sin(a);
      polygon[k].set_ij(l.v + s * x + c * y, l.u + c * x - s * y);
    }
  }
  m_nb_objects = m_landmarks.size();
}

const vpSSLLandmark *vpSSLDetector::getMatchedLandmark(size_t i) const
{
  if (i >= m_targetMatch.detection.size() || m_targetMatch.detection[i] < 0) {
    return nullptr;
  }
  return &m_landmarks[m_targetMatch.detection[i]];
}

double vpSSLDetector::range(const vpSSLLandmark &landmark, double radius, const vpCameraParameters &cam)
{
  if (!(landmark.radius > 0.)) {
    throw vpException(vpException::badValue, "vpSSLDetector::range: landmark radius %g px", landmark.radius);
  }
  return cam.get_px() * radius / landmark.radius;
}

std::vector<vpFeaturePoint> vpSSLDetector::getFeaturePoints(const vpCameraParameters &cam) const
{
  std::vector<vpFeaturePoint> features;
  for (size_t k = 0; k < m_targetMatch.detection.size(); ++k) {
    const vpSSLLandmark *l = getMatchedLandmark(k);
    if (l == nullptr) {
      continue;
    }
    double x = 0., y = 0.;
    vpPixelMeterConversion::convertPoint(cam, l->u, l->v, x, y);
    vpFeaturePoint s;
    s.buildFrom(x, y, range(*l, getTarget().getLandmark(k).radius, cam));
    features.push_back(s);
  }
  return features;
}
