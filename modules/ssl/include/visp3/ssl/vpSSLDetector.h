/*!
  \file vpSSLDetector.h
  \brief Self-similar landmark and target detector, a vpDetectorBase.
*/
#ifndef VP_SSL_DETECTOR_H
#define VP_SSL_DETECTOR_H

#include <chrono>
#include <string>
#include <vector>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpRect.h>
#include <visp3/detection/vpDetectorBase.h>
#include <visp3/ssl/vpSSLBrightnessNormalizer.h>
#include <visp3/ssl/vpSSLConcentricReader.h>
#include <visp3/ssl/vpSSLLandmark.h>
#include <visp3/ssl/vpSSLMatchingFunction.h>
#include <visp3/ssl/vpSSLPeakDetector.h>
#include <visp3/ssl/vpSSLRadiusEstimator.h>
#include <visp3/ssl/vpSSLTargetIdentifier.h>
#include <visp3/visual_features/vpFeaturePoint.h>

/*!
  \struct vpSSLDetectorTimes
  \ingroup group_ssl
  \brief Time spent by each stage of the last detect() call, in milliseconds.
*/
struct VISP_SSL_EXPORT vpSSLDetectorTimes
{
  double normalization = 0.;  ///< Brightness normalisation.
  double matching = 0.;       ///< Matching map (Eq. 5).
  double peaks = 0.;          ///< Peak detection.
  double radius = 0.;         ///< Ring reading, radius and centre refinement (Eq. 7).
  double identification = 0.; ///< Target identification.
  double total = 0.;          ///< Whole detect().
};

/*!
  \class vpSSLDetector
  \ingroup group_ssl
  \brief Detects circular self-similar landmarks and identifies the target among them.

  The pipeline follows the paper: brightness normalisation (Sec. 5), the four-direction matching
  function (Eq. 5) over the image or inside regions of interest (Sec. 4.1), its local maxima over a
  threshold (Sec. 3.1), the apparent radius at each (Eq. 7) and the target identification (Sec. 3.2).

  Each detected landmark is an object of vpDetectorBase: its polygon is the outer ellipse (16
  vertices), its message is "<target> <label>" for a landmark of the target ("ssl3-a3 B") and "ssl"
  for any other landmark.

  \code
  #include <visp3/ssl/vpSSLDetector.h>

  vpSSLDetector detector;                       // ssl3-a3, w = 40
  if (detector.detect(I)) {
    for (const vpSSLLandmark &l : detector.getLandmarks())
      std::cout << l.u << " " << l.v << " r=" << l.radius << std::endl;
    if (detector.getTargetMatch().found) {
      std::vector<vpFeaturePoint> s = detector.getFeaturePoints(cam);
    }
  }
  \endcode
  See tutorial-ssl-detector.cpp.
*/
class VISP_SSL_EXPORT vpSSLDetector : public vpDetectorBase
{
public:
  //! Detector for \e target (default ssl3-a3).
  explicit vpSSLDetector(const vpSSLTarget &target = vpSSLTarget::ssl3a3());

  /*!
    Detects the landmarks and identifies the target in \e I.
    \return true if at least one landmark was found.
    \exception vpException on an empty image, or one whose size does not match its buffer or exceeds the limits
    of vpSSLInputLimits::checkImage() (16384 px a side, 2^26 pixels).
  */
  bool detect(const vpImage<unsigned char> &I) override;

