/*!
  \file vpSSLRobotAuvTemplate.h
  \brief Skeleton of a ViSP robot driver for an AUV, in the style of ViSP's vpRobotTemplate: copy this file into
  your project and fill in the two places marked "YOUR VEHICLE". Header-only (no visp_ssl_harness code needed), used
  by tutorial-ssl-auv-driver and test_auv_driver_template.
*/
#ifndef VP_SSL_ROBOT_AUV_TEMPLATE_H
#define VP_SSL_ROBOT_AUV_TEMPLATE_H

#include <cmath>

#include <visp3/core/vpColVector.h>
#include <visp3/core/vpException.h>
#include <visp3/core/vpExponentialMap.h>
#include <visp3/core/vpFrameGrabber.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpMatrix.h>
#include <visp3/core/vpPoseVector.h>
#include <visp3/core/vpVelocityTwistMatrix.h>
#include <visp3/robot/vpRobot.h>
#include <visp3/robot/vpRobotException.h>

/*!
  \class vpSSLRobotAuvTemplate
  \ingroup group_ssl_harness
  \brief A velocity-controlled AUV as a vpRobot, so that vpSSLHomingBehaviour::apply() (or any ViSP servo loop)
  drives it, with the camera and the navigation a homing loop needs.

  Frames are those of vpSSLHomingBehaviour and vpSSLAuvSimulator: vehicle x forward, y starboard, z down; the
  odometry frame o is the navigation's (North-East-Down, z = 0 at the surface); the camera is mounted at vMc.

  What to fill in (search for "YOUR VEHICLE"):
  - sendBodyVelocity(): hand the body twist (surge, sway, heave, roll, pitch, yaw rates; m/s and rad/s) to the
    vehicle's autopilot or thruster allocation;
  - readNavigation(): the vehicle pose in its odometry frame (INS, DVL, compass, pressure sensor), its depth and
    the front collision switch.
  The camera needs no code: give setCamera() any vpFrameGrabber (vpV4l2Grabber, vpVideoReader, a vendor SDK
  wrapped as one). As shipped, the two functions stand in for a perfect vehicle (the commanded twist integrated
  over setTimeStep() at each acquire(), no collision), so the skeleton runs as is.

  \code
  vpSSLRobotAuvTemplate auv;
  auv.setCamera(grabber, vpSSLServoLaw::forwardCameraMount(0.5));
  vpSSLTracker tracker(vpSSLTarget::ssl3a3(), cam, auv.getCameraToVehicle());
  vpSSLHomingBehaviour homing;
  homing.getServoLaw().setCameraToVehicle(auv.getCameraToVehicle());
  while (homing.getState() != SSL_HOMING_DOCKED) {
    auv.acquire(I, oMv, depth, collision);
    tracker.track(I, oMv);
    homing.update(auv.getTime(), vpSSLServoInput::fromTracker(tracker), depth, collision);
    homing.apply(auv); // setVelocity(vpRobot::ARTICULAR_FRAME, (u v w p q r))
  }
  \endcode
  See tutorial-ssl-auv-driver.cpp.
*/
class vpSSLRobotAuvTemplate : public vpRobot
{
public:
  //! Connects to the vehicle (YOUR VEHICLE: open its link here). Limits 1 m/s and 1 rad/s, time step 0.2 s.
  vpSSLRobotAuvTemplate() : m_grabber(nullptr), m_dt(0.2), m_t(0.), m_velocity(6, 0.), m_depth(NAN), m_collision(false)
  {
    nDof = 6;
    setMaxTranslationVelocity(1.);
    setMaxRotationVelocity(1.);
  }
  //! Stops the thrusters.
  ~vpSSLRobotAuvTemplate() override { sendBodyVelocity(vpColVector(6, 0.)); }

  //! Zero command; displacements counted from here.
  void init() override
  {
    m_velocity = 0.;
    sendBodyVelocity(m_velocity);
    m_oMvDisplacement = m_oMv;
  }

