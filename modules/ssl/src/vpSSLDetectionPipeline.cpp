#include "vpSSLDetectionPipeline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <visp3/core/vpException.h>

#include <visp3/ssl/vpSSLInputLimits.h>

#include "vpSSLCentreTone.h"
#include "vpSSLLookupKernel.h"
#include "vpSSLResampleKernel.h"

namespace {
// Window of the small-landmark mode on the twice upsampled image: 1.25 times the 16 px that an 8 px
// landmark measures there (the response fades once w exceeds about 1.4 R, Eq. 2).
const unsigned int kSmallModeWindow = 20;
// Smallest apparent radius read (px): below it the rings are thinner than a pixel.
const double kMinRadius = 4.;
// Radii (px) of the landmarks whose centre disc must not be darker than their outer black ring, nor the band about the
// edge at p^2 R far lighter than their core (vpSSLCentreTone): from 10 px, where that disc (0.3 R) is more than a few
// pixels, to 40 px. The false landmarks those tests turn away on the independent corpus's negatives are 10 to 35 px;
// a nearer landmark's rings pass the similarity test that round clutter fails, and under perspective its centre disc
// drifts off the outer ellipse's centre.
const double kToneMinRadius = 10.;
const double kToneMaxRadius = 40.;
// Largest rise (vpSSLCentreTone::Reading) of a landmark kept, beyond its riseError: 0.8 at most on the landmarks of
// the corpus, 0.4 on the test grid (test_centre_tone), 1.3 and more on the bull's-eyes with a dark dot that pass the
// other tests, each more than twice its riseError over 1. Noise alone can lift a faint landmark's rise over 1. It is
// tested where the core spans a pixel at least along its minor semi-axis: narrower, the reading's centre error (up to
// a pixel on landmarks of 10 px) moves the core onto the next ring.
const double kMaxRise = 1.;
// Short window of a full search (vpSSLDetector::setShortWindow()): the response of w = 40 fades below a radius of
// about 28 px, and w = 10 answers from 7 px up, for a quarter of its matching cost.
const unsigned int kShortWindow = 10;
// Peaks of the short window's map read per frame: its strongest few. On textured surroundings the short window
// has many more peaks over the threshold than w = 40, and the 16 strongest find every small landmark the 64
// strongest do on the independent corpus (doc/detector.md).
const unsigned int kShortWindowPeaks = 16;
// Window of a full search on the image's quarter (80 px in image pixels): the landmarks of 40 px and more whose
// inner rings a blur of 2 to 3 px has wiped out, and which neither w = 40 nor the short window then answers. On the
// quarter their outer rings are sharp (the blur is a quarter as wide). Its strongest kQuarterPeaks peaks are read
// after every other, so that it only adds landmarks: the reading budget of the others is spent first. A handful of
// large landmarks fits in a frame; on noisy water the weaker peaks of that map are noise, each read all around.
const unsigned int kQuarterWindow = 20;
const unsigned int kQuarterPeaks = 8;
// A full search at full resolution computes w only where the image's half, matched with w / 2 (the same radii), has
// a local maximum over kCandidateThreshold of the peak threshold: in the tiles of kCandidateTile px within
// kCandidateReach px of it (the full-resolution peak lies within 2-4 px of the half image's).
const double kCandidateThreshold = 0.75;
const int kCandidateTile = 16;
const double kCandidateReach = 12.;
// Columns of the half map passed over at once where none reaches the candidates' threshold (a power of 2).
const int kCandidateBlock = 16;

unsigned int halfWindow(unsigned int w)
{
  return std::max(2u, w / 2);
}

// Twice the resolution, bilinear, pixel centres kept: output (u, v) samples input ((u + 0.5) / 2 - 0.5, ...), edges
// repeated. Output row v mixes input rows (v - 1) / 2 and the next one, 3:1 for odd v and 1:3 for even v.
void upsample2(const vpImage<unsigned char> &I, vpImage<unsigned char> &O)
{
  const int W = static_cast<int>(I.getWidth()), H = static_cast<int>(I.getHeight());
  O.resize(2 * H, 2 * W);
  for (int v = 0; v < 2 * H; ++v) {
    const int v0 = (v - 1) >> 1, v1 = std::min(H - 1, v0 + 1);
    vpSSLResampleKernel::upsampleRow(I[std::max(0, v0)], I[v1], (v & 1) ? 3 : 1, W, O[v]);
  }
}

/*
  Rows [v0, v1) and columns [u0, u1) of the image decimated twice (2x2 box average, rounded), through the
  normalisation table: O(v, u) = lut[mean of I(2v .. 2v + 1, 2u .. 2u + 1)]. O must be W / 2 x H / 2.
*/
void decimate2(const vpImage<unsigned char> &I, const unsigned char *lut, int u0, int v0, int u1, int v1,
               vpImage<unsigned char> &O)
{
  for (int v = v0; v < v1; ++v) {
    const unsigned char *a = I[2 * v], *b = I[2 * v + 1];
    unsigned char *out = O[v];
    // Two passes over the row (in L1): the averages vectorise, and so does the table look-up on its own.
    for (int u = u0; u < u1; ++u) {
      out[u] = static_cast<unsigned char>((a[2 * u] + a[2 * u + 1] + b[2 * u] + b[2 * u + 1] + 2) >> 2);
    }
    if (lut != nullptr && u1 > u0) {
      vpSSLLookupKernel::applyTable(lut, out + u0, out + u0, static_cast<size_t>(u1 - u0));
    }
  }
}

/*
  Window of the decimated matching pass for a full-resolution window w: 0.35 w (14 for w = 40) rather than w / 2.
  Decimation blurs the rings (a 2x2 box), and the peak of a landmark not much larger than the window sits a few
  pixels off its centre (the map is flat there): with w / 2 the smallest landmarks w = 40 finds at full
  resolution (20-25 px) gave no peak, or one too far off for the ring reading. 0.35 w finds all of those on the
  rendered views and the recorded underwater sequences (test_detector_decimation, test_tracker_sequences).
*/
unsigned int coarseWindow(unsigned int w)
{
  return std::max(2u, (7 * w + 10) / 20);
}

// Sampling step of the normalisation histogram: one pixel in 16 (19200 at 640x480, plenty for the 1 % and 99 %
// percentiles). The whole histogram cost a tenth of the frame's time, and most of a tracking frame's
// normalisation, which needs the whole image's table.
const unsigned int kHistogramStep = 4;

// Smallest correlation of a landmark's ring profile with the square wave s_p (vpSSLConcentricReader::similarity()):
// sharp landmarks give 0.8-0.9, 25 px ones blurred by 2 px 0.54 and more, bull's-eyes of equal rings 0.46 and less.
const double kMinSimilarity = 0.5;
// Candidates per frame that vpSSLConcentricReader may read where the rays give up (readAllAround()) by default
// (setAllAroundBudget()), and how close (px, in u and in v) a candidate's symmetric centre must be to one read in vain
// to be skipped. Twice as many find a few more faint small landmarks on noisy water, whose noise peaks spend the budget
// first, but read two more false targets on the independent corpus's negatives (doc/detector.md).
const unsigned int kAllAroundBudget = 24;
const double kSameCentre = 1.5;
// completeTarget(): rotations tried (the target's, or the best scanned), those a detection left out of the match
// gives, and how far (relative) that detection's rectified distance from the big landmark may be from the printed one
// (vpSSLTargetIdentifier's tolerance); the most landmarks read per rotation, the scan's step (in predicted minor
// semi-axes at the predicted centre) and its largest count, how far apart two tried rotations are (rad), and how close
// to its prediction (in predicted radii) and of what size (radius ratio) a reading must be.
const size_t kPredictedRotations = 3;
const size_t kDetectionRotations = 8;
const double kDetectionReach = 0.25;
const size_t kMaxTargetLandmarks = 8;
const double kRotationStep = 0.3;
const int kMaxRotations = 360;
const double kRotationSeparation = 0.35;
const double kPredictedReach = 0.5;
const double kPredictedSize = 0.7;

// Whether the landmark \e l lies where \e p is predicted, and is of its size.
bool asPredicted(const vpSSLLandmark &l, const vpSSLLandmark &p)
{
  const double ratio = l.radius / p.radius;
  return std::hypot(l.u - p.u, l.v - p.v) <= std::max(2., kPredictedReach * p.radius) && ratio >= kPredictedSize &&
         ratio <= 1. / kPredictedSize;
}

// Smallest semi-axis, relative to the window, of a predicted landmark whose region of a tracking frame is matched on
// the decimated image (vpSSLRegionPlanner::splitByResolution()).
const double kCoarseRegionRadius = 0.625;

double elapsedMs(std::chrono::steady_clock::time_point &t)
{
  const auto now = std::chrono::steady_clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - t).count();
  t = now;
  return ms;
}
} // namespace

