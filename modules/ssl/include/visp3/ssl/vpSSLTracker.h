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
    seen in a row; seen but not yet, or the filter re-initialised itself -> stays; not seen -> LOST.
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
  \class vpSSLTracker
  \ingroup group_ssl
  \brief Tracks the target over an image sequence: predicts where its landmarks will be, detects only in
  regions of interest around them, and fuses the detections with the vehicle odometry in a particle filter.

  Each track() call:
  -# predicts the filter with the vehicle displacement since the previous image (from the odometry oMv and
     the camera mounting vMc), or with a random walk when no odometry is given;
  -# projects the target's landmarks with the filter's mean pose and gives the detector a square region of
     interest (setRoiSize(), default 100 px) around each (paper Sec. 4.1); while searching or lost, or every
     setFullSearchPeriod() images, the whole image is searched instead;
  -# detects and identifies the target; the matched landmarks become labelled observations;
  -# initialises the filter from vpSSLPoseEstimator's hypotheses while searching or lost, updates it
     otherwise (the fresh hypotheses are passed as recovery when no particle explains the image).

  \code
  vpSSLTracker tracker(vpSSLTarget::ssl3a3(), cam, vMc);
  while (reader.next(frame, I)) {
    tracker.track(I, vpHomogeneousMatrix(frame.oMv));
    if (tracker.getState() == SSL_TRACKER_TRACKING)
      std::cout << tracker.getPose() << std::endl;
  }
  \endcode
  See test/test_tracker.cpp.
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
  //! Seeds the particle filter (reproducible runs).
  void setSeed(long seed) { m_filter.setSeed(seed); }

  //! State after the last track().
  vpSSLTrackerState getState() const { return m_state; }
  //! True when a pose is available (ACQUIRED, TRACKING or LOST).
  bool hasPose() const { return m_state != SSL_TRACKER_SEARCHING; }
  //! Target pose cMo: the filter's mean pose; identity while SEARCHING (see hasPose()).
  vpHomogeneousMatrix getPose() const;
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
  //! Whether the odometry of the last track() was used by the prediction.
  bool getLastOdometryUsed() const { return m_odometryUsed; }
  //! Re-initialisations by the gate of setReinitialisationGate() since construction.
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
  unsigned int m_nbReinitialisations;
  unsigned int m_seenInRow;
  unsigned int m_lostInRow;
  unsigned int m_nbLandmarks;
  bool m_hasOdometry;
  vpHomogeneousMatrix m_oMvPrevious;
  bool m_odometryUsed;
  std::vector<vpRect> m_rois;
  std::vector<vpSSLObservation> m_observations;
  std::vector<vpSSLPoseHypothesis> m_hypotheses;
  std::vector<bool> m_seen;    // per target landmark, detected in the last image
  std::vector<double> m_seenX; // its normalised coordinates
  std::vector<double> m_seenY;
};

#endif
