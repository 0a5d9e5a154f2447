/*!
  \file vpSSLAuvSimulator.h
  \brief Simulated small AUV (the paper's Starbug): 6-DOF dynamics, thrusters, current, odometry and a front
  range sensor, driven through vpRobot::setVelocity() like any ViSP robot.
*/
#ifndef VP_SSL_AUV_SIMULATOR_H
#define VP_SSL_AUV_SIMULATOR_H

#include <visp3/core/vpColVector.h>
#include <visp3/core/vpGaussRand.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpTranslationVector.h>
#include <visp3/robot/vpRobot.h>
#include <visp3/ssl/vpSSLConfig.h>
#include <visp3/ssl_sim/vpSSLDeadReckoning.h>

/*!
  \class vpSSLAuvSimulator
  \ingroup group_ssl_sim
  \brief A 6-DOF rigid-body model of a small AUV with a forward-looking camera, velocity-controlled through its
  thrusters, for closing the visual-servo loop in simulation.

  Frames are those of vpSSLScenario: the world is North-East-Down with the water surface at z = 0; the vehicle
  frame is x forward (surge), y starboard (sway), z down (heave); the camera is mounted at vMc (default
  vpSSLScenario::getDefaultCameraToVehicle(): at the nose, optical axis along x); the target frame is the sheet
  frame (Z into the sheet, the printed side facing -Z).

  <b>Dynamics</b> (Fossen 2011, diagonal model about the centre of buoyancy), on the velocity relative to the
  water \f$ \nu_r = \nu - R^\top v_c \f$:
  \f[ (M_{RB} + M_A)\,\dot\nu = \tau - C(\nu_r)\,\nu_r - (D_l + D_q |\nu_r|)\,\nu_r - g(\eta) \f]
  (the current's own acceleration is neglected: it varies slowly). \f$ C \f$ is the rigid-body plus added-mass
  Coriolis matrix of a diagonal mass matrix; \f$ g \f$ the righting moment of a centre of gravity
  getParameters().zg below the centre of buoyancy, the vehicle neutrally buoyant. The pose moves with the body
  twist through the exponential map. Integration: semi-implicit Euler (velocity first, then the pose with the new
  velocity) every getIntegrationStep() seconds, several sub-steps per setTimeStep(); stable for the default
  figures down to steps of 20 ms.

  Default figures (the Starbug of the paper: 26 kg, 1.2 m long, 1.5 m/s top speed; a flat hull 1.2 x 0.6 x 0.3
  m; the drag and added-mass coefficients are estimates for such a hull, not measurements):
  | axis  | mass/inertia | added  | linear drag | quadratic drag | thruster limit | top speed |
  |-------|--------------|--------|-------------|----------------|----------------|-----------|
  | surge | 26 kg        | 2.6 kg | 6 N s/m     | 18 N s2/m2     | 49.5 N         | 1.5 m/s   |
  | sway  | 26 kg        | 26 kg  | 30 N s/m    | 80 N s2/m2     | 5 N (weak)     | 0.12 m/s  |
  | heave | 26 kg        | 26 kg  | 30 N s/m    | 80 N s2/m2     | 40 N           | 0.55 m/s  |
  | roll  | 0.98 kg m2   | 0.2    | 3 N m s     | 1 N m s2       | 4 N m          | 1.0 rad/s |
  | pitch | 3.3 kg m2    | 1.5    | 8 N m s     | 4 N m s2       | 10 N m         | 0.87 rad/s|
  | yaw   | 3.9 kg m2    | 1.5    | 6 N m s     | 4 N m s2       | 8 N m          | 0.85 rad/s|
  The surge thrust is set so that the drag balances it at exactly the top speed.

  <b>Commands.</b> setVelocity() takes the demanded body twist: in vpRobot::ARTICULAR_FRAME (also
  END_EFFECTOR_FRAME) as (surge, sway, heave, roll rate, pitch rate, yaw rate) in the vehicle frame (m/s, rad/s);
  in vpRobot::CAMERA_FRAME as a camera twist, mapped to the vehicle frame through vMc. The vehicle's own
  autopilot tracks it every integration step with a per-axis PI loop plus the drag as feed-forward, on the
  velocity through the water (what the propellers know): so a current drifts the vehicle, the response lags
  (about 0.5 s) and each axis saturates at its thruster limit. Roll and pitch have no integral term: an integrated
  rate error is an attitude error, which would hold the vehicle at any tilt against its righting moment; without
  it the vehicle levels itself, and a pitch-rate demand q gives a bounded pitch (where the righting moment
  balances the rate loop), as on a passively stable hull. Like vpSimulatorCamera, setVelocity() then
  advances the simulation by getTimeStep() seconds; step() advances it holding the last demand.
  A command with a NaN or infinite component, or of the wrong size, throws vpException and leaves the vehicle
  as it was (the previous demand is kept). Like vpSimulatorCamera, setVelocity() switches the robot to
  vpRobot::STATE_VELOCITY_CONTROL.

  <b>Sensors</b>, deterministic for the seed of reset(): odometry oMv from vpSSLDeadReckoning (IMU, compass,
  pressure sensor, velocity integration, with noise and drift), a depth sensor (truth plus white noise), and a
  front range sensor at the nose along the surge axis: the distance to the target's plane where the axis meets
  the target board (setTargetBoard()), up to getRangeSensorMax(), NaN when nothing is in front or the target is
  out of the water. The collision flag is set when the true nose-to-board distance is below
  setCollisionThreshold(); the board is rigid: the nose cannot go through it.

  <b>Target</b>: setTargetPose() moves it at any time (moved by hand, swaying on its line with the current);
  setTargetInWater(false) takes it out (a renderer should then not draw it, the range sensor sees nothing).

  \code
  vpSSLAuvSimulator auv;
  auv.setTimeStep(0.2);                               // one camera frame
  auv.reset(vpHomogeneousMatrix(-5., 0., 2.5, 0., 0., 0.), 42);
  auv.setTargetPose(vpSSLScenario("approach").getTargetHome());
  vpColVector v(6, 0.);
  v[0] = 0.5;                                         // surge 0.5 m/s
  for (int i = 0; i < 50; ++i) {
    auv.setVelocity(vpRobot::ARTICULAR_FRAME, v);     // 0.2 s of dynamics
    std::cout << auv.getTime() << " " << auv.getFrontRange() << std::endl;
  }
  \endcode
  See tutorial-ssl-servo.cpp.
*/
class VISP_SSL_EXPORT vpSSLAuvSimulator : public vpRobot
{
public:
  /*!
    \struct vpSSLAuvParameters
    \brief Physical figures of the vehicle, per axis in the order surge, sway, heave, roll, pitch, yaw.
  */
  struct vpSSLAuvParameters
  {
    double mass = 26.;                                     ///< Dry mass (kg), equal to the buoyancy.
    double inertia[3] = {0.975, 3.31, 3.9};                ///< Moments of inertia about x, y, z (kg m2).
    double addedMass[6] = {2.6, 26., 26., 0.2, 1.5, 1.5};  ///< Added mass / inertia per axis.
    double linearDrag[6] = {6., 30., 30., 3., 8., 6.};     ///< Linear damping per axis.
    double quadraticDrag[6] = {18., 80., 80., 1., 4., 4.}; ///< Quadratic damping per axis.
    double thrustLimit[6] = {49.5, 5., 40., 4., 10., 8.};  ///< Largest force (N) / torque (N m) per axis.
    double zg = 0.03;                                      ///< Centre of gravity below the buoyancy (m).
    double length = 1.2;                                   ///< Hull length (m): the nose is at x = length / 2.
    double velocityGain[6] = {2., 2., 2., 3., 3., 3.};     ///< Autopilot proportional gain (1/s).
    double velocityIntegralGain[6] = {1., 1., 1.,
                                      0., 0., 2.}; ///< Autopilot integral gain (1/s2); 0 in roll and pitch, see below.
  };