  /*!
    The camera: \e grabber gives the images (opened by the caller) and \e vMc is its pose in the vehicle frame
    (from the vehicle's drawings, or a hand-eye calibration).
  */
  void setCamera(vpFrameGrabber &grabber, const vpHomogeneousMatrix &vMc)
  {
    m_grabber = &grabber;
    m_vMc = vMc;
  }
  //! Camera pose in the vehicle frame.
  const vpHomogeneousMatrix &getCameraToVehicle() const { return m_vMc; }
  //! Control period (s) of the stand-in navigation (readNavigation()). \exception vpException if not > 0.
  void setTimeStep(double dt)
  {
    if (!(dt > 0.) || !std::isfinite(dt)) {
      throw vpException(vpException::badValue, "vpSSLRobotAuvTemplate::setTimeStep: time step %g s is not > 0", dt);
    }
    m_dt = dt;
  }
  //! Time of the last acquire() (s).
  double getTime() const { return m_t; }
  //! Body twist of the last setVelocity(), after the limits.
  const vpColVector &getVelocity() const { return m_velocity; }
  //! Vehicle pose oMv in the odometry frame at the last acquire().
  const vpHomogeneousMatrix &getOdometry() const { return m_oMv; }

  /*!
    One control step's measurements: the camera image \e I, the vehicle pose \e oMv in its odometry frame, its
    \e depth (m, positive down; NaN if unknown) and the front \e collision switch, all of the same instant.
    \exception vpException (notInitialized) without setCamera().
  */
  void acquire(vpImage<unsigned char> &I, vpHomogeneousMatrix &oMv, double &depth, bool &collision)
  {
    if (m_grabber == nullptr) {
      throw vpException(vpException::notInitialized, "vpSSLRobotAuvTemplate::acquire: no camera (setCamera())");
    }
    readNavigation(m_oMv, m_depth, m_collision);
    m_grabber->acquire(I);
    oMv = m_oMv;
    depth = m_depth;
    collision = m_collision;
  }

  /*!
    Commands a twist, held until the next call: in vpRobot::ARTICULAR_FRAME or END_EFFECTOR_FRAME the body twist
    (surge, sway, heave, roll, pitch, yaw rates, vehicle frame), in vpRobot::REFERENCE_FRAME a twist expressed in
    the odometry frame, in vpRobot::CAMERA_FRAME a camera twist. Each is turned into the body twist and scaled
    down, whole, to the translation and rotation limits (vpRobot::setMaxTranslationVelocity(),
    setMaxRotationVelocity()).
    \exception vpRobotException (wrongStateError) unless in vpRobot::STATE_VELOCITY_CONTROL, or for MIXT_FRAME.
    \exception vpException (dimensionError) for a size other than 6, (badValue) for a non-finite component.
  */
  void setVelocity(const vpRobot::vpControlFrameType frame, const vpColVector &vel) override
  {
    if (getRobotState() != vpRobot::STATE_VELOCITY_CONTROL) {
      throw vpRobotException(vpRobotException::wrongStateError,
                             "vpSSLRobotAuvTemplate::setVelocity: the robot is not in velocity control "
                             "(setRobotState(vpRobot::STATE_VELOCITY_CONTROL))");
    }
    if (vel.size() != 6) {
      throw vpException(vpException::dimensionError, "vpSSLRobotAuvTemplate::setVelocity: velocity of size %u, not 6",
                        vel.size());
    }
    for (unsigned int i = 0; i < 6; ++i) {
      if (!std::isfinite(vel[i])) {
        throw vpException(vpException::badValue, "vpSSLRobotAuvTemplate::setVelocity: component %u is not finite", i);
      }
    }
    vpColVector v;
    switch (frame) {
    case vpRobot::ARTICULAR_FRAME:
    case vpRobot::END_EFFECTOR_FRAME:
      v = vel;
      break;
    case vpRobot::CAMERA_FRAME:
      v = vpVelocityTwistMatrix(m_vMc) * vel;
      break;
    case vpRobot::REFERENCE_FRAME: {
      const vpRotationMatrix vRo = m_oMv.getRotationMatrix().t();
      v = vpVelocityTwistMatrix(vpTranslationVector(), vRo) * vel;
      break;
    }
    default:
      throw vpRobotException(vpRobotException::wrongStateError,
                             "vpSSLRobotAuvTemplate::setVelocity: frame not supported (ARTICULAR_FRAME, "
                             "END_EFFECTOR_FRAME, CAMERA_FRAME or REFERENCE_FRAME)");
    }
    vpColVector vmax(6);
    for (unsigned int i = 0; i < 3; ++i) {
      vmax[i] = getMaxTranslationVelocity();
      vmax[i + 3] = getMaxRotationVelocity();
    }
    m_velocity = vpRobot::saturateVelocities(v, vmax, false);
    sendBodyVelocity(m_velocity);
  }