vpSSLDetectionPipeline::vpSSLDetectionPipeline(const vpSSLTarget &target)
    : m_normalizer(), m_match(40, target.getP()), m_peakDetector(), m_radiusEstimator(), m_identifier(target),
      m_prediction(target), m_normalize(true), m_upsample(false), m_window(40), m_decimation(1),
      m_matchCoarse(coarseWindow(40), target.getP()), m_shortWindow(kShortWindow),
      m_matchShort(kShortWindow, target.getP()), m_shortPeakDetector(), m_matchHalf(halfWindow(40), target.getP()),
      m_matchQuarter(kQuarterWindow, target.getP()), m_maxRadius(300.), m_radiusSweep(false), m_equalRingCheck(true),
      m_threshold(0.07), m_planner(), m_noRois(), m_lastSearchWasFull(true)
{
  m_shortPeakDetector.setMaxPeaks(kShortWindowPeaks);
  m_quarterPeakDetector.setMaxPeaks(kQuarterPeaks);
  setAllAroundBudget(kAllAroundBudget);
  m_radiusEstimator.setP(target.getP());
  m_concentricReader.setP(target.getP());
  m_concentricReader.setBlurredRingModel(true);
  for (size_t k = 1; k < target.size(); ++k) {
    if (target.getLandmark(k).radius > target.getLandmark(m_bigLandmark).radius) {
      m_bigLandmark = k;
    }
  }
}

void vpSSLDetectionPipeline::setWindow(unsigned int w)
{
  m_match.setWindow(w);
  m_matchCoarse.setWindow(coarseWindow(w));
  m_matchHalf.setWindow(halfWindow(w));
  m_window = w;
  if (m_upsample) {
    m_match.setWindow(kSmallModeWindow);
  }
}

void vpSSLDetectionPipeline::setSmallLandmarkMode(bool enable)
{
  m_upsample = enable;
  m_match.setWindow(enable ? kSmallModeWindow : m_window);
}

void vpSSLDetectionPipeline::setShortWindow(unsigned int w)
{
  if (w != 0) {
    m_matchShort.setWindow(w); // checks w
  }
  m_shortWindow = w;
}

void vpSSLDetectionPipeline::setDecimation(unsigned int decimation)
{
  if (decimation != 1 && decimation != 2) {
    throw vpException(vpException::badValue, "vpSSLDetector: decimation %u not 1 or 2", decimation);
  }
  m_decimation = decimation;
}

void vpSSLDetectionPipeline::setThreshold(double threshold)
{
  if (!(threshold >= 0. && threshold <= 1.)) {
    throw vpException(vpException::badValue, "vpSSLDetector: threshold %g not in [0, 1]", threshold);
  }
  m_threshold = threshold;
}

void vpSSLDetectionPipeline::setAllAroundBudget(unsigned int candidates)
{
  m_allAroundBudget = candidates;
  // Room for the centres read in vain, so that a frame allocates nothing; a budget beyond any frame's candidates
  // grows it once.
  m_allAroundTried.reserve(std::min(candidates, 1024u));
}

void vpSSLDetectionPipeline::setMaxRadius(double r)
{
  if (!(r > kMinRadius)) {
    throw vpException(vpException::badValue, "vpSSLDetector: max radius %g must be > %g px", r, kMinRadius);
  }
  m_maxRadius = r;
}

void vpSSLDetectionPipeline::detect(const vpImage<unsigned char> &I)
{
  auto t = std::chrono::steady_clock::now();
  // Containers are cleared, not freed: their storage is reused from frame to frame, so that a steady stream of
  // frames allocates nothing.
  m_landmarks.clear();
  m_targetMatch.detection.assign(getTarget().size(), -1);
  m_targetMatch.found = false;
  m_targetMatch.nbMatched = 0;
  m_targetMatch.residual = 0.;
  m_times = vpSSLDetectorTimes();
  if (I.getSize() == 0) {
    throw vpException(vpException::dimensionError, "vpSSLDetectionPipeline::detect: empty image");
  }
  // Width and height consistent with the buffer (in 64 bits) and within the documented limits: nothing is read
  // past a buffer whose declared size wraps.
  vpSSLInputLimits::checkImage(I, "vpSSLDetector::detect");

  // The rings are read on the camera's grey levels: the stretch that helps the matching function can
  // clip a dark background to the ink's black, and the outermost ring is told from the background by
  // its level (vpSSLRadiusEstimator).
  const vpImage<unsigned char> *raw = &I;
  // Paper Sec. 4.1: the caller (vpSSLTracker) decides which frames search the whole image, by giving no region.
  m_lastSearchWasFull = m_planner.getRegions().empty();
  const double scale = m_upsample ? 2. : 1.;
  // Decimated matching (setDecimation()): candidates from the half-resolution map, rings read at full
  // resolution.
  const bool canDecimate = !m_upsample && I.getWidth() >= 2 && I.getHeight() >= 2;
  if (m_upsample) {
    upsample2(I, m_upsampled);
    raw = &m_upsampled;
  }
  // One normalisation table for the frame, from a sparse histogram of the whole image: a region of interest is
  // normalised exactly as in a full search, whichever pixels are normalised.
  if (m_normalize) {
    m_normalizer.computeLut(*raw, m_lut, kHistogramStep);
  } else {
    for (int g = 0; g < 256; ++g) {
      m_lut[g] = static_cast<unsigned char>(g);
    }
  }
  m_radiusEstimator.setRadiusRange(kMinRadius * scale, m_maxRadius * scale);
  m_concentricReader.setRadiusRange(kMinRadius * scale, m_maxRadius * scale);
  m_radiusEstimator.setPixelScale(scale);
  // a_xi and b_xi of the full-resolution window, for Eq. 5 at single pixels (refinePeak(), scoreAt()).
  for (unsigned int xi = 0; xi <= m_match.getWindow(); ++xi) {
    m_offsetA[xi] = m_match.offsetSqrtP(xi);
    m_offsetB[xi] = m_match.offsetP(xi);
  }
  m_refined.clear();
  m_allAroundLeft = m_allAroundBudget;
  m_allAroundTried.clear();
  m_times.normalization = elapsedMs(t);
  m_planner.startFrame();
  double reread = 0.; // ring reading of the predicted landmarks, counted with the other ring readings
  if (m_lastSearchWasFull) {
    searchRegions(I, *raw, m_decimation == 2 && canDecimate, nullptr, scale, t);
  } else {
    rereadPredicted(*raw, scale);
    reread = elapsedMs(t);
    if (m_planner.getPending().empty()) {
      // Every region's landmark was re-read: nothing to match or search. The map keeps nothing of earlier regions.
      if (m_decimation == 2 && canDecimate) {
        m_decimated.resize(I.getHeight() / 2, I.getWidth() / 2);
      }
      clearMap(m_decimation == 2 && canDecimate ? m_decimated : *raw, m_mainMap);
      m_peaks.clear();
      m_times.normalization += elapsedMs(t);
    } else if (m_decimation == 1 && canDecimate) {
      // A region whose landmark is large enough for the decimated pass is matched there, a tenth of the work of
      // the full resolution; the others, and those where the decimated pass finds nothing, at full resolution.
      // The decimated pass finds every landmark whose smaller semi-axis is 0.625 w or more (25 px for w = 40).
      m_planner.splitByResolution(kCoarseRegionRadius * m_window);
      if (!m_planner.getCoarse().empty()) {
        searchRegions(I, *raw, true, &m_planner.getCoarse(), scale, t);
        m_planner.refineUnfilledCoarse();
      }
      if (!m_planner.getFine().empty()) {
        searchRegions(I, *raw, false, &m_planner.getFine(), scale, t);
      } else {
        clearMap(*raw, m_mainMap);
      }
      m_planner.setMapRegions(m_planner.getFine());
    } else {
      searchRegions(I, *raw, m_decimation == 2 && canDecimate, &m_planner.getPending(), scale, t);
      m_planner.setMapRegions(m_planner.getPending());
    }
  }
  // Stable insertion sort, best score first: a handful of landmarks, and std::stable_sort would allocate
  // a buffer every frame.
  for (size_t i = 1; i < m_landmarks.size(); ++i) {
    for (size_t j = i; j > 0 && m_landmarks[j - 1].score < m_landmarks[j].score; --j) {
      std::swap(m_landmarks[j - 1], m_landmarks[j]);
    }
  }
  m_times.radius += reread + elapsedMs(t);
  // Storage reused: no allocation once it has grown to the number of landmarks in view.
  m_planner.remember(m_landmarks);

  m_identifier.identify(m_landmarks, m_targetMatch);
  m_times.identification = elapsedMs(t);
  // Twice: a landmark read where a scanned rotation put it gives the target's rotation for the others. Its ring
  // readings count with the others.
  for (int round = 0; round < 2 && m_targetCompletion && m_lastSearchWasFull && m_decimation == 1 && !m_upsample &&
                      m_shortWindow != 0 && completeTarget(*raw);
       ++round) {
    for (size_t i = 1; i < m_landmarks.size(); ++i) {
      for (size_t j = i; j > 0 && m_landmarks[j - 1].score < m_landmarks[j].score; --j) {
        std::swap(m_landmarks[j - 1], m_landmarks[j]);
      }
    }
    m_planner.remember(m_landmarks);
    m_identifier.identify(m_landmarks, m_targetMatch);
  }
  m_times.radius += elapsedMs(t);
}

