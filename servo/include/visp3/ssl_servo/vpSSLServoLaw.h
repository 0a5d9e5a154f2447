/*!
  \file vpSSLServoLaw.h
  \brief Image-based visual servoing with a depth stand-off for an under-actuated vehicle.
*/
#ifndef VP_SSL_SERVO_LAW_H
#define VP_SSL_SERVO_LAW_H

#include <string>
#include <vector>

#include <visp3/core/vpColVector.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpMatrix.h>
#include <visp3/core/vpVelocityTwistMatrix.h>
#include <visp3/ssl/vpSSLConfig.h>
#include <visp3/ssl_servo/vpSSLServoInput.h>
#include <visp3/visual_features/vpFeatureDepth.h>
#include <visp3/visual_features/vpFeaturePoint.h>
#include <visp3/vs/vpAdaptiveGain.h>
#include <visp3/vs/vpServo.h>

/*!
  \enum vpSSLVehicleAxis
  \ingroup group_ssl_servo
  \brief Index of a vehicle axis in the 6-vector commands (vehicle frame: x forward, y starboard, z down).
*/
enum vpSSLVehicleAxis
{
  SSL_AXIS_SURGE = 0, ///< Forward speed u along x (m/s).
  SSL_AXIS_SWAY = 1,  ///< Starboard speed v along y (m/s).
  SSL_AXIS_HEAVE = 2, ///< Downward speed w along z (m/s).
  SSL_AXIS_ROLL = 3,  ///< Roll rate p about x (rad/s).
  SSL_AXIS_PITCH = 4, ///< Pitch rate q about y (rad/s).
  SSL_AXIS_YAW = 5    ///< Yaw rate r about z (rad/s).
};

/*!
  \enum vpSSLServoStatus
  \ingroup group_ssl_servo
  \brief Outcome of the last vpSSLServoLaw computation. Anything but SSL_SERVO_OK comes with a zero command.
*/
enum vpSSLServoStatus
{
  SSL_SERVO_OK,               ///< Command computed (possibly saturated, see vpSSLServoLaw::isSaturated()).
  SSL_SERVO_NO_TARGET,        ///< Input not valid or without any point.
  SSL_SERVO_INVALID_INPUT,    ///< A coordinate or depth is NaN, infinite or implausibly large.
  SSL_SERVO_BEHIND_CAMERA,    ///< A point has a depth <= 0.
  SSL_SERVO_NUMERICAL_FAILURE ///< The law itself gave a non-finite value or vpServo threw.
};

/*!
  \class vpSSLServoLaw
  \ingroup group_ssl_servo
  \brief ViSP image-based visual servoing of the target points plus a log-depth stand-off feature, mapped onto
  the axes an under-actuated vehicle can drive.

  Features (vpServo, interaction matrix computed at the current features, vpServo::CURRENT):
  - every input point as a vpFeaturePoint (x, y) with its current depth Z, its desired value the projection of
    its object point at the desired pose cdMo: the target centre on the optical axis at the stand-off distance
    Z*, the sheet facing the camera (identity rotation);
  - one vpFeatureDepth log(Z/Z*) of the target centre (its depth from cMo when the input has a pose, the mean
    point depth otherwise), desired value 0.

  Under-actuation as for ViSP's mobile robots (vpServo::EYEINHAND_L_cVe_eJe): the camera twist is
  v_c = cVe eJe qdot, with cVe from the camera mounting vMc (setCameraToVehicle()) and eJe = S W, S the 6 x n
  selection of the n enabled vehicle axes (setAxisEnabled()) and W their weights in (0, 1] (setAxisWeight());
  the law gives qdot = -lambda (L cVe eJe)^+ e and the vehicle command W qdot. Among the motions that give the
  same feature velocity this is the one of least weighted norm: an axis of small weight is used only where the
  others cannot do its work. Defaults: sway disabled (marginal on the Starbug), roll and pitch weighted 0.3 (the
  hull rights them), surge, heave and yaw 1.

  Conditioning: for a distant target heave and pitch move the image almost alike (v_y = Z w_x), so the smallest
  singular value of L cVe eJe is ~1e-4 of the largest. Inverting it turns a small inconsistency of the error (as
  when docking) into a heave-pitch command at the limits, so singular values below setPseudoInverseThreshold()
  (default 0.005 of the largest) are dropped.

  Gain: vpAdaptiveGain (setGain()), high near convergence, low for large errors. Every vehicle axis is limited
  (setVelocityLimits()); the whole vector is scaled down together so that its direction is kept.

  Depths: Z is floored at setMinDepth() (default 0.05 m) in the features, so a tiny depth cannot blow up 1/Z;
  the stand-off Z* is floored at the same value, so Z* = 0 (docking) aims at 0.05 m (vpSSLHomingBehaviour keeps
  a minimum surge there until the collision sensor trips). Below setMinPointStandOff() (default 0.3 m) the
  desired image of the points would leave any camera's field of view, so when Z* is below it the desired point
  features are those of the centred, facing target at depth min(Zc, 0.3 m), Zc the current centre depth: the
  points then only steer (centring, facing) and the depth feature alone closes the range, without the two
  fighting over it.

  Safety: any input that is not usable (see vpSSLServoStatus) gives a zero command and a status; the output is
  always finite and within the limits.

  \code
  vpSSLServoLaw law;                                            // Starbug axes: all but sway
  law.setCameraToVehicle(vMc);                                  // camera pose in the vehicle frame
  law.setStandOff(2.0);
  vpColVector qdot = law.computeControlLaw(vpSSLServoInput::fromTracker(tracker)); // vehicle frame
  if (law.getStatus() == SSL_SERVO_OK)
    robot.setVelocity(vpRobot::ARTICULAR_FRAME, qdot);
  // or on a camera robot (vpSimulatorCamera): robot.setVelocity(vpRobot::CAMERA_FRAME, law.getCameraVelocity());
  \endcode
  See doc/servo.md and test/test_servo_law.cpp.
*/
class VISP_SSL_EXPORT vpSSLServoLaw
{
public:
  /*!
    Law with the defaults: stand-off 2 m; Starbug axes (surge, heave, roll, pitch, yaw enabled, sway disabled;
    roll and pitch weighted 0.3); pseudo-inverse threshold 0.005; camera mount forwardCameraMount(0); adaptive gain (0.8
    at zero, 0.2 at infinity, slope 15); limits surge 0.5 m/s, sway 0.2 m/s, heave 0.3 m/s, roll, pitch 0.3 rad/s, yaw
    0.5 rad/s.
  */
  vpSSLServoLaw();