  //! The Starbug of the default figures, at the world origin, time step 0.04 s (vpSimulatorCamera's).
  vpSSLAuvSimulator();
  ~vpSSLAuvSimulator() override = default;

  //! Keeps the pose and the target, zeroes the velocity, the demand and the autopilot (vpRobot).
  void init() override;
  /*!
    Starts a run: vehicle at rest at \e wMv, time 0, autopilot zeroed, every sensor's noise seeded from \e seed.
    \exception vpException if wMv is not a finite rigid transform.
  */
  void reset(const vpHomogeneousMatrix &wMv, long seed);

  //! Physical figures (see the table above). \exception vpException if a mass, inertia or limit is not > 0.
  void setParameters(const vpSSLAuvParameters &parameters);
  const vpSSLAuvParameters &getParameters() const { return m_param; } ///< Physical figures.
  //! Steady speed reached on \e axis (0..5) under its full thrust, from the drag: sqrt-solve of Dl v + Dq v^2 = F.
  double getTopSpeed(unsigned int axis) const;

  //! Duration (s) simulated by each setVelocity(). \exception vpException if not > 0 and finite.
  void setTimeStep(double dt);
  double getTimeStep() const { return m_dt; } ///< See setTimeStep().
  //! Largest integration sub-step (s, default 0.005). \exception vpException if not in (0, 0.05].
  void setIntegrationStep(double h);
  double getIntegrationStep() const { return m_h; } ///< See setIntegrationStep().