void vpSSLDetectionPipeline::searchRegions(const vpImage<unsigned char> &I, const vpImage<unsigned char> &rawImage,
                                           bool coarse, const std::vector<vpRect> *regions, double scale,
                                           std::chrono::steady_clock::time_point &t)
{
  const vpImage<unsigned char> *raw = &rawImage;
  const vpImage<unsigned char> *In = raw;
  const std::vector<vpRect> *rois = regions != nullptr ? regions : &m_noRois;
  const bool full = regions == nullptr;
  // The decimated map of the regions a full-resolution tracking frame matches there has a map of its own:
  // getMatchingMap() stays the full-resolution one.
  MatchMap &map = coarse && m_decimation == 1 ? m_coarseMap : m_mainMap;
  // Whether only some pixels of the normalised image are up to date (m_lut holds the table then).
  bool partialNormalization = false;
  int maxValue = 0;
  if (coarse) {
    const unsigned char *lut = m_normalize ? m_lut : nullptr;
    const int Wc = static_cast<int>(I.getWidth() / 2), Hc = static_cast<int>(I.getHeight() / 2);
    m_decimated.resize(static_cast<unsigned int>(Hc), static_cast<unsigned int>(Wc));
    const int wc = static_cast<int>(m_matchCoarse.getWindow());
    m_scaledRois.clear();
    if (full) {
      decimate2(I, lut, 0, 0, Wc, Hc, m_decimated);
    } else {
      // Pixel j of the decimated image is centred on pixel 2 j + 0.5 of the image.
      for (const vpRect &r : *rois) {
        const vpRect c(0.5 * (r.getLeft() - 0.5), 0.5 * (r.getTop() - 0.5), 0.5 * r.getWidth(), 0.5 * r.getHeight());
        m_scaledRois.push_back(c);
        // The matching of a region reads w around it.
        const double u0 = std::max(0., std::floor(c.getLeft()) - wc - 1),
                     v0 = std::max(0., std::floor(c.getTop()) - wc - 1);
        const double u1 = std::min<double>(Wc, std::ceil(c.getRight()) + wc + 2);
        const double v1 = std::min<double>(Hc, std::ceil(c.getBottom()) + wc + 2);
        if (std::isfinite(u0) && std::isfinite(v0) && std::isfinite(u1) && std::isfinite(v1) && u0 < u1 && v0 < v1) {
          decimate2(I, lut, static_cast<int>(u0), static_cast<int>(v0), static_cast<int>(u1), static_cast<int>(v1),
                    m_decimated);
        }
      }
      rois = &m_scaledRois;
    }
    m_times.normalization += elapsedMs(t);
    if (full) {
      m_matchCoarse.compute(m_decimated, map.map);
      map.allWritten = true;
    } else {
      matchRegions(m_matchCoarse, m_decimated, *rois, map);
    }
    m_times.matching += elapsedMs(t);
    maxValue = m_matchCoarse.getMaxValue();
    m_peakDetector.setThreshold(std::max(1, static_cast<int>(std::ceil(m_threshold * maxValue))));
    m_peakDetector.detect(map.map, m_peaks, *rois);
    for (vpSSLPeak &p : m_peaks) {
      p.u = 2. * p.u + 0.5;
      p.v = 2. * p.v + 0.5;
    }
    m_times.peaks += elapsedMs(t);
  } else {
    if (m_upsample) {
      m_scaledRois.clear();
      for (const vpRect &r : *rois) {
        m_scaledRois.push_back(
            vpRect(2. * r.getLeft() + 0.5, 2. * r.getTop() + 0.5, 2. * r.getWidth(), 2. * r.getHeight()));
      }
      rois = &m_scaledRois;
    }
    if (m_normalize && full) {
      m_normalized.resize(raw->getHeight(), raw->getWidth());
      vpSSLLookupKernel::applyTable(m_lut, raw->bitmap, m_normalized.bitmap, raw->getSize());
      In = &m_normalized;
    } else if (m_normalize) {
      // Tracking frame: the table of the whole image (the same as a full search's), applied only to the pixels the
      // matching of the regions reads (each grown by the window); the Eq. 7 sweep normalises the row it reads.
      m_normalized.resize(raw->getHeight(), raw->getWidth());
      const int W = static_cast<int>(raw->getWidth()), H = static_cast<int>(raw->getHeight());
      const int w = static_cast<int>(m_match.getWindow());
      for (const vpRect &r : *rois) {
        const double u0 = std::max(0., std::floor(r.getLeft()) - w - 1),
                     v0 = std::max(0., std::floor(r.getTop()) - w - 1);
        const double u1 = std::min<double>(W, std::ceil(r.getRight()) + w + 2);
        const double v1 = std::min<double>(H, std::ceil(r.getBottom()) + w + 2);
        if (!(std::isfinite(u0) && std::isfinite(v0) && std::isfinite(u1) && std::isfinite(v1) && u0 < u1 && v0 < v1)) {
          continue;
        }
        for (int v = static_cast<int>(v0); v < static_cast<int>(v1); ++v) {
          vpSSLLookupKernel::applyTable(m_lut, (*raw)[v] + static_cast<int>(u0), m_normalized[v] + static_cast<int>(u0),
                                        static_cast<size_t>(u1 - u0));
        }
      }
      In = &m_normalized;
      partialNormalization = true;
    }
    m_times.normalization += elapsedMs(t);

    // A full search at full resolution matches w where the half image says a landmark of its radii may be.
    const bool candidates = full && !m_upsample && In->getWidth() >= 2 && In->getHeight() >= 2;
    const std::vector<vpRect> *peakRegions = rois;
    m_candidateRegions.clear();
    if (candidates) {
      planCandidateRegions(*In);
      matchRegions(m_match, *In, m_candidateRegions, map);
      peakRegions = &m_candidateRegions;
    } else if (full) {
      m_match.compute(*In, map.map);
      map.allWritten = true;
    } else {
      matchRegions(m_match, *In, *rois, map);
    }
    m_times.matching += elapsedMs(t);

    maxValue = m_match.getMaxValue();
    m_peakDetector.setThreshold(std::max(1, static_cast<int>(std::ceil(m_threshold * maxValue))));
    if (candidates && m_candidateRegions.empty()) {
      m_peaks.clear(); // no region: an empty list would mean the whole image
    } else {
      m_peakDetector.detect(map.map, m_peaks, *peakRegions);
    }
    m_times.peaks += elapsedMs(t);
    if (full && m_shortWindow != 0 && !m_upsample) {
      addShortWindowPeaks(*In, maxValue, t);
    }
  }

  for (const vpSSLPeak &peak : m_peaks) {
    // Landmarks do not overlap, so a peak inside one already found or on its paper ring (peaks come
    // strongest first) is on its rings, not another landmark's centre: most peaks are, and reading their
    // rays is the dearest stage. Another landmark's centre is at least R + r from this one's, so it can
    // only lie within R / sqrt(p) if its radius r is below (1 / sqrt(p) - 1) R, 0.41 R for p = 0.5, and it
    // touches this one's outer ring: printed landmarks are separated by a margin.
    const double pu = m_upsample ? 0.5 * (peak.u + 0.5) - 0.5 : peak.u;
    const double pv = m_upsample ? 0.5 * (peak.v + 0.5) - 0.5 : peak.v;
    bool inside = insideFound(pu, pv);
    // Tracking mode (paper Sec. 4.1): a region of interest is placed around one predicted landmark. Once a
    // landmark has been read inside every region that holds this peak, the peak is on the paper or the rings
    // around it (most of the peaks left in a region are): it is not read. A landmark the regions did not
    // predict is found by the next full search.
    if (!inside && !m_lastSearchWasFull) {
      inside = !m_planner.isOpen(pu, pv);
    }
    if (inside) {
      continue;
    }
    vpSSLLandmark l;
    l.u = peak.u;
    l.v = peak.v;
    l.score = std::min(1., static_cast<double>(peak.value) / maxValue);
    // Tracking mode (paper Sec. 4.1): a landmark read in the previous frame near this peak is re-read around
    // its previous ellipse, which skips the search over the whole radius range.
    const vpSSLLandmark *prior = m_lastSearchWasFull ? nullptr : m_planner.previousNear(pu, pv);
    bool read = false;
    if (prior != nullptr) {
      vpSSLLandmark scaled = *prior;
      if (m_upsample) {
        scaled.u = 2. * scaled.u + 0.5;
        scaled.v = 2. * scaled.v + 0.5;
        scaled.radius *= 2.;
        scaled.minorRadius *= 2.;
      }
      // With decimation the re-reading starts from the decimated peak itself: it lies within a pixel or two of the
      // centre, which the symmetry centring of the re-reading searches +-3 px around, so the climb to the
      // full-resolution maximum is not needed (it was a tenth of a tracking frame). The score is then the
      // full-resolution map at the centre read, one evaluation of Eq. 5.
      vpSSLLandmark tracked = l;
      // Held within 11 % of a landmark that passed selfSimilar(), the re-reading is not checked again.
      read = m_radiusEstimator.estimate(*raw, tracked, scaled);
      if (read && coarse) {
        tracked.score = scoreAt(I, tracked.u, tracked.v);
      }
      if (read) {
        l = tracked;
      }
    }
    if (!read) {
      if (coarse) {
        // The decimated peak only says where to look: the full-resolution maximum nearby is the one the
        // full-resolution pass would have found, and the ring reading starts from it.
        vpSSLPeak fine = peak;
        if (!refinePeak(I, fine, true)) {
          continue;
        }
        l.u = fine.u;
        l.v = fine.v;
        l.score = std::min(1., static_cast<double>(fine.value) / m_match.getMaxValue());
      }
      // The rays' reading is the more precise; where it cannot follow the rings of a point-symmetric candidate
      // (small, blurred or strongly oblique landmarks), or where what they read does not shrink by p all the way
      // in, the rings are read all around at once.
      const bool rays = m_radiusEstimator.estimate(*raw, l) && selfSimilar(*raw, l);
      if (!rays && !readAllAround(*raw, l)) {
        continue;
      }
    }
    keepLandmark(l, *raw, *In, coarse || partialNormalization, scale);
  }
  m_times.radius += elapsedMs(t);
}

