/*
  Private to vpSSLDetector: the stages of one frame (normalisation, matching, peaks, ring reading, identification),
  over the whole image or the regions of interest that vpSSLRegionPlanner plans.
*/
#ifndef VP_SSL_DETECTION_PIPELINE_H
#define VP_SSL_DETECTION_PIPELINE_H

#include <chrono>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpImagePoint.h>

#include "vpSSLImageBuffer.h"
#include <visp3/core/vpRect.h>
#include <visp3/ssl/vpSSLBrightnessNormalizer.h>
#include <visp3/ssl/vpSSLConcentricReader.h>
#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl/vpSSLLandmark.h>
#include <visp3/ssl/vpSSLMatchingFunction.h>
#include <visp3/ssl/vpSSLPeakDetector.h>
#include <visp3/ssl/vpSSLRadiusEstimator.h>
#include <visp3/ssl/vpSSLTargetIdentifier.h>

#include "vpSSLRegionPlanner.h"
#include "vpSSLTargetPrediction.h"

/*
  The settings and the working storage of vpSSLDetector's detection, and its results. Every setting and result
  is the one vpSSLDetector documents under the same name.
*/
class vpSSLDetectionPipeline
{
public:
  explicit vpSSLDetectionPipeline(const vpSSLTarget &target);

  // Detects the landmarks and identifies the target in \e I: the whole image without regions of interest, else
  // the regions (vpSSLDetector::setRegionsOfInterest()).
  void detect(const vpImage<unsigned char> &I);

  void setWindow(unsigned int w);
  void setThreshold(double threshold);
  void setBrightnessNormalization(bool enable) { m_normalize = enable; }
  void setNbThreads(unsigned int n)
  {
    m_match.setNbThreads(n);
    m_matchCoarse.setNbThreads(n);
    m_matchShort.setNbThreads(n);
    m_matchHalf.setNbThreads(n);
    m_matchQuarter.setNbThreads(n);
  }
  void setDecimation(unsigned int decimation);
  void setMaxRadius(double r);
  void setRadiusSweep(bool enable) { m_radiusSweep = enable; }
  void setSmallLandmarkMode(bool enable);
  void setEqualRingCheck(bool enable) { m_equalRingCheck = enable; }
  void setBlurredRingModel(bool enable) { m_concentricReader.setBlurredRingModel(enable); }
  void setTargetCompletion(bool enable) { m_targetCompletion = enable; }
  void setAllAroundBudget(unsigned int candidates);
  void setShortWindow(unsigned int w);
  void setRegionsOfInterest(const std::vector<vpRect> &rois) { m_planner.setRegions(rois); }

  unsigned int getWindow() const { return m_window; }
  double getThreshold() const { return m_threshold; }
  bool getBrightnessNormalization() const { return m_normalize; }
  unsigned int getDecimation() const { return m_decimation; }
  bool getRadiusSweep() const { return m_radiusSweep; }
  bool getSmallLandmarkMode() const { return m_upsample; }
  bool getEqualRingCheck() const { return m_equalRingCheck; }
  bool getBlurredRingModel() const { return m_concentricReader.getBlurredRingModel(); }
  bool getTargetCompletion() const { return m_targetCompletion; }
  unsigned int getAllAroundBudget() const { return m_allAroundBudget; }
  unsigned int getShortWindow() const { return m_shortWindow; }
  const vpSSLTarget &getTarget() const { return m_identifier.getTarget(); }
  bool getLastSearchWasFull() const { return m_lastSearchWasFull; }

  const std::vector<vpSSLLandmark> &getLandmarks() const { return m_landmarks; }
  const vpSSLTargetMatch &getTargetMatch() const { return m_targetMatch; }
  vpSSLDetectorTimes &getTimes() { return m_times; }
  const vpSSLDetectorTimes &getTimes() const { return m_times; }
  const vpImage<int> &getMatchingMap() const { return m_mainMap.map; }
  const vpSSLMatchingFunction &getMatchingFunction() const { return m_match; }
  const vpSSLRegionPlanner &getPlanner() const { return m_planner; }
  // Where the last full search at full resolution computed the map (planCandidateRegions()).
  const std::vector<vpRect> &getCandidateRegions() const { return m_candidateRegions; }

private:
  // A matching map and the regions the last tracking frame wrote into it (the rest is 0).
  struct MatchMap
  {
    vpSSLImageBuffer<int> map;
    std::vector<vpRect> written;
    bool allWritten = true; // whether the last call wrote the whole map (or it is uninitialised)
  };

