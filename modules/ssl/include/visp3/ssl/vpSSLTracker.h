/*!
  \file vpSSLTracker.h
  \brief Target tracker: detector in regions of interest, single-frame pose and particle filter (paper Sec. 3.3, 4.1).
*/
#ifndef VP_SSL_TRACKER_H
#define VP_SSL_TRACKER_H

#include <vector>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRect.h>
#include <visp3/ssl/vpSSLConfig.h>
#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl/vpSSLParticleFilter.h>
#include <visp3/ssl/vpSSLPoseEstimator.h>
#include <visp3/ssl/vpSSLPoseHypothesis.h>
#include <visp3/ssl/vpSSLTarget.h>
#include <visp3/visual_features/vpFeaturePoint.h>

/*!
  \enum vpSSLTrackerState
  \ingroup group_ssl
  \brief State of vpSSLTracker after a track() call.

  Transitions, evaluated once per image ("seen": the target was identified in the image):
  - SEARCHING: seen -> ACQUIRED (filter initialised from the single-frame hypotheses); else stays.
  - ACQUIRED: seen -> TRACKING once the filter has converged or after setAcquisitionFrames() images
    seen in a row, unless the image's position-only reading contradicts an acquisition made on one or two
    landmarks (see getOrientationKnown()); seen but not yet, or the filter re-initialised itself -> stays;
    not seen -> LOST.
  - TRACKING: seen -> stays (also when setReinitialisationGate() re-initialises the filter); seen but the
    filter re-initialised itself from the hypotheses (vpSSLParticleFilter::REINITIALISED) -> ACQUIRED;
    not seen -> LOST.
  - LOST: seen -> ACQUIRED (filter re-initialised); not seen for more than setMaxLostFrames() images in a
    row -> SEARCHING (the pose is dropped); else stays, the filter coasting on the odometry.
*/
enum vpSSLTrackerState
{
  SSL_TRACKER_SEARCHING, ///< No pose: every image is searched whole.
  SSL_TRACKER_ACQUIRED,  ///< Target just found: the filter is initialised but not yet trusted.
  SSL_TRACKER_TRACKING,  ///< The filter follows the target, detection in regions of interest.
  SSL_TRACKER_LOST       ///< Target not seen in the last image(s): the pose is a prediction only.
};

/*!
  \ingroup group_ssl
  Name of a tracker state, as the tutorials print it and write it in their CSV: "searching", "acquired",
  "tracking" or "lost" ("?" for a value outside the enum).
*/
VISP_SSL_EXPORT const char *vpSSLTrackerStateName(vpSSLTrackerState state);