void vpSSLDetectionPipeline::addShortWindowPeaks(const vpImage<unsigned char> &normalized, int mainMax,
                                                 std::chrono::steady_clock::time_point &t)
{
  // The short window on the image and on its half: w and 2 w in image pixels. w = 40 and w = 10 alone leave a gap
  // at radii of 12-20 px, where the response of either is weak (it fades once the window exceeds about 1.4 R, and
  // a window much shorter than R sees only the innermost rings, the most blurred); the half image fills it for a
  // quarter of the cost of the image's short-window map.
  const int shortMax = m_matchShort.getMaxValue();
  m_shortPeakDetector.setThreshold(std::max(1, static_cast<int>(std::ceil(m_threshold * shortMax))));
  // One scale for every map's peaks: the score (Eq. 5) over its largest value. A landmark big enough for several
  // windows gives a peak in each; the later ones are skipped as inside the first one read. Pixel j of the half image
  // is centred on pixel 2 j + 0.5 of the image.
  auto addPeaks = [&](const vpImage<int> &map, bool half) {
    m_times.matching += elapsedMs(t);
    m_shortPeakDetector.detect(map, m_shortPeaks, m_noRois);
    for (vpSSLPeak p : m_shortPeaks) {
      p.value = static_cast<int>(static_cast<long long>(p.value) * mainMax / shortMax);
      if (half) {
        p.u = 2. * p.u + 0.5;
        p.v = 2. * p.v + 0.5;
      }
      m_peaks.push_back(p);
    }
    m_times.peaks += elapsedMs(t);
  };
  m_matchShort.compute(normalized, m_shortMap);
  addPeaks(m_shortMap, false);
  const int Wh = static_cast<int>(normalized.getWidth() / 2), Hh = static_cast<int>(normalized.getHeight() / 2);
  if (Wh > 0 && Hh > 0) {
    // planCandidateRegions() has made the half image of this frame.
    m_matchShort.compute(m_shortHalf, m_shortHalfMap);
    addPeaks(m_shortHalfMap, true);
  }

  // Strongest first, ties in row-major order: std::sort allocates nothing, and the order is total.
  std::sort(m_peaks.begin(), m_peaks.end(), [](const vpSSLPeak &a, const vpSSLPeak &b) {
    return a.value != b.value ? a.value > b.value : (a.v != b.v ? a.v < b.v : a.u < b.u);
  });
  m_times.peaks += elapsedMs(t);
  const int Wq = Wh / 2, Hq = Hh / 2;
  if (Wq > 0 && Hq > 0) {
    m_shortQuarter.resize(static_cast<unsigned int>(Hq), static_cast<unsigned int>(Wq));
    decimate2(m_shortHalf, nullptr, 0, 0, Wq, Hq, m_shortQuarter);
    m_matchQuarter.compute(m_shortQuarter, m_shortQuarterMap);
    const int quarterMax = m_matchQuarter.getMaxValue();
    m_quarterPeakDetector.setThreshold(std::max(1, static_cast<int>(std::ceil(m_threshold * quarterMax))));
    m_times.matching += elapsedMs(t);
    m_quarterPeakDetector.detect(m_shortQuarterMap, m_shortPeaks, m_noRois);
    // Pixel j of the quarter image is centred on pixel 4 j + 1.5 of the image.
    for (vpSSLPeak p : m_shortPeaks) {
      p.value = static_cast<int>(static_cast<long long>(p.value) * mainMax / quarterMax);
      p.u = 4. * p.u + 1.5;
      p.v = 4. * p.v + 1.5;
      m_peaks.push_back(p);
    }
    m_times.peaks += elapsedMs(t);
  }
}

void vpSSLDetectionPipeline::planCandidateRegions(const vpImage<unsigned char> &normalized)
{
  const int W = static_cast<int>(normalized.getWidth()), H = static_cast<int>(normalized.getHeight());
  const int Wh = W / 2, Hh = H / 2;
  m_shortHalf.resize(static_cast<unsigned int>(Hh), static_cast<unsigned int>(Wh));
  decimate2(normalized, nullptr, 0, 0, Wh, Hh, m_shortHalf);
  m_matchHalf.compute(m_shortHalf, m_halfMap);
  const int threshold =
      std::max(1, static_cast<int>(std::ceil(kCandidateThreshold * m_threshold * m_matchHalf.getMaxValue())));
  const int tw = (W + kCandidateTile - 1) / kCandidateTile, th = (H + kCandidateTile - 1) / kCandidateTile;
  m_activeTiles.assign(static_cast<size_t>(tw) * static_cast<size_t>(th), 0);
  // Every local maximum (3x3, plateaus included) over the threshold: no suppression, which could drop the maximum of
  // a landmark next to a stronger one.
  for (int y = 0; y < Hh; ++y) {
    const int *row = m_halfMap[y];
    for (int x = 0; x < Wh; ++x) {
      // Most of the map is under the threshold: a block of it is passed over on its largest value.
      if ((x & (kCandidateBlock - 1)) == 0) {
        const int end = std::min(Wh, x + kCandidateBlock);
        if (*std::max_element(row + x, row + end) < threshold) {
          x = end - 1;
          continue;
        }
      }
      const int m = row[x];
      if (m < threshold) {
        continue;
      }
      bool maximum = true;
      for (int dy = -1; dy <= 1 && maximum; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx >= 0 && ny >= 0 && nx < Wh && ny < Hh && m_halfMap[ny][nx] > m) {
            maximum = false;
            break;
          }
        }
      }
      if (!maximum) {
        continue;
      }
      // Pixel x of the half image is centred on pixel 2 x + 0.5 of the image.
      const double u = 2. * x + 0.5, v = 2. * y + 0.5;
      const int x0 = std::max(0, static_cast<int>(std::floor((u - kCandidateReach) / kCandidateTile)));
      const int x1 = std::min(tw - 1, static_cast<int>(std::floor((u + kCandidateReach) / kCandidateTile)));
      const int y0 = std::max(0, static_cast<int>(std::floor((v - kCandidateReach) / kCandidateTile)));
      const int y1 = std::min(th - 1, static_cast<int>(std::floor((v + kCandidateReach) / kCandidateTile)));
      for (int ty = y0; ty <= y1; ++ty) {
        std::fill(m_activeTiles.begin() + ty * tw + x0, m_activeTiles.begin() + ty * tw + x1 + 1, 1);
      }
    }
  }
  m_candidateRegions.clear();
  for (int ty = 0; ty < th; ++ty) {
    for (int tx = 0; tx < tw;) {
      if (!m_activeTiles[static_cast<size_t>(ty * tw + tx)]) {
        ++tx;
        continue;
      }
      int end = tx;
      while (end < tw && m_activeTiles[static_cast<size_t>(ty * tw + end)]) {
        ++end;
      }
      const int u0 = tx * kCandidateTile, v0 = ty * kCandidateTile;
      const int u1 = std::min(W, end * kCandidateTile), v1 = std::min(H, (ty + 1) * kCandidateTile);
      m_candidateRegions.push_back(vpRect(u0, v0, u1 - u0, v1 - v0));
      tx = end;
    }
  }
}