  // Normalisation, matching and peaks of the whole image (\e regions nullptr) or of regions, at full resolution or
  // on the image decimated twice (\e coarse), then the ring reading of the peaks; the stage times are added up.
  void searchRegions(const vpImage<unsigned char> &I, const vpImage<unsigned char> &raw, bool coarse,
                     const std::vector<vpRect> *regions, double scale, std::chrono::steady_clock::time_point &t);
  // Whether (u, v) (image pixels) lies within R / sqrt(p) of a landmark found this frame, but landmark \e skip.
  bool insideFound(double u, double v, int skip = -1) const;
  // Whether the ring profile inside \e l's outer ellipse follows s_p (vpSSLConcentricReader::similarity()).
  bool selfSimilar(const vpImage<unsigned char> &raw, const vpSSLLandmark &l);
  // Where the rays' reading rejects a point-symmetric candidate: vpSSLConcentricReader from its symmetric centre.
  bool readAllAround(const vpImage<unsigned char> &raw, vpSSLLandmark &l);
  // Full search at full resolution, once the target is identified: reads the target's landmarks that the match
  // lacks where the big landmark's ellipse puts them (vpSSLTargetPrediction); whether it added any.
  bool completeTarget(const vpImage<unsigned char> &raw);
  // A rotation of the target in the rectified image (rad) and the big landmark's size over its reading.
  struct Hypothesis
  {
    double phi;
    double scale;
  };
  // completeTarget(): reads the landmarks each hypothesis predicts, in turn, and keeps those of the first one they
  // bear out (\e changed: whether it added a landmark or resized the big one); whether one did.
  bool tryHypotheses(const vpImage<unsigned char> &raw, int anchorIndex, const Hypothesis *hypotheses,
                     size_t nbHypotheses, bool &changed);
  // vpSSLConcentricReader::readAt() on \e l's ellipse, then the equal-ring check: whether \e l was read.
  bool readShaped(const vpImage<unsigned char> &raw, vpSSLLandmark &l);
  // completeTarget() without a second landmark matched: the rotations and sizes of the big landmark, read as the
  // detection \e anchorIndex, under which a detection the match left out is one of the target's other landmarks, at
  // its place and of its size; the size as read among them only if \e asRead.
  void detectionRotations(int anchorIndex, bool asRead, Hypothesis *hypotheses, size_t &nbHypotheses);
  // Whether a detection but landmark \e skip lies where \e p is predicted and is of its size.
  bool foundAsPredicted(const vpSSLLandmark &p, int skip) const;
  // completeTarget() without any: the best rotations scanned, for either size of the big landmark.
  void scanRotations(const vpSSLLandmark &anchor, Hypothesis *hypotheses, size_t &nbHypotheses);
  // \e l with its outer ellipse scaled by \e scale.
  static vpSSLLandmark scaledLandmark(const vpSSLLandmark &l, double scale);
  // The short-window maps' strongest value (over their largest) within 2 px of \e p's centre.
  double shortWindowScore(const vpSSLLandmark &p) const;
  // Reads the landmark predicted as \e p (rays within 11 % of its ellipse, else all around from its centre) into
  // \e l: whether one passes the checks of a full search, near \e p's centre and of \e p's size.
  bool readPredicted(const vpImage<unsigned char> &raw, const vpSSLLandmark &p, vpSSLLandmark &l);
  // Sets \e map to I's size and to 0 where the last call wrote it.
  void clearMap(const vpImage<unsigned char> &I, MatchMap &map);
  void matchRegions(const vpSSLMatchingFunction &match, const vpImage<unsigned char> &I,
                    const std::vector<vpRect> &rois, MatchMap &map);
  int fullResolutionMatch(const vpImage<unsigned char> &I, int u, int v) const;
  void normalizeCross(const vpImage<unsigned char> &I, int u0, int v0, int reach);
  int crossMatch(int u, int v) const;
  bool refinePeak(const vpImage<unsigned char> &I, vpSSLPeak &peak, bool grid);
  // Eq. 7 sweep, back to image pixels, duplicate check; adds the landmark and fills its region. \e rowOnly: only
  // the sweep's row is normalised (else \e normalized is the whole normalised image).
  bool keepLandmark(vpSSLLandmark &l, const vpImage<unsigned char> &raw, const vpImage<unsigned char> &normalized,
                    bool rowOnly, double scale);
  // Tracking frame: re-reads each region's previous landmark from the region's centre; the regions left are
  // deferred to the matching (vpSSLRegionPlanner::getPending()).
  void rereadPredicted(const vpImage<unsigned char> &raw, double scale);
  double scoreAt(const vpImage<unsigned char> &I, double u, double v) const;
  // Full search at full resolution: adds the strongest peaks of the short window's maps of the normalised image and
  // of its half to m_peaks (values on the scale of the main window's, \e mainMax) and sorts them all, strongest first;
  // then appends the strongest of the quarter's map (kQuarterWindow).
  void addShortWindowPeaks(const vpImage<unsigned char> &normalized, int mainMax,
                           std::chrono::steady_clock::time_point &t);
  // Full search at full resolution: the regions where w is computed, around the candidates of w / 2 on the normalised
  // image's half (m_shortHalf, computed here); m_candidateRegions holds them.
  void planCandidateRegions(const vpImage<unsigned char> &normalized);