  /*!
    The forward-looking camera of a torpedo-like AUV, \e ahead metres in front of the vehicle origin: optical
    axis (camera z) along the vehicle's x (forward), camera x along the vehicle's y (starboard), camera y along
    its z (down). Same mounting as vpSSLScenario::getDefaultCameraToVehicle() with ahead = 0.5.
  */
  static vpHomogeneousMatrix forwardCameraMount(double ahead = 0.);

  //! Stand-off Z* (m, >= 0; 0 docks). \exception vpException if negative or not finite.
  void setStandOff(double Zstar);
  //! Stand-off Z* (m).
  double getStandOff() const { return m_standOff; }
  //! Floor of every depth used in the features and of Z* (m, > 0, default 0.05). \exception vpException if <= 0.
  void setMinDepth(double Zmin);
  //! Stand-off below which the desired point features follow the current range (m, > 0, default 0.3).
  //! \exception vpException if <= 0.
  void setMinPointStandOff(double Zmin);

  //! Camera pose in the vehicle frame vMc (the vehicle's "end-effector" e). \exception vpException if not finite.
  void setCameraToVehicle(const vpHomogeneousMatrix &vMc);
  //! Camera pose in the vehicle frame.
  const vpHomogeneousMatrix &getCameraToVehicle() const { return m_vMc; }
  /*!
    Configures the law for a robot that moves the camera itself (vpSimulatorCamera, a robot arm's end
    effector): vMc = identity, all six axes enabled with weight 1 and ViSP's pseudo-inverse threshold 1e-6 (a
    camera that follows every twist at once needs the weak direction to reach the facing pose). The "vehicle"
    command is then the camera twist. See tutorial-ssl-ibvs.cpp (vpSimulatorCamera through rendered images).
  */
  void setCameraRobot();

  //! Enables or disables a vehicle axis (a disabled axis is removed from eJe and its command is 0).
  void setAxisEnabled(vpSSLVehicleAxis axis, bool enabled);
  //! Whether \e axis is enabled.
  bool getAxisEnabled(vpSSLVehicleAxis axis) const;
  /*!
    Weight of an enabled axis, in (0, 1] (default 1, roll and pitch 0.3): the column of eJe and the command of
    that axis are multiplied by it, so that the least-squares solution prefers the axes of larger weight (see the
    class description). \exception vpException outside (0, 1].
  */
  void setAxisWeight(vpSSLVehicleAxis axis, double weight);
  //! Weight of \e axis.
  double getAxisWeight(vpSSLVehicleAxis axis) const;

  /*!
    Singular values of L cVe eJe below \e ratio times the largest are dropped from its pseudo-inverse
    (vpServo::setPseudoInverseThreshold(); default 0.005, see the class description).
    \exception vpException unless 0 <= ratio < 1.
  */
  void setPseudoInverseThreshold(double ratio);
  //! Relative pseudo-inverse threshold.
  double getPseudoInverseThreshold() const { return m_pseudoInverseThreshold; }

  //! Constant gain lambda > 0. \exception vpException if not > 0.
  void setGain(double lambda);
  //! Adaptive gain (vpAdaptiveGain): \e gain0 at zero error, \e gainInf for large errors, \e slope0 at zero.
  void setGain(double gain0, double gainInf, double slope0);
  /*!
    Limits of the vehicle axes (6-vector, m/s and rad/s, each > 0), in the order of vpSSLVehicleAxis.
    \exception vpException if the size is not 6 or a limit is not > 0 and finite.
  */
  void setVelocityLimits(const vpColVector &vmax);
  //! Limits of the vehicle axes.
  const vpColVector &getVelocityLimits() const { return m_vmax; }