bool vpSSLDetectionPipeline::insideFound(double u, double v, int skip) const
{
  // The white paper just outside the outermost black ring continues the pattern by one ring (out to
  // R / sqrt(p), vpSSLRadiusEstimator), so the matching map has a ridge of peaks there too.
  const double margin2 = 1. / getTarget().getP();
  for (size_t i = 0; i < m_landmarks.size(); ++i) {
    if (static_cast<int>(i) == skip) {
      continue;
    }
    const vpSSLLandmark &k = m_landmarks[i];
    const double c = std::cos(k.theta), s = std::sin(k.theta), du = u - k.u, dv = v - k.v;
    const double x = (c * du + s * dv) / k.radius, y = (c * dv - s * du) / k.minorRadius;
    if (x * x + y * y < margin2) {
      return true;
    }
  }
  return false;
}

bool vpSSLDetectionPipeline::selfSimilar(const vpImage<unsigned char> &raw, const vpSSLLandmark &l)
{
  // The rings the rays read must shrink by p all the way in, as far as they are resolved: a bull's-eye of equal
  // rings matches the outer two or three only, and so does a landmark read at R / p where dark surroundings past the
  // white margin continue its pattern on most rays.
  return m_concentricReader.similarity(raw, l) >= kMinSimilarity &&
         !(m_equalRingCheck && m_concentricReader.isEqualRings());
}

bool vpSSLDetectionPipeline::readAllAround(const vpImage<unsigned char> &raw, vpSSLLandmark &l)
{
  // Only a candidate the rays found point-symmetric (a landmark is, under any affine view and symmetric blur;
  // clutter seldom is), from the centre that test settled on; at most the frame's budget (setAllAroundBudget()), the
  // strongest peaks first (a landmark's are among them), which bounds the cost of a frame full of symmetric clutter.
  double u = 0., v = 0.;
  if (m_allAroundLeft == 0 || !m_radiusEstimator.getLastSymmetric(u, v) ||
      insideFound(m_upsample ? 0.5 * (u + 0.5) - 0.5 : u, m_upsample ? 0.5 * (v + 0.5) - 0.5 : v)) {
    return false; // the symmetric centre of a peak on a found landmark's rings is that landmark's
  }
  // Peaks of both windows, and of a landmark's rings, often settle on the same symmetric centre: one read there
  // says what the others would.
  for (const vpImagePoint &p : m_allAroundTried) {
    if (std::fabs(p.get_u() - u) <= kSameCentre && std::fabs(p.get_v() - v) <= kSameCentre) {
      return false;
    }
  }
  --m_allAroundLeft;
  vpSSLLandmark c = l;
  c.u = u;
  c.v = v;
  if (!m_concentricReader.read(raw, c)) {
    m_allAroundTried.push_back(vpImagePoint(v, u));
    return false;
  }
  // The reading's own check of s_p sees the rings about the fitted ellipse; the inner rings that tell a bull's-eye
  // apart are read about the landmark's final centre.
  if (m_equalRingCheck) {
    m_concentricReader.similarity(raw, c);
    if (m_concentricReader.isEqualRings()) {
      m_allAroundTried.push_back(vpImagePoint(v, u));
      return false;
    }
  }
  l = c;
  return true;
}

bool vpSSLDetectionPipeline::completeTarget(const vpImage<unsigned char> &raw)
{
  // The big landmark is read from the farthest, the others, half its size or less, are often missed beside it: their
  // peaks fall under those of the surroundings, or their rings pass no test alone. Where the big one's ellipse puts
  // them, at the size it gives them, they are read again: a reading must land there and at that size.
  const size_t K = getTarget().size();
  const int anchorIndex = m_targetMatch.found ? m_targetMatch.detection[m_bigLandmark] : -1;
  if (anchorIndex < 0 || m_targetMatch.nbMatched >= K) {
    return false;
  }
  const vpSSLLandmark anchor = m_landmarks[static_cast<size_t>(anchorIndex)];
  // The hypotheses: a rotation of the target about the plane's normal, and the big landmark's true size relative to
  // its reading. The rotation comes from a landmark the match holds, else from a detection it left out, else from a
  // scan of the short-window maps.
  Hypothesis hypotheses[kDetectionRotations];
  size_t nbHypotheses = 0;
  for (size_t k = 0; k < K && nbHypotheses == 0; ++k) {
    const int d = m_targetMatch.detection[k];
    if (k != m_bigLandmark && d >= 0) {
      m_prediction.setAnchor(anchor, m_bigLandmark);
      hypotheses[nbHypotheses++] = {m_prediction.rotationTo(m_landmarks[static_cast<size_t>(d)], k), 1.};
    }
  }
  const bool matched = nbHypotheses > 0;
  if (!matched) {
    detectionRotations(anchorIndex, true, hypotheses, nbHypotheses);
  }
  bool changed = false;
  if (tryHypotheses(raw, anchorIndex, hypotheses, nbHypotheses, changed) || matched) {
    return changed;
  }
  scanRotations(anchor, hypotheses, nbHypotheses);
  if (tryHypotheses(raw, anchorIndex, hypotheses, nbHypotheses, changed) || m_targetMatch.nbMatched > 1) {
    return changed;
  }
  // The match took the biggest detection for the big landmark (one alone has no scale): the big landmark may be
  // another one, read at an inner copy (its outer ring cut by the frame's edge or an occlusion) beside the others,
  // of their size.
  for (size_t d = 0; d < m_landmarks.size(); ++d) {
    if (static_cast<int>(d) != anchorIndex) {
      detectionRotations(static_cast<int>(d), false, hypotheses, nbHypotheses);
      if (tryHypotheses(raw, static_cast<int>(d), hypotheses, nbHypotheses, changed)) {
        return changed;
      }
    }
  }
  return changed;
}