  //! Camera pose in the vehicle frame (default vpSSLScenario::getDefaultCameraToVehicle()).
  void setCameraToVehicle(const vpHomogeneousMatrix &vMc) { m_vMc = vMc; }
  const vpHomogeneousMatrix &getCameraToVehicle() const { return m_vMc; } ///< vMc.

  /*!
    Water current (world frame, m/s): \e constant plus a sinusoidal sway of \e amplitude (m/s) and \e period (s)
    along the horizontal direction \e heading (rad from north towards east; pi/2: east-west).
    \exception vpException if a value is not finite or the period is not > 0 while the amplitude is not 0.
  */
  void setCurrent(const vpTranslationVector &constant, double amplitude = 0., double period = 10.,
                  double heading = M_PI / 2.);
  //! The current (world frame, m/s) at time \e t.
  vpTranslationVector getCurrent(double t) const;

  //! Target pose in the world (the sheet frame). \exception vpException if not a finite rigid transform.
  void setTargetPose(const vpHomogeneousMatrix &wMo);
  const vpHomogeneousMatrix &getTargetPose() const { return m_wMo; } ///< wMo.
  //! Puts the target in the water or takes it out (then it is neither sensed nor rendered, nor an obstacle).
  void setTargetInWater(bool inWater) { m_targetInWater = inWater; }
  bool isTargetInWater() const { return m_targetInWater; } ///< See setTargetInWater().
  /*!
    The rigid board carrying the target sheet, centred on the target origin in its plane: \e width x \e height
    (m, default 0.6 x 0.45, an A3 sheet on a frame). \exception vpException if not > 0.
  */
  void setTargetBoard(double width, double height);

  //! Nose-to-board distance (m) below which the collision flag is set (default 0.02). \exception if < 0.
  void setCollisionThreshold(double distance);
  //! Front range sensor: largest range (m, default 5) and noise standard deviation (m, default 0.01).
  void setRangeSensor(double maxRange, double sigma);
  double getRangeSensorMax() const { return m_rangeMax; } ///< See setRangeSensor().

  // vpRobot interface.
  /*!
    Demanded twist, see the class description; advances the simulation by getTimeStep().
    \exception vpException (badValue) for a non-finite component, (dimensionError) for a size other than 6,
    (notImplementedError) for REFERENCE_FRAME or MIXT_FRAME.
  */
  void setVelocity(const vpRobot::vpControlFrameType frame, const vpColVector &vel) override;
  //! Teleports the vehicle (REFERENCE_FRAME or ARTICULAR_FRAME: vpPoseVector of wMv; CAMERA_FRAME: of wMc), at rest.
  void setPosition(const vpRobot::vpControlFrameType frame, const vpColVector &q) override;
  //! Pose vector of wMv (REFERENCE_FRAME, ARTICULAR_FRAME, END_EFFECTOR_FRAME) or of wMc (CAMERA_FRAME).
  void getPosition(const vpRobot::vpControlFrameType frame, vpColVector &q) override;
  //! Displacement since the previous call, as a pose vector in the vehicle (or camera) frame.
  void getDisplacement(const vpRobot::vpControlFrameType frame, vpColVector &q) override;
  //! Identity: the six body velocities are the "joints".
  void get_eJe(vpMatrix &eJe) override;
  //! Body twist to world twist: diag(wRv, wRv).
  void get_fJe(vpMatrix &fJe) override;

