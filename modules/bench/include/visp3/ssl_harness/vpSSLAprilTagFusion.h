/*!
  \file vpSSLAprilTagFusion.h
  \brief The SSL tracker's fusion (particle filter with odometry) applied to the AprilTag baseline's detections.
*/
#ifndef VP_SSL_APRILTAG_FUSION_H
#define VP_SSL_APRILTAG_FUSION_H

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/ssl/vpSSLParticleFilter.h>
#include <visp3/ssl/vpSSLTarget.h>
#include <visp3/ssl_servo/vpSSLServoInput.h>

/*!
  \class vpSSLAprilTagFusion
  \ingroup group_ssl_harness
  \brief The fusion the SSL tracker gives its detections, for the AprilTag baseline: the same particle filter
  (vpSSLParticleFilter with its defaults, as vpSSLTracker) over a target made of the tag's four corners,
  predicted with the vehicle's odometry at each image, updated with the detected corners and re-initialised
  from the tag's pose (vpSSLTracker's paper Sec. 3.3 scheme); the tag's pose is the input when the filter agrees
  with it. While the tag is not seen the prediction stays the input (nbPoints 0) for as many images as
  vpSSLTracker's default setMaxLostFrames() (5), then nothing.
*/
class vpSSLAprilTagFusion
{
public:
  //! The filter over a target of the four corners of a \e tagSize tag, seen by \e cam mounted at \e vMc.
  vpSSLAprilTagFusion(double tagSize, const vpCameraParameters &cam, const vpHomogeneousMatrix &vMc);

  void setSeed(long seed) { m_filter.setSeed(seed); } //!< Seed of the filter's particles.

  /*!
    One image: \e detection is vpSSLServoInput::fromAprilTag() of the tag (or none()), \e oMv the odometry.
    \return the fused input: measured corners where seen, the filter's pose and projected corners otherwise.
  */
  vpSSLServoInput track(const vpSSLServoInput &detection, const vpHomogeneousMatrix &oMv);

private:
  // The corners in vpSSLServoInput::fromAprilTag()'s order and frame (X right, Y down, Z into the sheet).
  static vpSSLTarget cornerTarget(double tagSize);

  vpSSLTarget m_target;
  vpSSLParticleFilter m_filter;
  vpCameraParameters m_cam;
  vpHomogeneousMatrix m_cMv, m_oMvPrevious;
  bool m_active = false, m_hasOdometry = false;
  unsigned int m_lostInRow = 0;
};

#endif