bool vpSSLDetectionPipeline::tryHypotheses(const vpImage<unsigned char> &raw, int anchorIndex,
                                           const Hypothesis *hypotheses, size_t nbHypotheses, bool &changed)
{
  const size_t K = getTarget().size();
  const vpSSLLandmark anchor = m_landmarks[static_cast<size_t>(anchorIndex)];
  const int W = static_cast<int>(raw.getWidth()), H = static_cast<int>(raw.getHeight());
  vpSSLLandmark read[kMaxTargetLandmarks];
  for (size_t h = 0; h < nbHypotheses; ++h) {
    const Hypothesis &hyp = hypotheses[h];
    const vpSSLLandmark scaled = scaledLandmark(anchor, hyp.scale);
    m_prediction.setAnchor(scaled, m_bigLandmark);
    size_t nbRead = 0, nbMissing = 0, nbFound = 0;
    for (size_t j = 0; j < K && nbRead < kMaxTargetLandmarks; ++j) {
      if (m_targetMatch.detection[j] >= 0) {
        continue;
      }
      ++nbMissing;
      const vpSSLLandmark p = m_prediction.predict(j, hyp.phi);
      if (!(p.minorRadius >= kMinRadius && p.u >= 0. && p.v >= 0. && p.u <= W - 1. && p.v <= H - 1.)) {
        continue;
      }
      // Already detected there, at its size: the match left it out only because of the big landmark's reading.
      if (hyp.scale != 1. && foundAsPredicted(p, anchorIndex)) {
        ++nbFound;
        continue;
      }
      if (insideFound(p.u, p.v, hyp.scale == 1. ? -1 : anchorIndex)) {
        continue;
      }
      if (readPredicted(raw, p, read[nbRead])) {
        read[nbRead].score = scoreAt(raw, read[nbRead].u, read[nbRead].v);
        ++nbRead;
      }
    }
    // Another size of the big landmark than read is believed only when every landmark it predicts is there.
    if (hyp.scale == 1. ? nbRead == 0 : nbRead + nbFound < nbMissing) {
      continue;
    }
    if (hyp.scale != 1.) {
      // The big landmark read again at its size. A larger one must show its outer rings there: two landmarks beside
      // an inner copy of it (a copy of their size, in an equilateral triangle) are also two of the others beside the
      // third, whose reading at twice its size finds no outer ring. A smaller one is what the landmarks inside the
      // disc read say it is.
      vpSSLLandmark big = scaled;
      if (m_radiusEstimator.estimate(raw, big, scaled) && selfSimilar(raw, big)) {
        big.score = anchor.score;
      } else if (big = scaled, readShaped(raw, big)) {
        big.score = anchor.score;
      } else if (hyp.scale > 1.) {
        continue;
      } else {
        big = scaled;
      }
      m_landmarks[static_cast<size_t>(anchorIndex)] = big;
    }
    bool added = false;
    for (size_t i = 0; i < nbRead; ++i) {
      added = keepLandmark(read[i], raw, raw, true, 1.) || added;
    }
    changed = added || hyp.scale != 1.;
    return true;
  }
  return false;
}

vpSSLLandmark vpSSLDetectionPipeline::scaledLandmark(const vpSSLLandmark &l, double scale)
{
  vpSSLLandmark s = l;
  s.radius *= scale;
  s.minorRadius *= scale;
  for (double &r : s.directionalRadius) {
    r *= scale;
  }
  return s;
}

void vpSSLDetectionPipeline::detectionRotations(int anchorIndex, bool asRead, Hypothesis *hypotheses,
                                                size_t &nbHypotheses)
{
  // A detection the match left out may be one of the target's other landmarks: the match cannot tell which of two
  // equal ones it is beside the big landmark alone, nor pair it with a big landmark read at another size (p times
  // its size where the paper and dark surroundings past the outer ring were read as one more ring; 1 / p where a
  // frame edge or an occlusion cut the outer ring and an inner copy was read). Each label and size under which the
  // detection lies at its predicted place, at its predicted size, is a hypothesis.
  const size_t K = getTarget().size();
  const double p = getTarget().getP();
  const double scales[3] = {p, 1. / p, 1.};
  const vpSSLLandmark anchor = m_landmarks[static_cast<size_t>(anchorIndex)];
  nbHypotheses = 0;
  for (size_t d = 0; d < m_landmarks.size(); ++d) {
    bool matched = static_cast<int>(d) == anchorIndex;
    for (size_t k = 0; k < K; ++k) {
      matched = matched || (k != m_bigLandmark && m_targetMatch.detection[k] == static_cast<int>(d));
    }
    if (matched) {
      continue;
    }
    for (const double scale : scales) {
      if (scale == 1. && !asRead) {
        continue;
      }
      m_prediction.setAnchor(scaledLandmark(anchor, scale), m_bigLandmark);
      for (size_t k = 0; k < K; ++k) {
        if (k == m_bigLandmark || m_targetMatch.detection[k] >= 0 || nbHypotheses == kDetectionRotations) {
          continue;
        }
        // The rotation puts the prediction on the detection's direction; its distance from the big landmark is
        // the identifier's test (perspective stretches the plane beyond the big landmark's ellipse).
        const vpSSLLandmark &l = m_landmarks[d];
        const double phi = m_prediction.rotationTo(l, k);
        const vpSSLLandmark q = m_prediction.predict(k, phi);
        const double ratio = l.radius / q.radius;
        if (ratio >= kPredictedSize && ratio <= 1. / kPredictedSize &&
            std::fabs(m_prediction.distanceRatio(l, k) - 1.) <= kDetectionReach) {
          hypotheses[nbHypotheses++] = {phi, scale};
        }
      }
    }
  }
}

bool vpSSLDetectionPipeline::foundAsPredicted(const vpSSLLandmark &p, int skip) const
{
  for (size_t i = 0; i < m_landmarks.size(); ++i) {
    if (static_cast<int>(i) != skip && asPredicted(m_landmarks[i], p)) {
      return true;
    }
  }
  return false;
}

void vpSSLDetectionPipeline::scanRotations(const vpSSLLandmark &anchor, Hypothesis *hypotheses, size_t &nbHypotheses)
{
  // The rotations whose predicted landmarks the short-window maps answer most strongly, a few far enough apart, for
  // either size of the big landmark. Steps move each predicted centre by at most kRotationStep of its predicted minor
  // semi-axis.
  const size_t K = getTarget().size();
  const double scales[2] = {1., getTarget().getP()};
  m_rotationScore.clear();
  int n[2] = {0, 0};
  for (int si = 0; si < 2; ++si) {
    m_prediction.setAnchor(scaledLandmark(anchor, scales[si]), m_bigLandmark);
    double step = 2. * M_PI;
    for (size_t j = 0; j < K; ++j) {
      const double reach = m_prediction.reach(j);
      if (j != m_bigLandmark && reach > 0.) {
        step = std::min(step, kRotationStep * m_prediction.predict(j, 0.).minorRadius / reach);
      }
    }
    n[si] = std::max(1, std::min(kMaxRotations, static_cast<int>(std::ceil(2. * M_PI / step))));
    for (int i = 0; i < n[si]; ++i) {
      const double phi = 2. * M_PI * i / n[si];
      double score = 0.;
      for (size_t j = 0; j < K; ++j) {
        if (m_targetMatch.detection[j] < 0) {
          score += shortWindowScore(m_prediction.predict(j, phi));
        }
      }
      m_rotationScore.push_back(score);
    }
  }
  nbHypotheses = 0;
  while (nbHypotheses < kPredictedRotations) {
    int best = -1, bestScale = 0;
    size_t index = 0;
    double bestScore = 0.;
    for (int si = 0; si < 2; ++si) {
      for (int i = 0; i < n[si]; ++i, ++index) {
        const double phi = 2. * M_PI * i / n[si];
        bool apart = true;
        for (size_t r = 0; r < nbHypotheses; ++r) {
          apart = apart && (hypotheses[r].scale != scales[si] ||
                            std::fabs(std::remainder(phi - hypotheses[r].phi, 2. * M_PI)) >= kRotationSeparation);
        }
        if (apart && m_rotationScore[index] > bestScore) {
          bestScore = m_rotationScore[index];
          best = i;
          bestScale = si;
        }
      }
    }
    if (best < 0) {
      break;
    }
    hypotheses[nbHypotheses++] = {2. * M_PI * best / n[bestScale], scales[bestScale]};
  }
}

double vpSSLDetectionPipeline::shortWindowScore(const vpSSLLandmark &p) const
{
  const double shortMax = m_matchShort.getMaxValue();
  double best = 0.;
  auto look = [&](const vpImage<int> &map, double u, double v) {
    const int W = static_cast<int>(map.getWidth()), H = static_cast<int>(map.getHeight());
    const int cu = static_cast<int>(std::lround(u)), cv = static_cast<int>(std::lround(v));
    for (int y = std::max(0, cv - 2); y <= std::min(H - 1, cv + 2); ++y) {
      for (int x = std::max(0, cu - 2); x <= std::min(W - 1, cu + 2); ++x) {
        best = std::max(best, map[y][x] / shortMax);
      }
    }
  };
  look(m_shortMap, p.u, p.v);
  // Pixel j of the half image is centred on pixel 2 j + 0.5 of the image.
  look(m_shortHalfMap, 0.5 * (p.u - 0.5), 0.5 * (p.v - 0.5));
  return best;
}

