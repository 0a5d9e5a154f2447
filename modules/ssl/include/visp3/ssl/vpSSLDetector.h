/*!
  \file vpSSLDetector.h
  \brief Self-similar landmark and target detector, a vpDetectorBase.
*/
#ifndef VP_SSL_DETECTOR_H
#define VP_SSL_DETECTOR_H

#include <memory>
#include <string>
#include <vector>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpRect.h>
#include <visp3/detection/vpDetectorBase.h>
#include <visp3/ssl/vpSSLLandmark.h>
#include <visp3/ssl/vpSSLMatchingFunction.h>
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
  double radius = 0.;         ///< Ring reading, radius and centre refinement (Eq. 7), target completion.
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

  The detector is copyable: a copy has the settings, the last results and the previous frame's landmarks (which a
  tracking frame re-reads) of the original, and detects on its own from then on.
*/
class VISP_SSL_EXPORT vpSSLDetector : public vpDetectorBase
{
public:
  //! Detector for \e target (default ssl3-a3).
  explicit vpSSLDetector(const vpSSLTarget &target = vpSSLTarget::ssl3a3());
  //! Copy of \e other: its settings, results and tracking state.
  vpSSLDetector(const vpSSLDetector &other);
  //! Move: \e other is left without state and must not be used but to be destroyed or assigned to.
  vpSSLDetector(vpSSLDetector &&other) noexcept;
  //! Copy of \e other: its settings, results and tracking state.
  vpSSLDetector &operator=(const vpSSLDetector &other);
  //! Move: \e other is left without state and must not be used but to be destroyed or assigned to.
  vpSSLDetector &operator=(vpSSLDetector &&other) noexcept;
  //! Releases the detector and its working storage.
  ~vpSSLDetector() override;

  /*!
    Detects the landmarks and identifies the target in \e I.
    \return true if at least one landmark was found.
    \exception vpException on an empty image, or one whose size does not match its buffer or exceeds the limits
    of vpSSLInputLimits::checkImage() (16384 px a side, 2^26 pixels).
  */
  bool detect(const vpImage<unsigned char> &I) override;