/*!
  \class vpSSLTracker
  \ingroup group_ssl
  \brief Tracks the target over an image sequence: predicts where its landmarks will be, detects only in
  regions of interest around them, and fuses the detections with the vehicle odometry in a particle filter.

  Each track() call:
  -# predicts the filter with the vehicle displacement since the previous image (from the odometry oMv and
     the camera mounting vMc), or with a random walk when no odometry is given;
  -# projects the target's landmarks with the filter's mean pose and gives the detector a square region of
     interest (setRoiSize(), default 100 px) around each (paper Sec. 4.1); while searching or lost, while
     the orientation is unknown (getOrientationKnown()), when a landmark is predicted outside the image, or
     every setFullSearchPeriod() images, the whole image is searched instead;
  -# chooses the detector's scale (vpSSLDetector::setSmallLandmarkMode(), see below);
  -# detects and identifies the target; the matched landmarks become labelled observations; while a
     prediction exists (ACQUIRED, TRACKING, LOST), a landmark read at p^k (k >= 1, within a third of a ring
     step) of its predicted apparent radius is an inner ring copy of it (the pattern repeats at every scale
     inside, and close up the outer rings leave the image): its radius, and the range of its position-only
     hypothesis, are scaled back by p^k (test/test_tracker_contact.cpp);
  -# initialises the filter from vpSSLPoseEstimator's hypotheses while searching or lost, updates it
     otherwise (the fresh hypotheses are passed as recovery when no particle explains the image); when only
     one or two landmarks are seen and the filter knows the orientation, their labels are dropped and each
     goes to the nearest projected landmark (a lone landmark is labelled B by the identifier, as in the paper,
     even when it is S1);
  -# gives as pose (getPose()) the best ranked full single-frame hypothesis that lies within the filter's
     uncertainty (setSelectionGate()), the filter's mean when none does.

  <b>Why the pose is a selected hypothesis.</b> On a sharp image of the three landmarks the single-frame pose
  (P3P refined by virtual visual servoing) is already within millimetres, while 1000 particles in six
  dimensions cannot resolve the pose much below a centimetre and a few degrees. What the filter knows and
  one image does not is which of the P3P solutions is the target (the single-frame ranking picks a wrong one
  in a few percent of the views, most often the mirrored tilt) and where the target is when fewer than three
  landmarks, or none, are seen. So the filter vetoes the hypotheses of the image that disagree with it and
  stands alone only when none is a full pose that agrees with it: one or two landmarks (the filter keeps the orientation
  it learnt), a lost target (odometry only), or hypotheses that all disagree (a misidentification).

  \code
  vpSSLTracker tracker(vpSSLTarget::ssl3a3(), cam, vMc);
  while (reader.next(frame, I)) {
    tracker.track(I, vpHomogeneousMatrix(frame.oMv));
    if (tracker.getState() == SSL_TRACKER_TRACKING)
      std::cout << tracker.getPose() << std::endl;
  }
  \endcode

  <b>Small-landmark mode.</b> With its default window (w = 40) the detector does not see a landmark whose
  smaller semi-axis is below about 25 px: with a 554 px camera, B (R = 0.1 m) beyond about 2.2 m and S1, S2
  (R = 0.05 m) beyond about 1.1 m. Its small-landmark mode sees them down to 8 px of radius (B to about 7 m)
  for several times the matching cost. Unless setAutomaticSmallLandmarkMode(false), the tracker switches it
  before each detection:
  - SEARCHING or LOST (whole-image search, nothing is known of the range): small-landmark mode on, since it
    also finds large landmarks while the default mode misses every small one;
  - ACQUIRED or TRACKING: from the predicted radii. Each landmark's circle is projected with the filter's
    mean pose and its smallest apparent radius is taken, i.e. the shortest distance from the projected centre
    to the projected rim (the rays the detector reads; with a tilt this is about the minor semi-axis). The
    smallest of these over the landmarks predicted in the image, getPredictedSmallestRadius(), switches the
    mode on below setSmallLandmarkRadius() (default 30 px, 25 px and a margin for the prediction error) and
    off above 1.25 times it; in between the mode is kept, so that it does not flip at every image near the
    boundary. All the landmarks count, not only B, because three landmarks give a full pose and one only a
    position.
  getLastSmallLandmarkMode() tells which mode the last detection used.

  Accuracy per range band against the single-frame pose: doc/benchmarks.md, "Tracker".
  See test/test_tracker.cpp, test/test_tracker_sequences.cpp and tutorial-ssl-tracker.cpp.
*/
class VISP_SSL_EXPORT vpSSLTracker
{
public:
  /*!
    Tracker of \e target seen by the camera \e cam, mounted at \e vMc on the vehicle (camera pose in the
    vehicle frame, the sequence's camera_to_vehicle).
    \exception vpException if the camera has no positive px/py or the target no landmark.
  */
  vpSSLTracker(const vpSSLTarget &target, const vpCameraParameters &cam,
               const vpHomogeneousMatrix &vMc = vpHomogeneousMatrix());

  /*!
    Processes one image without odometry (random-walk prediction).
    \return the new state.
    \exception vpException on an empty image.
  */
  vpSSLTrackerState track(const vpImage<unsigned char> &I);
  /*!
    Processes one image with the vehicle pose \e oMv in its odometry frame at that image. Odometry that is
    not finite or jumps too far is not used for the prediction (see vpSSLParticleFilter::predict()).
    \return the new state.
    \exception vpException on an empty image.
  */
  vpSSLTrackerState track(const vpImage<unsigned char> &I, const vpHomogeneousMatrix &oMv);

  //! Back to SEARCHING: forgets the pose and the odometry reference.
  void reset();