bool vpSSLDetectionPipeline::readShaped(const vpImage<unsigned char> &raw, vpSSLLandmark &l)
{
  if (!m_concentricReader.readAt(raw, l)) {
    return false;
  }
  if (m_equalRingCheck) {
    m_concentricReader.similarity(raw, l);
    return !m_concentricReader.isEqualRings();
  }
  return true;
}

bool vpSSLDetectionPipeline::readPredicted(const vpImage<unsigned char> &raw, const vpSSLLandmark &p, vpSSLLandmark &l)
{
  l = p;
  if (!(m_radiusEstimator.estimate(raw, l, p) && selfSimilar(raw, l))) {
    l = p;
    if (!m_concentricReader.read(raw, l)) {
      l = p;
      if (!m_concentricReader.readAt(raw, l)) {
        return false;
      }
    }
    if (m_equalRingCheck) {
      m_concentricReader.similarity(raw, l);
      if (m_concentricReader.isEqualRings()) {
        return false;
      }
    }
  }
  return asPredicted(l, p);
}

bool vpSSLDetectionPipeline::keepLandmark(vpSSLLandmark &l, const vpImage<unsigned char> &raw,
                                          const vpImage<unsigned char> &normalized, bool rowOnly, double scale)
{
  // Two peaks on the same landmark: keep the stronger one (peaks come strongest first). Most readings of a frame are
  // such repeats: they are dropped before the tests below. Centres and minor semi-axes in image pixels.
  const double u = m_upsample ? 0.5 * (l.u + 0.5) - 0.5 : l.u, v = m_upsample ? 0.5 * (l.v + 0.5) - 0.5 : l.v;
  const double minor = m_upsample ? 0.5 * l.minorRadius : l.minorRadius;
  for (const vpSSLLandmark &k : m_landmarks) {
    if (std::hypot(k.u - u, k.v - v) < 0.5 * std::min(k.minorRadius, minor)) {
      return false;
    }
  }
  // The centre disc of a landmark is two thirds white, so its mean level lies above the outer black ring's while blur
  // leaves the rings resolved; a bull's-eye with a solid dark centre, or a dark blob ringed in light, whose outer rings
  // pass for a landmark's, has it darker than the black ring. A bull's-eye ending in a dark dot inside a wide light
  // ring has that ring far lighter than its core, where a landmark's core (a third white) and the band about the edge
  // at p^2 R (half white) differ by a sixth of the rings' contrast.
  vpSSLCentreTone::Reading centre;
  if (m_equalRingCheck && l.radius >= kToneMinRadius * scale && l.radius < kToneMaxRadius * scale &&
      vpSSLCentreTone::measure(raw, l, getTarget().getP(), centre) &&
      (centre.tone < 0. || (centre.coreMinor >= scale && centre.rise > kMaxRise + centre.riseError))) {
    return false;
  }
  const int su = static_cast<int>(std::lround(l.u)), sv = static_cast<int>(std::lround(l.v));
  const unsigned int maxWindow = static_cast<unsigned int>(1.5 * scale * m_maxRadius);
  if (!m_radiusSweep) {
    l.radiusEq7 = 0.;
  } else if (rowOnly) {
    // The sweep runs along +x on the normalised row of the centre: only that row is normalised.
    const int W = static_cast<int>(raw.getWidth());
    m_sweepRow.resize(1, raw.getWidth());
    const bool inside = sv >= 0 && sv < static_cast<int>(raw.getHeight());
    if (inside) {
      const int first = std::max(0, su);
      if (first < W) {
        vpSSLLookupKernel::applyTable(m_lut, raw[sv] + first, m_sweepRow[0] + first, static_cast<size_t>(W - first));
      }
    }
    l.radiusEq7 = vpSSLRadiusEstimator::sweep(m_sweepRow, m_match, su, inside ? 0 : -1, maxWindow, m_sweep);
  } else {
    l.radiusEq7 = vpSSLRadiusEstimator::sweep(normalized, m_match, su, sv, maxWindow, m_sweep);
  }
  if (m_upsample) {
    l.u = u;
    l.v = v;
    l.radius *= 0.5;
    l.minorRadius = minor;
    l.radiusEq7 *= 0.5;
    for (double &r : l.directionalRadius) {
      r *= 0.5;
    }
  }
  m_landmarks.push_back(l);
  if (!m_lastSearchWasFull) {
    m_planner.fillNearest(l.u, l.v);
  }
  return true;
}

void vpSSLDetectionPipeline::rereadPredicted(const vpImage<unsigned char> &raw, double scale)
{
  // A region of interest is centred on a predicted landmark (paper Sec. 4.1). When a landmark of the previous
  // frame lies near that prediction, it is re-read straight from there: symmetry centring (+-3 px per step),
  // then its rings around its previous ellipse. This needs no matching at all, the dearest stage of a tracking
  // frame; a region whose landmark moved further, changed size or is not read is matched as in the paper.
  const std::vector<vpRect> &rois = m_planner.getRegions();
  for (size_t k = 0; k < rois.size(); ++k) {
    const vpRect &r = rois[k];
    const double cu = r.getLeft() + 0.5 * r.getWidth(), cv = r.getTop() + 0.5 * r.getHeight();
    const vpSSLLandmark *prior = m_planner.previousNear(cu, cv);
    if (prior == nullptr || m_planner.isFilled(k)) {
      m_planner.defer(k);
      continue;
    }
    vpSSLLandmark scaled = *prior, l;
    l.u = cu;
    l.v = cv;
    if (m_upsample) {
      scaled.u = 2. * scaled.u + 0.5;
      scaled.v = 2. * scaled.v + 0.5;
      scaled.radius *= 2.;
      scaled.minorRadius *= 2.;
      l.u = 2. * l.u + 0.5;
      l.v = 2. * l.v + 0.5;
    }
    if (!m_radiusEstimator.estimate(raw, l, scaled)) {
      m_planner.defer(k);
      continue;
    }
    l.score = scoreAt(raw, l.u, l.v);
    if (keepLandmark(l, raw, raw, true, scale)) {
      m_planner.fill(k);
    } else {
      m_planner.defer(k);
    }
  }
}

double vpSSLDetectionPipeline::scoreAt(const vpImage<unsigned char> &I, double u, double v) const
{
  // The map's value (Eq. 5, full resolution) at the centre read, over its largest value.
  const int W = static_cast<int>(I.getWidth()), H = static_cast<int>(I.getHeight());
  const int cu = std::min(W - 1, std::max(0, static_cast<int>(std::lround(u))));
  const int cv = std::min(H - 1, std::max(0, static_cast<int>(std::lround(v))));
  return std::max(0., std::min(1., static_cast<double>(fullResolutionMatch(I, cu, cv)) / m_match.getMaxValue()));
}

void vpSSLDetectionPipeline::clearMap(const vpImage<unsigned char> &I, MatchMap &map)
{
  // The map must be zero outside the regions (getMatchingMap()). Clearing it all at every tracking frame cost as
  // much as matching the regions of a decimated frame: only what the last call wrote is cleared (the boxes
  // vpSSLMatchingFunction writes: each rectangle's pixels, clipped to the image).
  const int W = static_cast<int>(I.getWidth()), H = static_cast<int>(I.getHeight());
  if (map.allWritten || map.map.getWidth() != I.getWidth() || map.map.getHeight() != I.getHeight()) {
    map.map.resize(I.getHeight(), I.getWidth());
    std::fill(map.map.bitmap, map.map.bitmap + map.map.getSize(), 0);
  } else {
    for (const vpRect &r : map.written) {
      const double u0 = std::ceil(std::max(0., r.getLeft())), v0 = std::ceil(std::max(0., r.getTop()));
      const double u1 = std::floor(std::min(W - 1., r.getRight())), v1 = std::floor(std::min(H - 1., r.getBottom()));
      if (!(u0 <= u1 && v0 <= v1)) {
        continue; // outside the image: nothing was written
      }
      for (int v = static_cast<int>(v0); v <= static_cast<int>(v1); ++v) {
        std::fill(map.map[v] + static_cast<int>(u0), map.map[v] + static_cast<int>(u1) + 1, 0);
      }
    }
  }
  map.written.clear();
  map.allWritten = false;
}

void vpSSLDetectionPipeline::matchRegions(const vpSSLMatchingFunction &match, const vpImage<unsigned char> &I,
                                          const std::vector<vpRect> &rois, MatchMap &map)
{
  clearMap(I, map);
  map.allWritten = true; // until computeInside() has returned (it throws on a non-finite rectangle)
  match.computeInside(I, rois, map.map);
  map.written.assign(rois.begin(), rois.end());
  map.allWritten = false;
}