  /*!
    Window length w of the matching function (default 40, paper Sec. 2.1). A full search at full resolution
    (setDecimation(1), not the small-landmark mode) computes w only where a landmark may be: it matches the
    normalised image's half (2x2 averages) with w / 2, the same radii in image pixels, for an eighth of the cost,
    and computes w in the tiles of 16x16 px within 12 px of a local maximum (3x3) of that map over 0.75 of the peak
    threshold (getThreshold()). A landmark's peak at full resolution lies within a few pixels of its peak on the
    half image. On noise or dense texture the tiles cover nearly the whole image.
  */
  void setWindow(unsigned int w);
  /*!
    Short window of a full search (default 10; 0: none). The matching function's response to a landmark fades once
    the window exceeds about 1.4 times its apparent radius, so w = 40 gives no peak at the centre of landmarks under
    about 28 px. A full search at full resolution (setDecimation(1), not the small-landmark mode) also matches the
    normalised image and its half (2x2 averages) with this window: w and 2 w in image pixels, from 7 px of radius up
    for w = 10, at 1.25 times a quarter of the cost of w = 40. It reads the 16 strongest peaks of each of these maps
    with those of w = 40, strongest first (the scores of all maps on the same scale). With a short window, a full search
    at full resolution also matches the image's quarter with a window of 20 (80 px in image pixels): landmarks of 40 px
    and more whose narrow inner rings a blur of 2 to 3 px has wiped out; its 8 strongest peaks are read after all the
    others. Tracking frames (setRegionsOfInterest()) use w alone.
    \exception vpException unless 0 or in [2, 128].
  */
  void setShortWindow(unsigned int w);
  //! Short window of a full search (setShortWindow()), 0 if none.
  unsigned int getShortWindow() const;
  //! Score threshold in [0, 1] on the normalised matching value at a peak (default 0.07).
  void setThreshold(double threshold);
  //! Brightness normalisation before matching (default on, paper Fig. 13).
  void setBrightnessNormalization(bool enable);
  //! Worker threads of the matching function (0: all cores).
  void setNbThreads(unsigned int n);
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
  unsigned int getDecimation() const;
  //! Largest apparent radius searched (px, default 300).
  void setMaxRadius(double r);
  /*!
    Whether each landmark also gets the paper's Eq. 7 estimate, vpSSLLandmark::radiusEq7 (default off: it is a
    second, less accurate radius, kept to compare with the paper's Fig. 4-5; vpSSLLandmark::radius is the one to
    use). When off, radiusEq7 is 0 and the sweep costs nothing.
  */
  void setRadiusSweep(bool enable);
  //! Whether the Eq. 7 sweep is computed (setRadiusSweep()).
  bool getRadiusSweep() const;
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
  bool getSmallLandmarkMode() const;
  /*!
    Equal-ring check (default on). Every landmark read already has to follow \f$ s_p \f$ over its resolved rings
    (vpSSLConcentricReader::similarity() of 0.5 or more), which a bull's-eye of equal-width rings fails when sharp;
    blurred, its outer rings can pass. The check turns away as well a landmark whose ring profile rings of one width
    explain better, while its inner rings keep their contrast (vpSSLConcentricReader::isEqualRings()), and one of 10
    to 40 px whose centre disc is darker than its outer black ring (a landmark's is two thirds white): a bull's-eye
    with a solid dark centre, a dark speck ringed in light. It also turns away some landmarks read at twice their
    radius. doc/detector.md gives what each part removes on the negatives of the independent corpus.
  */
  void setEqualRingCheck(bool enable);
  //! Whether the equal-ring check is on (setEqualRingCheck()).
  bool getEqualRingCheck() const;
  /*!
    Blurred-ring model (default on). Where the all-around reading of a candidate (vpSSLConcentricReader) fits the
    rings' ellipses but its outer-ring tests, which need a few grey levels of contrast in nearly every direction, find
    no ring, the profile is compared with \f$ s_p \f$ blurred by 0.4 to 4 px and with a blurred solid disc
    (vpSSLConcentricReader::setBlurredRingModel()): faint landmarks of 8 to 40 px, blurred by 1 to 2.5 px, are read.
    On the independent corpus it finds 1 to 2 % more B and 2 to 3 % more S1 and S2 than without it, loses none, and
    adds one false target on 3,400 negatives, for a few per cent more time per image (doc/detector.md).
  */
  void setBlurredRingModel(bool enable);
  //! Whether the blurred-ring model is on (setBlurredRingModel()).
  bool getBlurredRingModel() const;
  /*!
    Target completion (default on). On a full search at full resolution (no decimation, no small-landmark mode, the
    short window on), once the target match holds its big landmark but not every other one, the ellipse of the big
    one says where the others lie and how large they are, up to the target's rotation about the plane's normal: from a
    second landmark of the match, else from the rotations where the short window's maps answer most strongly. The
    missing landmarks are read there by the rings (vpSSLRadiusEstimator within 11 % of the predicted ellipse), else all
    around (vpSSLConcentricReader::read(), then vpSSLConcentricReader::readAt() about the predicted shape), with every
    check of a full search, and kept when they land within half a predicted radius of the prediction, at 0.7 to 1.43
    times its size. A big landmark read at 1 / p times its radius (the paper and dark surroundings past its outer ring
    read as one more ring) is read again at its size when every landmark that size predicts is read. On the
    independent corpus it finds 2.6 to 4.8 % more of the eligible S1 and S2 and loses nothing (doc/detector.md).
  */
  void setTargetCompletion(bool enable);
  //! Whether the target completion is on (setTargetCompletion()).
  bool getTargetCompletion() const;
  /*!
    Candidates per frame that the all-around reader (vpSSLConcentricReader) may read where the rays give up on a
    point-symmetric candidate (default 24), strongest peaks first; 0 leaves the rays alone. On flat noisy water the
    stretched sensor noise gives dozens of such candidates, each read in vain, as strong as a faint small landmark's,
    which the budget may then not reach: on the independent corpus a budget of 48 finds 0.7 to 1 % more of the B
    within 60 degrees of the normal, and more S1 and S2, for 0.5 to 1.4 ms more per image on average and two more false
    targets on 3,400 negatives (doc/detector.md, "Its budget").
  */
  void setAllAroundBudget(unsigned int candidates);
  //! Candidates per frame the all-around reader may read (setAllAroundBudget()).
  unsigned int getAllAroundBudget() const;
  /*!
    Restricts the next detections to these rectangles (empty: whole image), each centred on a predicted
    landmark (paper Sec. 4.1: vpSSLTracker centres them on its prediction, and gives none on the frames that
    search the whole image, vpSSLTracker::setFullSearchPeriod()). In these tracking frames:
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
    getMatchingMap() is 0 outside the rectangles of the last tracking frame matched at its resolution.
  */
  void setRegionsOfInterest(const std::vector<vpRect> &rois);
  //! Whether the last detect() searched the whole image: no region of interest was set (setRegionsOfInterest()).
  bool getLastSearchWasFull() const;

  unsigned int getWindow() const;          ///< Window length w (at full resolution).
  double getThreshold() const;             ///< Score threshold.
  bool getBrightnessNormalization() const; ///< Whether normalisation is on.
  const vpSSLTarget &getTarget() const;    ///< Target model.

  //! Landmarks of the last detection, best score first.
  const std::vector<vpSSLLandmark> &getLandmarks() const;
  //! Target identified in the last detection.
  const vpSSLTargetMatch &getTargetMatch() const;
  //! The landmark matched to target landmark \e i in the last detection, or nullptr.
  const vpSSLLandmark *getMatchedLandmark(size_t i) const;
  //! Stage times of the last detection.
  const vpSSLDetectorTimes &getTimes() const;
  /*!
    Matching map of the last detection, with window w, at the resolution it was computed: half the image's with
    decimation 2 (setDecimation()), twice in the small-landmark mode. It is zero outside the regions computed: in a
    tracking frame, the regions of interest matched at its resolution (setRegionsOfInterest()); in a full search at
    full resolution, the tiles around the candidates of the image's half (setWindow()).
  */
  const vpImage<int> &getMatchingMap() const;
  //! The matching function in use.
  const vpSSLMatchingFunction &getMatchingFunction() const;

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
  // The tests read the regions a tracking frame matched through it (modules/ssl/src/vpSSLDetectorTestAccess.h).
  friend class vpSSLDetectorTestAccess;
  class Impl;

  void fillObjects();

  std::unique_ptr<Impl> m_impl;
};

#endif