  vpSSLBrightnessNormalizer m_normalizer;
  vpSSLMatchingFunction m_match;
  vpSSLPeakDetector m_peakDetector;
  vpSSLRadiusEstimator m_radiusEstimator;
  vpSSLConcentricReader m_concentricReader;
  unsigned int m_allAroundBudget = 0;         // candidates vpSSLConcentricReader may read per frame
  unsigned int m_allAroundLeft = 0;           // of which it may still read this frame
  std::vector<vpImagePoint> m_allAroundTried; // centres it read nothing at this frame
  vpSSLTargetIdentifier m_identifier;
  vpSSLTargetPrediction m_prediction;
  size_t m_bigLandmark = 0;            // the target's biggest landmark, the anchor of completeTarget()
  std::vector<double> m_rotationScore; // completeTarget(): the short-window score of each rotation scanned
  bool m_normalize;
  bool m_upsample;
  unsigned int m_window;
  unsigned int m_decimation;
  vpSSLMatchingFunction m_matchCoarse; // window 0.35 w, on the decimated image
  unsigned int m_shortWindow;          // 0: no short-window map
  vpSSLMatchingFunction m_matchShort;  // the short window, full searches at full resolution
  vpSSLPeakDetector m_shortPeakDetector;
  vpSSLMatchingFunction m_matchHalf;       // w / 2 on the normalised image's half: where w is worth computing
  vpSSLImageBuffer<int> m_halfMap;         // its map
  vpSSLMatchingFunction m_matchQuarter;    // kQuarterWindow on the normalised image's quarter: large radii
  vpSSLPeakDetector m_quarterPeakDetector; // its strongest peaks
  std::vector<char> m_activeTiles;         // tiles of the image where w is computed
  std::vector<vpRect> m_candidateRegions;  // those tiles, merged along each row of tiles
  double m_maxRadius;
  bool m_radiusSweep;
  bool m_equalRingCheck;
  bool m_targetCompletion = true;
  double m_threshold;
  vpSSLRegionPlanner m_planner;
  std::vector<vpRect> m_noRois; // always empty: the whole image
  bool m_lastSearchWasFull;

  vpSSLImageBuffer<unsigned char> m_normalized;
  vpSSLImageBuffer<unsigned char> m_upsampled;
  vpSSLImageBuffer<unsigned char> m_decimated; // normalised, decimated image (decimation 2)
  vpSSLImageBuffer<unsigned char> m_sweepRow;  // one normalised full-resolution row, for the Eq. 7 sweep
  unsigned char m_lut[256];                    // normalisation table of the last frame
  int m_offsetA[129], m_offsetB[129];          // a_xi, b_xi of the full-resolution window (refinePeak())
  std::vector<vpImagePoint> m_refined;         // full-resolution peaks already read this frame
  // Normalised pixels around a decimated peak (refinePeak()): rows (row-major) and columns (column-major).
  std::vector<unsigned char> m_crossRows, m_crossCols;
  int m_crossU0 = 0, m_crossV0 = 0, m_crossW = 0, m_crossCu0 = 0, m_crossCv0 = 0, m_crossH = 0;
  int m_imageW = 0, m_imageH = 0;
  std::vector<vpRect> m_scaledRois;
  MatchMap m_mainMap;   // the map of getMatchingMap()
  MatchMap m_coarseMap; // the decimated regions of a full-resolution tracking frame
  std::vector<vpSSLPeak> m_peaks;
  std::vector<vpSSLPeak> m_shortPeaks;
  vpSSLImageBuffer<int> m_shortMap;               // the short window's map of the image
  vpSSLImageBuffer<unsigned char> m_shortHalf;    // the normalised image's half (2x2 averages)
  vpSSLImageBuffer<int> m_shortHalfMap;           // the short window's map of m_shortHalf
  vpSSLImageBuffer<unsigned char> m_shortQuarter; // the normalised image's quarter (2x2 averages of m_shortHalf)
  vpSSLImageBuffer<int> m_shortQuarterMap;        // m_matchQuarter's map of m_shortQuarter
  std::vector<vpSSLLandmark> m_landmarks;
  std::vector<int> m_sweep; // Eq. 7 sweep, reused
  vpSSLTargetMatch m_targetMatch;
  vpSSLDetectorTimes m_times;
};

#endif