  //! Window length w of the matching function (default 40, paper Sec. 2.1).
  void setWindow(unsigned int w);
  //! Score threshold in [0, 1] on the normalised matching value at a peak (default 0.10).
  void setThreshold(double threshold);
  //! Brightness normalisation before matching (default on, paper Fig. 13).
  void setBrightnessNormalization(bool enable) { m_normalize = enable; }
  //! Worker threads of the matching function (0: all cores).
  void setNbThreads(unsigned int n)
  {
    m_match.setNbThreads(n);
    m_matchCoarse.setNbThreads(n);
  }
  /*!
    Decimation of the matching pass, like AprilTag's quad decimate (default 1). With 2, the candidates are
    searched on the image decimated twice (2x2 box average) with a window of 0.35 w, then each is moved to the
    full-resolution maximum of the map nearby and the rings are read at full resolution as before, so centres
    and radii keep their full-resolution accuracy; the normalisation table comes from a sparse histogram and
    only the decimated pixels that are matched are normalised. About 2x faster at 640x480 (a tenth of the
    matching cost), and every landmark of the documented envelope (smaller semi-axis >= 25 px for w = 40) is
    found, but landmarks of 14-20 px, which the full-resolution pass still often finds on sharp images, are
    mostly lost: hence not the default. With 1, the whole pipeline runs at full resolution (the map of the
    reference matching function). The small-landmark mode ignores this setting (it matches on the upsampled
    image).
    \exception vpException unless 1 or 2.
  */
  void setDecimation(unsigned int decimation);
  //! Decimation of the matching pass (1 or 2).
  unsigned int getDecimation() const { return m_decimation; }
  //! Largest apparent radius searched (px, default 300).
  void setMaxRadius(double r);
  /*!
    Whether each landmark also gets the paper's Eq. 7 estimate, vpSSLLandmark::radiusEq7 (default off: it is a
    second, less accurate radius, kept to compare with the paper's Fig. 4-5; vpSSLLandmark::radius is the one to
    use). When off, radiusEq7 is 0 and the sweep costs nothing.
  */
  void setRadiusSweep(bool enable) { m_radiusSweep = enable; }
  //! Whether the Eq. 7 sweep is computed (setRadiusSweep()).
  bool getRadiusSweep() const { return m_radiusSweep; }
  /*!
    Small-landmark mode (default off). The discrete matching function needs rings of a few pixels and a
    window not much larger than 1.4 times the apparent radius (beyond it the white paper around the
    landmark adds negative terms to Eq. 2), so with w = 40 at full resolution the centre of a landmark
    whose smaller semi-axis is below about 25 px is no longer a peak. This mode matches on the image
    upsampled twice (bilinear) with a window of 20, which finds landmarks down to 8 px of radius (a
    0.1 m landmark at 8 m through a 640x480 camera of 640 px focal length) for about twice the
    matching cost. Coordinates and radii are reported in the original image.
  */
  void setSmallLandmarkMode(bool enable);
  //! Whether the small-landmark mode is on.
  bool getSmallLandmarkMode() const { return m_upsample; }
  /*!
    Restricts the next detections to these rectangles (empty: whole image), each centred on a predicted
    landmark (paper Sec. 4.1: vpSSLTracker centres them on its prediction). In these tracking frames:
    - a landmark of the previous frame whose centre lies within half its smaller semi-axis of a rectangle's
      centre is first re-read straight from that centre (symmetry centring, then its rings around its previous
      ellipse), without any matching; its score is then the full-resolution map at its centre (a full search
      reports the maximum of the map nearby, which may be a little higher);
    - the other rectangles, and those where that re-reading fails, are matched and searched for peaks. Landmarks
      whose centre lies inside such a rectangle are found as long as the rectangle extends w around them. Only
      the pixels this matching reads are normalised (with the table of the whole image, so that the map is the
      one a full search gives there), and a landmark of the previous frame near a peak is re-read around its
      previous ellipse; with setDecimation(2) that re-reading starts from the decimated peak;
    - at full resolution (setDecimation(1)), a rectangle whose predicted landmark (the previous frame's landmark
      inside it, nearest its centre) has a smaller semi-axis of 0.625 w or more (25 px for w = 40: the envelope of
      the decimated pass) is matched on the image decimated twice, as with setDecimation(2), a tenth of the work;
      if no landmark is read there, it is matched again at full resolution.
    getMatchingMap() is 0 outside the rectangles matched at its resolution (getMapRegions()).
  */
  void setRegionsOfInterest(const std::vector<vpRect> &rois);
  /*!
    Regions of interest that the last tracking frame matched: those whose landmark was not re-read from their
    centre (setRegionsOfInterest()). Empty after a full search.
  */
  const std::vector<vpRect> &getMatchedRegions() const { return m_pendingRois; }
  /*!
    Regions of the last tracking frame matched at the resolution of getMatchingMap(): getMatchedRegions() but for
    those of a full-resolution detector (setDecimation(1)) whose predicted landmark was matched, and read, on the
    decimated image (setRegionsOfInterest()). Empty after a full search.
  */
  const std::vector<vpRect> &getMapRegions() const { return m_mapRois; }
  /*!
    Full-search period n of the tracking mode (default 10, paper Sec. 4.1): while regions of interest
    are set, every n-th detect() call (the n-th, 2n-th, ... since the regions were first set) searches
    the whole image instead, so that a landmark outside the regions is found again. 0: never; 1: always.
  */
  void setFullSearchPeriod(unsigned int n) { m_fullSearchPeriod = n; }
  //! Full-search period of the tracking mode.
  unsigned int getFullSearchPeriod() const { return m_fullSearchPeriod; }
  //! Whether the last detect() searched the whole image (always true without regions of interest).
  bool getLastSearchWasFull() const { return m_lastSearchWasFull; }