  //! Advances \e duration seconds holding the last demand. \exception vpException if not >= 0 and finite.
  void step(double duration);

  double getTime() const { return m_t; }                        ///< Simulated time (s) since reset().
  const vpHomogeneousMatrix &get_wMv() const { return m_wMv; }  ///< True vehicle pose.
  vpHomogeneousMatrix get_wMc() const { return m_wMv * m_vMc; } ///< True camera pose.
  vpHomogeneousMatrix get_cMo() const;                          ///< True target pose in the camera frame.
  const vpColVector &getBodyVelocity() const { return m_nu; }   ///< True body twist over ground.
  vpColVector getWaterVelocity() const;                         ///< Body twist through the water.
  const vpColVector &getDemand() const { return m_demand; }     ///< Demanded body twist.
  const vpColVector &getThrust() const { return m_tau; }        ///< Last forces/torques (saturated).
  //! Number of axes at their thruster limit during the last integration step.
  unsigned int getNbSaturatedAxes() const { return m_nbSaturated; }

  //! Odometry pose oMv (vpSSLDeadReckoning), updated at each setVelocity() or step().
  const vpHomogeneousMatrix &getOdometry() const { return m_odometry.get_oMv(); }
  //! The odometry model, to change its noise figures before reset().
  vpSSLDeadReckoning &getDeadReckoning() { return m_odometry; }
  //! Depth sensor (m): true depth of the vehicle origin plus white noise (sigma 0.02 m), one draw per call.
  double getDepthMeasurement();
  //! True depth (m) of the vehicle origin.
  double getDepth() const { return m_wMv[2][3]; }
  //! True nose-to-board distance along the surge axis (m), NaN if the axis misses the board or it is out.
  double getTrueFrontRange() const;
  //! Front range sensor (m): getTrueFrontRange() plus noise, NaN beyond its range; one draw per call.
  double getFrontRange();
  //! True while the nose is within the collision threshold of the board.
  bool getCollision() const { return m_collision; }
  //! Time of the first collision since reset() (s), NaN if none.
  double getFirstCollisionTime() const { return m_firstCollision; }

private:
  void integrate(double h);
  void accelerations(const vpColVector &nuR, const vpColVector &tau, vpColVector &nuDot) const;
  void autopilot(const vpColVector &nuR, double h);
  void contact();
  bool frontRay(double &distance) const;

  vpSSLAuvParameters m_param;
  double m_dt;
  double m_h;
  vpHomogeneousMatrix m_vMc;
  vpTranslationVector m_current;
  double m_swayAmplitude, m_swayPeriod, m_swayHeading;
  vpHomogeneousMatrix m_wMo;
  bool m_targetInWater;
  double m_boardWidth, m_boardHeight;
  double m_collisionThreshold;
  double m_rangeMax, m_rangeSigma;

  double m_t;
  vpHomogeneousMatrix m_wMv;
  vpHomogeneousMatrix m_wMvLastDisplacement;
  vpColVector m_nu;       //!< body twist over ground
  vpColVector m_demand;   //!< demanded body twist through the water
  vpColVector m_integral; //!< autopilot integrators
  vpColVector m_tau;      //!< applied forces and torques
  unsigned int m_nbSaturated;
  bool m_collision;
  double m_firstCollision;
  vpSSLDeadReckoning m_odometry;
  vpGaussRand m_depthNoise;
  vpGaussRand m_rangeNoise;
};

#endif