int vpSSLDetectionPipeline::fullResolutionMatch(const vpImage<unsigned char> &I, int u, int v) const
{
  // Eq. 5 at one pixel on the normalised image (through the table), exactly as the full-resolution map.
  const int w = static_cast<int>(m_match.getWindow());
  const int W = static_cast<int>(I.getWidth()), H = static_cast<int>(I.getHeight());
  const std::ptrdiff_t steps[4] = {1, -1, static_cast<std::ptrdiff_t>(W), -static_cast<std::ptrdiff_t>(W)};
  const bool valid[4] = {u + w < W, u >= w, v + w < H, v >= w};
  const unsigned char *p = I.bitmap + static_cast<std::ptrdiff_t>(v) * W + u;
  bool any = false;
  int best = 0;
  for (int d = 0; d < 4; ++d) {
    if (!valid[d]) {
      continue;
    }
    const std::ptrdiff_t step = steps[d];
    int sum = 0;
    for (int xi = 1; xi <= w; ++xi) {
      const int c = m_lut[p[xi * step]], a = m_lut[p[m_offsetA[xi] * step]], b = m_lut[p[m_offsetB[xi] * step]];
      sum += std::abs(c - a) - std::abs(c - b);
    }
    best = any ? std::max(best, sum) : sum;
    any = true;
  }
  return best;
}

void vpSSLDetectionPipeline::normalizeCross(const vpImage<unsigned char> &I, int u0, int v0, int reach)
{
  // The pixels Eq. 5 reads for every centre within reach of (u0, v0): rows v0 +- reach over the columns the
  // horizontal directions read, and columns u0 +- reach over the rows the vertical ones read (stored column by
  // column, so that a vertical sum reads contiguous bytes), through the normalisation table.
  const int w = static_cast<int>(m_match.getWindow());
  const int W = static_cast<int>(I.getWidth()), H = static_cast<int>(I.getHeight());
  m_crossU0 = std::max(0, u0 - reach - w);
  m_crossV0 = std::max(0, v0 - reach);
  m_crossW = std::min(W, u0 + reach + w + 1) - m_crossU0;
  const int rows = std::min(H, v0 + reach + 1) - m_crossV0;
  m_crossRows.resize(static_cast<size_t>(std::max(0, rows) * std::max(0, m_crossW)));
  for (int y = 0; y < rows; ++y) {
    const unsigned char *src = I[m_crossV0 + y] + m_crossU0;
    unsigned char *dst = m_crossRows.data() + static_cast<size_t>(y) * m_crossW;
    for (int x = 0; x < m_crossW; ++x) {
      dst[x] = m_lut[src[x]];
    }
  }
  m_crossCu0 = std::max(0, u0 - reach);
  m_crossCv0 = std::max(0, v0 - reach - w);
  m_crossH = std::min(H, v0 + reach + w + 1) - m_crossCv0;
  const int cols = std::min(W, u0 + reach + 1) - m_crossCu0;
  m_crossCols.resize(static_cast<size_t>(std::max(0, cols) * std::max(0, m_crossH)));
  for (int y = 0; y < m_crossH; ++y) {
    const unsigned char *src = I[m_crossCv0 + y] + m_crossCu0;
    for (int x = 0; x < cols; ++x) {
      m_crossCols[static_cast<size_t>(x) * m_crossH + y] = m_lut[src[x]];
    }
  }
}

int vpSSLDetectionPipeline::crossMatch(int u, int v) const
{
  // fullResolutionMatch() on the copies of normalizeCross(): the same integers, without a table look-up per sample.
  const int w = static_cast<int>(m_match.getWindow());
  const bool valid[4] = {u + w < m_imageW, u >= w, v + w < m_imageH, v >= w};
  const unsigned char *row =
      m_crossRows.data() + static_cast<std::ptrdiff_t>(v - m_crossV0) * m_crossW + (u - m_crossU0);
  const unsigned char *col =
      m_crossCols.data() + static_cast<std::ptrdiff_t>(u - m_crossCu0) * m_crossH + (v - m_crossCv0);
  bool any = false;
  int best = 0;
  for (int d = 0; d < 4; ++d) {
    if (!valid[d]) {
      continue;
    }
    const unsigned char *p = d < 2 ? row : col;
    const int step = (d & 1) == 0 ? 1 : -1;
    int sum = 0;
    for (int xi = 1; xi <= w; ++xi) {
      const int c = p[xi * step], a = p[m_offsetA[xi] * step], b = p[m_offsetB[xi] * step];
      sum += std::abs(c - a) - std::abs(c - b);
    }
    best = any ? std::max(best, sum) : sum;
    any = true;
  }
  return best;
}

bool vpSSLDetectionPipeline::refinePeak(const vpImage<unsigned char> &I, vpSSLPeak &peak, bool grid)
{
  // Hill climbing on the full-resolution map from the decimated peak, each value computed once.
  const int W = static_cast<int>(I.getWidth()), H = static_cast<int>(I.getHeight());
  const int kReach = 8, kSize = 2 * kReach + 1;
  int cache[kSize * kSize];
  std::fill(cache, cache + kSize * kSize, std::numeric_limits<int>::min());
  const int u0 = std::min(W - 1, std::max(0, static_cast<int>(std::lround(peak.u))));
  const int v0 = std::min(H - 1, std::max(0, static_cast<int>(std::lround(peak.v))));
  // Up to a few dozen evaluations within kReach: the pixels they read are normalised once.
  m_imageW = W;
  m_imageH = H;
  normalizeCross(I, u0, v0, kReach);
  auto M = [&](int u, int v) {
    int &m = cache[(v - v0 + kReach) * kSize + (u - u0 + kReach)];
    if (m == std::numeric_limits<int>::min()) {
      m = crossMatch(u, v);
    }
    return m;
  };
  // The full-resolution map is bumpy near a landmark's centre (Eq. 5 takes the best of four directions):
  // climbing from the decimated peak alone can stop on a secondary maximum a few pixels off, from which the
  // ring reading does not find the centre. A 2-pixel grid over the decimated peak's uncertainty first.
  int u = u0, v = v0, best = std::numeric_limits<int>::min();
  for (int dv = -4; dv <= 4 && grid; dv += 2) {
    for (int du = -4; du <= 4; du += 2) {
      const int gu = u0 + du, gv = v0 + dv;
      if (gu >= 0 && gv >= 0 && gu < W && gv < H && M(gu, gv) > best) {
        best = M(gu, gv);
        u = gu;
        v = gv;
      }
    }
  }
  for (;;) {
    const int m = M(u, v);
    int bu = u, bv = v, bm = m;
    for (int dv = -1; dv <= 1; ++dv) {
      for (int du = -1; du <= 1; ++du) {
        const int nu = u + du, nv = v + dv;
        if ((du == 0 && dv == 0) || nu < 0 || nv < 0 || nu >= W || nv >= H) {
          continue;
        }
        const int n = M(nu, nv);
        // As the peak detector: one pixel per plateau, the last in row-major order.
        const bool later = dv > 0 || (dv == 0 && du > 0);
        if (later ? n >= bm : n > bm) {
          bm = n;
          bu = nu;
          bv = nv;
        }
      }
    }
    if (bu == u && bv == v) {
      break;
    }
    u = bu;
    v = bv;
    if (std::abs(u - u0) >= kReach || std::abs(v - v0) >= kReach) {
      return false; // no maximum near the decimated peak
    }
  }
  const int m = M(u, v);
  if (m < std::max(1, static_cast<int>(std::ceil(m_threshold * m_match.getMaxValue())))) {
    return false;
  }
  // The same full-resolution maximum reached from another decimated peak has been read already.
  if (grid) {
    for (const vpImagePoint &r : m_refined) {
      if (r.get_u() == u && r.get_v() == v) {
        return false;
      }
    }
    m_refined.push_back(vpImagePoint(v, u));
  }
  auto parabola = [](double a, double b, double c) {
    const double den = a - 2. * b + c;
    return den >= 0. ? 0. : std::max(-0.5, std::min(0.5, 0.5 * (a - c) / den));
  };
  peak.u = u;
  peak.v = v;
  peak.value = m;
  if (u > 0 && u < W - 1) {
    peak.u += parabola(M(u - 1, v), m, M(u + 1, v));
  }
  if (v > 0 && v < H - 1) {
    peak.v += parabola(M(u, v - 1), m, M(u, v + 1));
  }
  return true;
}