  /*!
    Servo law toward the stand-off: the vehicle-axes command (6-vector, vpSSLVehicleAxis order; disabled axes
    0). Zero with a status other than SSL_SERVO_OK on unusable input.
  */
  vpColVector computeControlLaw(const vpSSLServoInput &input);
  /*!
    Centring only (ALIGN state of vpSSLHomingBehaviour): the target centre's image point driven to the image
    centre by the enabled axes that move the image across: translations across the optical axis and rotations
    that turn it (heave, sway, pitch and yaw of a forward-looking camera). Motions along the optical axis (surge,
    the roll about it) cannot centre and are left out, so the range is kept. Axis weights apply as in
    computeControlLaw(): with the defaults a target below is centred mostly by heave, since the hull rights its
    pitch. Same checks and outputs.
  */
  vpColVector computeCentringLaw(const vpSSLServoInput &input);

  /*!
    What the law would say of \e input before computing anything: SSL_SERVO_OK when it can servo on it, else the
    reason (no target, a non-finite or implausible value, a depth <= 0).
  */
  static vpSSLServoStatus checkInput(const vpSSLServoInput &input);
  /*!
    Target centre (centroid of the object points) of a usable \e input (checkInput() OK): its normalised image
    coordinates \e x, \e y and depth \e Z, through cMo when the input has a usable pose, else the mean of the
    points. \return false (outputs NaN) when the input is not usable.
  */
  static bool getTargetCentre(const vpSSLServoInput &input, double &x, double &y, double &Z);

  //! Status of the last computation.
  vpSSLServoStatus getStatus() const { return m_status; }
  //! Name of a status ("ok", "no-target", "invalid-input", "behind-camera", "numerical-failure").
  static std::string getStatusName(vpSSLServoStatus status);
  //! Whether the last command was scaled down by the velocity limits.
  bool isSaturated() const { return m_saturated; }
  //! Last vehicle-axes command (6-vector).
  const vpColVector &getVelocity() const { return m_velocity; }
  //! Camera twist equivalent to the last command, cVv getVelocity() (6-vector, camera frame).
  const vpColVector &getCameraVelocity() const { return m_cameraVelocity; }
  //! The camera twist of a vehicle-axes command \e v under this law's camera mounting.
  vpColVector toCameraVelocity(const vpColVector &v) const;
  //! Last task error e = s - s* (empty after a failure).
  const vpColVector &getError() const { return m_error; }
  /*!
    Task Jacobian L cVe eJe of the last computation (one row per feature coordinate, one column per enabled axis,
    weights included; empty after a failure), as vpServo::getTaskJacobian(): its singular values are what
    setPseudoInverseThreshold() compares.
  */
  const vpMatrix &getTaskJacobian() const { return m_taskJacobian; }
  //! Mean image error of the points, sqrt(mean |p - p*|^2) in normalised coordinates (NaN after a failure).
  double getPointError() const { return m_pointError; }
  //! Depth of the target centre in the last valid input (m, NaN after a failure).
  double getCentreDepth() const { return m_centreDepth; }
  //! Target centre in the last valid input, normalised image coordinates (NaN after a failure).
  void getCentre(double &x, double &y) const
  {
    x = m_centreX;
    y = m_centreY;
  }
  /*!
    Desired pose of the object frame in the camera frame for \e input: the centroid of its object points at
    (0, 0, Z*) (or at the docking depth described above when Z* < setMinPointStandOff()), identity rotation.
  */
  vpHomogeneousMatrix getDesiredPose(const vpSSLServoInput &input) const;
  //! The vehicle Jacobian eJe = S W of the enabled axes (6 x n), weights included.
  vpMatrix getVehicleJacobian() const;

private:
  void computeCentre(const vpSSLServoInput &input);
  vpColVector solve(const vpSSLServoInput &input, bool centringOnly);
  vpColVector finish(const vpColVector &qdotEnabled, const std::vector<unsigned int> &axes);
  void fail(vpSSLServoStatus status);

  double m_standOff;
  double m_minDepth;
  double m_minPointStandOff;
  vpHomogeneousMatrix m_vMc;
  bool m_enabled[6];
  double m_weight[6];
  double m_pseudoInverseThreshold;
  vpAdaptiveGain m_gain;
  vpColVector m_vmax;

  vpSSLServoStatus m_status;
  bool m_saturated;
  vpColVector m_velocity;
  vpColVector m_cameraVelocity;
  vpColVector m_error;
  vpMatrix m_taskJacobian;
  double m_pointError;
  double m_centreDepth;
  double m_centreX;
  double m_centreY;
  std::vector<vpFeaturePoint> m_s; // kept as members: vpServo stores pointers to its features
  std::vector<vpFeaturePoint> m_sd;
  vpFeatureDepth m_depth;
  vpFeatureDepth m_depthDesired;
};

#endif