  unsigned int getWindow() const { return m_window; }                       ///< Window length w (at full resolution).
  double getThreshold() const { return m_threshold; }                       ///< Score threshold.
  bool getBrightnessNormalization() const { return m_normalize; }           ///< Whether normalisation is on.
  const vpSSLTarget &getTarget() const { return m_identifier.getTarget(); } ///< Target model.

  //! Landmarks of the last detection, best score first.
  const std::vector<vpSSLLandmark> &getLandmarks() const { return m_landmarks; }
  //! Target identified in the last detection.
  const vpSSLTargetMatch &getTargetMatch() const { return m_targetMatch; }
  //! The landmark matched to target landmark \e i in the last detection, or nullptr.
  const vpSSLLandmark *getMatchedLandmark(size_t i) const;
  //! Stage times of the last detection.
  const vpSSLDetectorTimes &getTimes() const { return m_times; }
  /*!
    Matching map of the last detection (zero outside the regions of interest of getMapRegions() in a tracking
    frame), at the resolution it was computed: half the image's with decimation 2 (setDecimation()), twice in the
    small-landmark mode.
  */
  const vpImage<int> &getMatchingMap() const { return m_mainMap.map; }
  //! The matching function in use.
  const vpSSLMatchingFunction &getMatchingFunction() const { return m_match; }

  /*!
    Visual features of the matched landmarks, in target landmark order (unmatched ones skipped):
    normalised coordinates through \e cam (distortion included) and depth Z from the apparent
    radius (Eq. 6: \f$ Z = p_x R / r \f$).
  */
  std::vector<vpFeaturePoint> getFeaturePoints(const vpCameraParameters &cam) const;

  /*!
    Range to the landmark centre from its apparent radius (Eq. 6), in metres.
    \param landmark : detected landmark.
    \param radius : its printed outer radius (m).
    \param cam : camera model (its px is the focal length in pixels).
  */
  static double range(const vpSSLLandmark &landmark, double radius, const vpCameraParameters &cam);

  /*!
    Detects the landmarks and the target in \e I (detect(const vpImage<unsigned char> &)), then gives the target's
    pose the way vpDetectorAprilTag::detect(I, tagSize, cam, cMo_vec) gives the tags': a ViSP user swaps one detector
    for the other. The sizes come from the target model (getTarget()), so there is no size argument. The pose is
    vpSSLPoseEstimator's best hypothesis (paper Sec. 3.2): with three or more landmarks of the target matched, P3P
    (or vpPose with four or more) refined by virtual visual servoing.

    A position-only result (one or two landmarks matched, paper cases 1 and 2: a range from Eq. 6, no orientation)
    is never put in \e cMo_vec; it goes to \e positions.

    \param I : grey image.
    \param cam : camera model (px, py > 0).
    \param cMo_vec : the target's full pose (target frame in the camera frame), one element when it was estimated,
    else empty. Cleared first.
    \param cMo_vec2 : if not nullptr, the second best full pose of the same view (another P3P solution, which the
    tracker's filter may still prefer), one element when there is one, else empty.
    \param projErrors : if not nullptr, the RMS distance between the detected and the projected centres of each
    pose of \e cMo_vec (px).
    \param projErrors2 : if not nullptr, the same for \e cMo_vec2.
    \param positions : if not nullptr, when only a position is known, one element: the position in the camera
    frame (m) of the centre of the biggest matched landmark of the target (getMatchedLandmark()); else empty.
    \return true when \e cMo_vec holds a full pose.
    \exception vpException on a bad image, as detect(const vpImage<unsigned char> &).

    \code
    vpSSLDetector detector; // ssl3-a3: the landmark sizes are the target's
    std::vector<vpHomogeneousMatrix> cMo_vec;
    if (detector.detect(I, cam, cMo_vec)) {
      vpDisplay::displayFrame(I, cMo_vec[0], cam, 0.1, vpColor::none, 3);
    }
    \endcode
    See tutorial-ssl-detector-pose.cpp, a port of ViSP's tutorial-apriltag-detector.cpp.
  */
  bool detect(const vpImage<unsigned char> &I, const vpCameraParameters &cam, std::vector<vpHomogeneousMatrix> &cMo_vec,
              std::vector<vpHomogeneousMatrix> *cMo_vec2 = nullptr, std::vector<double> *projErrors = nullptr,
              std::vector<double> *projErrors2 = nullptr, std::vector<vpTranslationVector> *positions = nullptr);

private:
  // A matching map and the regions the last tracking frame wrote into it (the rest is 0).
  struct MatchMap
  {
    vpImage<int> map;
    std::vector<vpRect> written;
    bool allWritten = true; // whether the last call wrote the whole map (or it is uninitialised)
  };

