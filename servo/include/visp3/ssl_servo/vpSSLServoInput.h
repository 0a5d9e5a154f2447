/*!
  \file vpSSLServoInput.h
  \brief What the servo law sees of the target at one frame, whatever found it (SSL tracker, AprilTag, truth).
*/
#ifndef VP_SSL_SERVO_INPUT_H
#define VP_SSL_SERVO_INPUT_H

#include <vector>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImagePoint.h>
#include <visp3/core/vpPoint.h>
#include <visp3/ssl/vpSSLConfig.h>
#include <visp3/visual_features/vpFeaturePoint.h>

class vpSSLTracker;

/*!
  \struct vpSSLServoPoint
  \ingroup group_ssl_servo
  \brief One matched target point: where it is on the target and where the camera sees it now.
*/
struct VISP_SSL_EXPORT vpSSLServoPoint
{
  double oX = 0.; ///< X in the object frame (m); object frame: X right, Y down, Z into the sheet (as vpSSLTarget).
  double oY = 0.; ///< Y in the object frame (m).
  double oZ = 0.; ///< Z in the object frame (m).
  double x = 0.;  ///< Current normalised image coordinate x (X/Z in the camera frame).
  double y = 0.;  ///< Current normalised image coordinate y (Y/Z in the camera frame).
  double Z = 0.;  ///< Current depth in the camera frame (m); must be > 0 for the point to be used.

  //! The object point as a vpPoint (object coordinates set).
  vpPoint getObjectPoint() const;
  //! The current visual feature (x, y, Z).
  vpFeaturePoint getFeature() const;
};

/*!
  \struct vpSSLServoInput
  \ingroup group_ssl_servo
  \brief Everything the servo law and the homing behaviour get about the target at one frame.

  Independent of how the target was found: fromTracker() (SSL tracker), fromAprilTag() (vpDetectorAprilTag),
  fromPose() (ground truth, tests). The object frame is the one of vpSSLTarget: X right, Y down on the
  printed sheet, Z \e into it, so that a camera facing the sheet has cMo with the identity rotation. The
  target centre is the centroid of the object points (the sheet centre for ssl3-a3 and for an AprilTag).

  The fields are plain data: garbage (NaN, infinite, negative depth) is allowed here; vpSSLServoLaw checks
  it and answers with a zero command and a status instead of a crash or a NaN.

  \code
  vpSSLTracker tracker(vpSSLTarget::ssl3a3(), cam, vMc);
  vpSSLHomingBehaviour homing;
  homing.getServoLaw().setCameraToVehicle(vMc);
  for (;;) {
    tracker.track(I, oMv);
    homing.update(t, vpSSLServoInput::fromTracker(tracker), depth, collision);
    homing.apply(robot); // vpRobot::ARTICULAR_FRAME: vehicle axes
  }
  \endcode
*/
struct VISP_SSL_EXPORT vpSSLServoInput
{
  bool valid = false;                  ///< True when the source has the target (points usable, possibly predicted).
  std::vector<vpSSLServoPoint> points; ///< Matched points (object point + current x, y, Z), in any order.
  bool hasPose = false;                ///< True when cMo is set.
  vpHomogeneousMatrix cMo;             ///< Pose of the object frame in the camera frame (when hasPose).
  unsigned int nbPoints = 0;           ///< Points actually measured in this image (the paper's nbPoints).

  //! An input without target (valid false, no point): what to pass when nothing was found.
  static vpSSLServoInput none();

  /*!
    Input from the SSL tracker after its last track(): valid when the tracker has a pose (ACQUIRED, TRACKING
    or LOST, see vpSSLTracker::hasPose()); one point per target landmark from getFeaturePoints() with the
    landmark centre as object point; cMo = getPose(); nbPoints = getNbLandmarks() (0 while LOST: the points
    are then the filter's prediction).
  */
  static vpSSLServoInput fromTracker(const vpSSLTracker &tracker);

  /*!
    Input from one AprilTag detection, as vpDetectorAprilTag gives it: its four corners in pixels
    (getPolygon(i)), its pose \e cMo from getPose(i, tagSize, cam, cMo) and the tag size (side of the black
    square, m). The four corners become the points: object coordinates (+-tagSize/2, +-tagSize/2, 0) in the
    sheet convention above, each paired with the detected corner nearest to its projection through \e cMo (so
    the corner order does not matter); x, y from the pixels through \e cam; Z from \e cMo.
    \param corners : the 4 detected corners (pixels).
    \param cMo : the tag pose from vpDetectorAprilTag::getPose().
    \param tagSize : side of the black square (m).
    \param cam : camera parameters used by the detector.
    \param zAlignedWithCameraAxis : false (vpDetectorAprilTag's default) when \e cMo is the pose of the tag
    frame (Y up, Z out of the tag): it is turned into the sheet frame (cMo * 180 deg about X); true when the
    detector was set with setZAlignedWithCameraAxis(true) (cMo is already the sheet frame).
    \return an input with valid false when there are not 4 corners, tagSize <= 0 or a value is not finite.
  */
  static vpSSLServoInput fromAprilTag(const std::vector<vpImagePoint> &corners, const vpHomogeneousMatrix &cMo,
                                      double tagSize, const vpCameraParameters &cam,
                                      bool zAlignedWithCameraAxis = false);

  /*!
    Input of a perfect sensor: \e objectPoints (object coordinates set, sheet convention) projected through
    \e cMo; valid, hasPose, nbPoints = number of points in front of the camera (all are listed).
  */
  static vpSSLServoInput fromPose(const std::vector<vpPoint> &objectPoints, const vpHomogeneousMatrix &cMo);

  //! Number of points.
  size_t size() const { return points.size(); }
};

#endif