  //! Full-image search at least every \e n images while tracking (default 10, paper Sec. 4.1; 0: never).
  void setFullSearchPeriod(unsigned int n);
  //! Side of the square region of interest around each predicted landmark (px, default 100).
  void setRoiSize(double side);
  //! Images seen in a row after which ACQUIRED becomes TRACKING even if the filter has not converged (default 3).
  void setAcquisitionFrames(unsigned int n) { m_acquisitionFrames = n; }
  //! Images without the target after which LOST becomes SEARCHING (default 5).
  void setMaxLostFrames(unsigned int n) { m_maxLostFrames = n; }
  /*!
    Re-initialisation gate (px, default 5, ten times the detector's centre accuracy): when the filter's mean
    pose reprojects the detected centres with an RMS error above it while the best single-frame full pose
    (three landmarks or more) stays below half of it, the filter is re-initialised from the single-frame
    hypotheses. The filter alone can stay in a wrong mode: at 3 m, 0.3 m of depth moves the ssl3-a3 centres by
    about 3 px, within its pixel sigma. The state stays TRACKING (the target was seen without interruption);
    from ACQUIRED it stays ACQUIRED.
  */
  void setReinitialisationGate(double pixels) { m_reinitPixels = pixels; }
  /*!
    Whether the tracker switches the detector's small-landmark mode itself (default true; see the class
    description). false: the mode set on getDetector() is left as it is.
  */
  void setAutomaticSmallLandmarkMode(bool enable) { m_autoSmall = enable; }
  /*!
    Predicted smallest apparent radius (px, default 30) below which the automatic switch uses the
    small-landmark mode; the mode is left above 1.25 times it.
    \exception vpException if \e pixels is not a positive number.
  */
  void setSmallLandmarkRadius(double pixels);
  /*!
    Gate of the hypothesis selection (see getPose()): a full single-frame hypothesis is taken as the pose when
    its position lies within \e sigmas standard deviations of the filter's position spread plus \e
    rangeFraction of the range (default 3 and 0.1), and its rotation within \e sigmas standard deviations of
    the rotation spread plus \e degrees (default 30 deg) of the filter's mean. The gate is wide on purpose: it
    only vetoes gross disagreements (a landmark taken for another one doubles the range, a wrong P3P branch
    turns the target by twice its tilt); between hypotheses that agree with the filter the image's ranking is
    the better judge, and the filter's mean is often several degrees off. \e sigmas = 0, \e rangeFraction
    = 0 and \e degrees = 0 switch the selection off: the pose is then always the filter's mean.
    \exception vpException if a value is negative or not finite.
  */
  void setSelectionGate(double sigmas, double rangeFraction, double degrees);
  //! Seeds the particle filter (reproducible runs).
  void setSeed(long seed) { m_filter.setSeed(seed); }