  void fillObjects();
  // Normalisation, matching and peaks of the whole image (\e regions nullptr) or of regions, at full resolution or
  // on the image decimated twice (\e coarse), then the ring reading of the peaks; the stage times are added up.
  void searchRegions(const vpImage<unsigned char> &I, const vpImage<unsigned char> &raw, bool coarse,
                     const std::vector<vpRect> *regions, double scale, std::chrono::steady_clock::time_point &t);
  // Whether (u, v) (image pixels) lies within R / sqrt(p) of a landmark found this frame.
  bool insideFound(double u, double v) const;
  // Where the rays' reading rejects a point-symmetric candidate: vpSSLConcentricReader from its symmetric centre.
  bool readAllAround(const vpImage<unsigned char> &raw, vpSSLLandmark &l);
  // Whether the landmark a tracking frame's region predicts is large enough for the decimated pass.
  bool largeLandmarkIn(const vpRect &r) const;
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
  // listed in m_pendingRois.
  void rereadPredicted(const vpImage<unsigned char> &raw, double scale);
  double scoreAt(const vpImage<unsigned char> &I, double u, double v) const;
  // The landmark of the previous detection nearest to (u, v) and within half its smaller semi-axis, if any.
  const vpSSLLandmark *previousNear(double u, double v) const;

  vpSSLBrightnessNormalizer m_normalizer;
  vpSSLMatchingFunction m_match;
  vpSSLPeakDetector m_peakDetector;
  vpSSLRadiusEstimator m_radiusEstimator;
  vpSSLConcentricReader m_concentricReader;
  unsigned int m_allAroundLeft = 0; // candidates vpSSLConcentricReader may still read this frame
  vpSSLTargetIdentifier m_identifier;
  bool m_normalize;
  bool m_upsample;
  unsigned int m_window;
  unsigned int m_decimation;
  vpSSLMatchingFunction m_matchCoarse; // window w / 2, on the decimated image
  double m_maxRadius;
  bool m_radiusSweep;
  double m_threshold;
  std::vector<vpRect> m_rois;
  std::vector<vpRect> m_noRois;       // always empty: the whole image
  std::vector<vpRect> m_pendingRois;  // regions of this tracking frame whose landmark was not re-read directly
  std::vector<size_t> m_pendingIndex; // their indices in m_rois
  // Regions of a full-resolution tracking frame matched on the decimated image, their indices, and the others.
  std::vector<vpRect> m_coarseRois, m_fineRois;
  std::vector<size_t> m_coarseIndex;
  std::vector<vpRect> m_mapRois; // regions of this tracking frame matched into getMatchingMap()
  unsigned int m_fullSearchPeriod;
  unsigned long m_roiCalls; // detect() calls with regions of interest since they were set
  bool m_lastSearchWasFull;

  vpImage<unsigned char> m_normalized;
  vpImage<unsigned char> m_upsampled;
  vpImage<unsigned char> m_decimated;  // normalised, decimated image (decimation 2)
  vpImage<unsigned char> m_sweepRow;   // one normalised full-resolution row, for the Eq. 7 sweep
  unsigned char m_lut[256];            // normalisation table of the last frame
  int m_offsetA[129], m_offsetB[129];  // a_xi, b_xi of the full-resolution window (refinePeak())
  std::vector<vpImagePoint> m_refined; // full-resolution peaks already read this frame
  // Normalised pixels around a decimated peak (refinePeak()): rows (row-major) and columns (column-major).
  std::vector<unsigned char> m_crossRows, m_crossCols;
  int m_crossU0 = 0, m_crossV0 = 0, m_crossW = 0, m_crossCu0 = 0, m_crossCv0 = 0, m_crossH = 0;
  int m_imageW = 0, m_imageH = 0;
  std::vector<vpSSLLandmark> m_previous; // landmarks of the previous detect(), re-read in tracking mode
  std::vector<char> m_roiFilled;         // whether a landmark has been read inside each region this frame
  std::vector<vpRect> m_scaledRois;
  MatchMap m_mainMap;   // the map of getMatchingMap()
  MatchMap m_coarseMap; // the decimated regions of a full-resolution tracking frame
  std::vector<vpSSLPeak> m_peaks;
  std::vector<vpSSLLandmark> m_landmarks;
  std::vector<int> m_sweep; // Eq. 7 sweep, reused
  vpSSLTargetMatch m_targetMatch;
  vpSSLDetectorTimes m_times;
};

#endif