  //! Pose vector of oMv (REFERENCE_FRAME, ARTICULAR_FRAME, END_EFFECTOR_FRAME) or of oMc (CAMERA_FRAME).
  void getPosition(const vpRobot::vpControlFrameType frame, vpColVector &q) override
  {
    q = vpPoseVector(frame == vpRobot::CAMERA_FRAME ? m_oMv * m_vMc : m_oMv);
  }
  //! Displacement since the previous call, as a pose vector in the vehicle frame (the camera's for CAMERA_FRAME).
  void getDisplacement(const vpRobot::vpControlFrameType frame, vpColVector &q) override
  {
    vpHomogeneousMatrix d = m_oMvDisplacement.inverse() * m_oMv;
    if (frame == vpRobot::CAMERA_FRAME) {
      d = m_vMc.inverse() * d * m_vMc;
    }
    q = vpPoseVector(d);
    m_oMvDisplacement = m_oMv;
  }
  //! An AUV is not position-controlled here. \exception vpRobotException (wrongStateError) always.
  void setPosition(const vpRobot::vpControlFrameType, const vpColVector &) override
  {
    throw vpRobotException(vpRobotException::wrongStateError,
                           "vpSSLRobotAuvTemplate::setPosition: the vehicle is velocity-controlled only");
  }
  //! Identity: the six body velocities are the "joints".
  void get_eJe(vpMatrix &eJe) override { eJe.eye(6); }
  //! Body twist to odometry-frame twist: diag(oRv, oRv).
  void get_fJe(vpMatrix &fJe) override
  {
    fJe.resize(6, 6, true);
    const vpRotationMatrix oRv = m_oMv.getRotationMatrix();
    for (unsigned int i = 0; i < 3; ++i) {
      for (unsigned int j = 0; j < 3; ++j) {
        fJe[i][j] = fJe[i + 3][j + 3] = oRv[i][j];
      }
    }
  }

private:
  /*!
    YOUR VEHICLE: send the body twist \e v (surge, sway, heave m/s; roll, pitch, yaw rates rad/s) to the
    autopilot. Stand-in: nothing to send, readNavigation() integrates getVelocity() itself.
  */
  void sendBodyVelocity(const vpColVector &v) { (void)v; }

  /*!
    YOUR VEHICLE: read the navigation of this instant: the vehicle pose \e oMv in the odometry frame, its depth
    (m, positive down) and the front collision switch, and the time. Stand-in: a perfect vehicle starting at
    the odometry origin, the last command integrated over one time step (exponential map); no pressure sensor
    (depth NaN: vpSSLHomingBehaviour's search then does not heave) and no collision switch.
  */
  void readNavigation(vpHomogeneousMatrix &oMv, double &depth, bool &collision)
  {
    oMv = oMv * vpExponentialMap::direct(m_velocity, m_dt);
    m_t += m_dt;
    depth = NAN;
    collision = false;
  }

  vpFrameGrabber *m_grabber;
  vpHomogeneousMatrix m_vMc;
  double m_dt;
  double m_t;
  vpColVector m_velocity;
  vpHomogeneousMatrix m_oMv;
  vpHomogeneousMatrix m_oMvDisplacement;
  double m_depth;
  bool m_collision;
};

#endif