  //! State after the last track().
  vpSSLTrackerState getState() const { return m_state; }
  //! True when a pose is available (ACQUIRED, TRACKING or LOST).
  bool hasPose() const { return m_state != SSL_TRACKER_SEARCHING; }
  /*!
    Target pose cMo: the best ranked full single-frame hypothesis of the last image that passes
    setSelectionGate() around the filter's mean pose, the filter's mean pose when none does (see the class
    description); identity while SEARCHING (see hasPose()).
  */
  vpHomogeneousMatrix getPose() const;
  /*!
    Whether the orientation of getPose() is known: a full single-frame pose (three landmarks or more) was seen
    since the filter was last initialised. False while SEARCHING and after an initialisation from one or two
    landmarks: the filter then only knows that the target faces the camera, so its orientation, and the
    position of the target origin away from the landmark seen, are arbitrary. getPose() then places that
    landmark where the particles put it (or where the image's position-only hypothesis puts it when that one
    passes setSelectionGate()), with the filter's mean orientation. While the orientation is unknown, two
    images in a row whose position-only reading of that landmark lies farther from the filter's estimate than
    the range fraction of setSelectionGate() re-initialise the filter from them (state ACQUIRED): the
    acquisition rested on one reading, and that one was wrong (a first reading that takes S1 for B doubles the
    range).
  */
  bool getOrientationKnown() const { return m_orientationKnown; }
  //! Whether getPose() is a single-frame hypothesis selected by the filter (false: the filter's mean).
  bool getPoseIsSelectedHypothesis() const { return m_selected; }
  //! Number of target landmarks identified in the last image (the paper's nbPoints).
  unsigned int getNbLandmarks() const { return m_nbLandmarks; }
  /*!
    One vpFeaturePoint per target landmark, in target order: normalised coordinates measured in the last
    image when the landmark was detected there, projected from the pose otherwise; depth Z from the pose.
    Empty while SEARCHING.
  */
  std::vector<vpFeaturePoint> getFeaturePoints() const;
  //! Single-frame hypotheses of the last image (empty when the target was not seen), best first.
  const std::vector<vpSSLPoseHypothesis> &getHypotheses() const { return m_hypotheses; }
  //! Regions of interest given to the detector for the last image (empty: whole image).
  const std::vector<vpRect> &getRegionsOfInterest() const { return m_rois; }
  //! Whether the last image was searched whole.
  bool getLastSearchWasFull() const { return m_detector.getLastSearchWasFull(); }
  //! Whether the last detection used the detector's small-landmark mode.
  bool getLastSmallLandmarkMode() const { return m_detector.getSmallLandmarkMode(); }
  /*!
    Smallest apparent radius (px) of the target's landmarks predicted in the last image from the filter's mean
    pose (see the class description); infinity when nothing was predicted (SEARCHING or LOST, or no landmark
    in the image).
  */
  double getPredictedSmallestRadius() const { return m_predictedRadius; }
  //! Whether the odometry of the last track() was used by the prediction.
  bool getLastOdometryUsed() const { return m_odometryUsed; }
  /*!
    Re-initialisations by the tracker's gates since construction: setReinitialisationGate(), and the
    position-only disagreement of getOrientationKnown().
  */
  unsigned int getNbReinitialisations() const { return m_nbReinitialisations; }
  //! The detector (to configure it, e.g. setSmallLandmarkMode()).
  vpSSLDetector &getDetector() { return m_detector; }
  //! The particle filter (to configure it, e.g. setNbParticles()).
  vpSSLParticleFilter &getFilter() { return m_filter; }
  //! The target.
  const vpSSLTarget &getTarget() const { return m_target; }
  //! The camera.
  const vpCameraParameters &getCameraParameters() const { return m_cam; }

private:
  vpSSLTrackerState process(const vpImage<unsigned char> &I);
  void predictRegions(unsigned int width, unsigned int height);
  void chooseScale();
  void selectPose();
  bool heldLandmarkEstimate(vpTranslationVector &t) const;
  bool positionDisagrees() const;
  double apparentRadius(const vpHomogeneousMatrix &cMo, const vpSSLTargetLandmark &l, double u, double v) const;
  double innerCopyScale(size_t k, double u, double v, double radius) const;
  double reprojectionError(const vpHomogeneousMatrix &cMo) const;
  void undistort(double u, double v, double &uu, double &vu) const;

  vpSSLTarget m_target;
  vpCameraParameters m_cam;
  vpHomogeneousMatrix m_cMv;
  vpSSLDetector m_detector;
  vpSSLPoseEstimator m_estimator;
  vpSSLParticleFilter m_filter;
  vpSSLTrackerState m_state;
  unsigned int m_fullSearchPeriod;
  double m_roiSize;
  unsigned int m_acquisitionFrames;
  unsigned int m_maxLostFrames;
  double m_reinitPixels;
  double m_gateSigmas;
  double m_gateRangeFraction;
  double m_gateDegrees;
  bool m_selected;
  bool m_orientationKnown;
  size_t m_heldLandmark;        // landmark the filter was initialised on, when the orientation is unknown
  unsigned int m_disagreeInRow; // images in a row whose position-only reading disagrees with the filter
  vpHomogeneousMatrix m_pose;
  bool m_autoSmall;
  double m_smallRadius;
  double m_predictedRadius;
  unsigned int m_nbReinitialisations;
  unsigned int m_seenInRow;
  unsigned int m_lostInRow;
  unsigned int m_nbLandmarks;
  bool m_hasOdometry;
  vpHomogeneousMatrix m_oMvPrevious;
  bool m_odometryUsed;
  std::vector<vpRect> m_rois;
  bool m_hadRegions;            // whether the previous image had regions of interest
  unsigned long m_regionFrames; // images with regions of interest since they appeared (setFullSearchPeriod())
  std::vector<vpSSLObservation> m_observations;
  std::vector<vpSSLObservation> m_unlabelled; // the observations given to the filter's update
  std::vector<vpSSLPoseHypothesis> m_hypotheses;
  std::vector<bool> m_seen;    // per target landmark, detected in the last image
  std::vector<double> m_seenX; // its normalised coordinates
  std::vector<double> m_seenY;
};

#endif
