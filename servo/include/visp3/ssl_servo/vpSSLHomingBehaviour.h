/*!
  \file vpSSLHomingBehaviour.h
  \brief Homing and docking state machine of the paper's Sec. 5.2: search, align, home, dock.
*/
#ifndef VP_SSL_HOMING_BEHAVIOUR_H
#define VP_SSL_HOMING_BEHAVIOUR_H

#include <string>

#include <visp3/core/vpColVector.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/robot/vpRobot.h>
#include <visp3/ssl/vpSSLConfig.h>
#include <visp3/ssl_servo/vpSSLServoInput.h>
#include <visp3/ssl_servo/vpSSLServoLaw.h>

/*!
  \enum vpSSLHomingState
  \ingroup group_ssl_servo
  \brief State of vpSSLHomingBehaviour.
*/
enum vpSSLHomingState
{
  SSL_HOMING_SEARCH, ///< No target: spin about the vertical axis while the depth oscillates.
  SSL_HOMING_ALIGN,  ///< Target seen: turn (yaw, pitch) until it is centred in the image.
  SSL_HOMING_HOME,   ///< Servo law holding the stand-off.
  SSL_HOMING_DOCK,   ///< Servo law with stand-off 0 until the front collision sensor trips.
  SSL_HOMING_DOCKED  ///< Collision while docking: zero command until reset().
};

/*!
  \class vpSSLHomingBehaviour
  \ingroup group_ssl_servo
  \brief The homing behaviour of the paper's Sec. 5.2 as a state machine driving vpSSLServoLaw.

  Call update() once per frame with the time, the target input, the vehicle depth and the collision flag; it
  returns the vehicle-axes command (vpSSLVehicleAxis order: surge, sway, heave, roll, pitch, yaw rates in the
  vehicle frame x forward, y starboard, z down). apply() sends the last command to any vpRobot.

  The target is \e seen at a frame when the input is valid with at least setMinPoints() measured points
  (nbPoints). Transitions, evaluated in update():
  - SEARCH: seen -> ALIGN. Command: yaw rate setSearchPattern() and heave tracking a depth that oscillates
    between the pattern's two depths (triangle wave), so that a target above or below is swept. With odometry
    (the update() that takes oMv) the search also holds its ground (setSearchHold()): surge (and sway, when the
    law enables it) push the vehicle back in front of the target where it was last seen, or where the search began,
    so that a current does not carry it off while it turns.
  - ALIGN: the target centre within setAlignTolerance() of the optical axis, or setAlignTimeout() seconds in
    ALIGN with the target seen -> HOME (-> DOCK if docking was requested). Command: vpSSLServoLaw::computeCentringLaw()
  (heave, pitch and yaw; no surge).
  - HOME: docking requested (startDocking(), or setAutoDock() after holding the stand-off) -> DOCK. Command:
    vpSSLServoLaw::computeControlLaw() at the stand-off, plus integral action on the range
    (setRangeIntegralGain()) that balances a current along the target's axis; DOCK keeps that share of the surge.
  - DOCK: collision -> DOCKED. Command: the servo law with stand-off 0. When the target is lost within
    setBlindDockRange() of the camera (too close to be seen whole), the last surge is held (at least
    setBlindDockSpeed()) with the other axes at zero.
  - ALIGN, HOME, DOCK: not seen for more than setLostTimeout() seconds -> SEARCH (the docking request stays).
    While not seen but the input is still valid (a tracker predicting the pose), the law keeps servoing on the
    prediction; with an invalid input the command is zero (hover), except the blind docking above.
  - DOCKED: stays until reset(). A collision outside DOCK is only counted (getCollision()).

  \code
  vpSSLHomingBehaviour homing;
  homing.getServoLaw().setCameraToVehicle(vMc);
  homing.setStandOff(2.0);
  homing.setAutoDock(20.);                      // dock after 20 s at the stand-off
  while (homing.getState() != SSL_HOMING_DOCKED) {
    tracker.track(I, oMv);
    homing.update(t, vpSSLServoInput::fromTracker(tracker), vehicleDepth, frontCollision);
    homing.apply(auv);                          // vpRobot::ARTICULAR_FRAME: vehicle axes
  }
  \endcode
  See doc/servo.md, test/test_servo_behaviour.cpp and tutorial-ssl-auv-driver.cpp (a vpRobot driver skeleton for an
  AUV driven by this behaviour).
*/
class VISP_SSL_EXPORT vpSSLHomingBehaviour
{
public:
  /*!
    Behaviour with the defaults: stand-off 2 m; search yaw rate 0.2 rad/s, depth between 1 and 3 m with a
    period of 40 s, depth gain 0.5 1/s; align tolerance 5 deg; lost timeout 3 s; min points 1; no auto dock;
    blind docking within 0.6 m at 0.1 m/s at least. The servo law's own defaults (vpSSLServoLaw()).
  */
  vpSSLHomingBehaviour();

  //! The servo law (camera mounting, axes, gains, limits). Its stand-off is set by update() from the state.
  vpSSLServoLaw &getServoLaw() { return m_law; }
  //! The servo law.
  const vpSSLServoLaw &getServoLaw() const { return m_law; }

  //! Stand-off held in HOME (m, > 0). \exception vpException if not > 0 and finite.
  void setStandOff(double Zstar);
  //! Stand-off held in HOME (m).
  double getStandOff() const { return m_standOff; }
  /*!
    Search pattern: yaw rate (rad/s, sign gives the direction, 0 allowed), depth oscillating between
    \e depthMin and \e depthMax (m, world depth, positive down) with period \e period (s); heave = depthGain
    (depth reference - depth), saturated by the law's heave limit.
    \exception vpException if not finite, depthMin > depthMax, period or depthGain not > 0, or beyond the
    bounds |yawRate| <= 10 rad/s, |depthMin|, |depthMax| <= 11000 m, period <= 86400 s, depthGain <= 100.
  */
  void setSearchPattern(double yawRate, double depthMin, double depthMax, double period, double depthGain = 0.5);
  //! Angle between the optical axis and the target centre below which ALIGN ends (rad, default 5 deg).
  void setAlignTolerance(double angle);
  /*!
    Time in ALIGN after which the full law takes over even if the target is not centred (s, >= 0, may be
    infinite; default 5). A cross current the vehicle cannot counter without sway holds the target off-centre;
    ALIGN, which does not drive the range, would let the vehicle drift away.
  */
  void setAlignTimeout(double seconds);
  //! Time without the target after which ALIGN, HOME or DOCK fall back to SEARCH (s, >= 0, default 3).
  void setLostTimeout(double seconds);
  //! Measured points (input nbPoints) needed for the target to count as seen (>= 1, default 1).
  void setMinPoints(unsigned int n);
  /*!
    Automatic docking: after \e holdSeconds in HOME with the range within \e rangeTolerance (m) of the
    stand-off and the target centre within \e angleTolerance (rad) of the optical axis, HOME -> DOCK.
    holdSeconds < 0 disables it (default). In a cross current an under-actuated vehicle cannot hold the
    stand-off (it weathervanes round the target): wider tolerances and a short hold let it dock before it drifts
    off the target's axis (doc/servo-simulation.md, Monte Carlo).
    \exception vpException if a value is not finite or a tolerance is not > 0.
  */
  void setAutoDock(double holdSeconds, double rangeTolerance = 0.1, double angleTolerance = 5. * M_PI / 180.);
  //! Blind final approach: range (m) below which a lost target in DOCK keeps the surge, and its minimum speed.
  void setBlindDock(double range, double minSpeed);
  /*!
    Station keeping during SEARCH when update() is given the odometry. The goal: once the target has been seen
    with a pose (vpSSLServoInput::hasPose), the point on its axis at the stand-off, from where it is in view
    whatever the vehicle drifted to (and, from closer to the board's plane than that, first straight out along
    the axis, so that the way back does not cross the board); before, the odometry position of the last step where
    the target was seen, or of the first step with odometry. Surge = \e gain times the horizontal distance to the
    goal along the vehicle's heading, saturated at \e maxSpeed (m/s) and the law's surge limit; the same on sway
    when the law enables that axis. While the vehicle turns the surge pushes back whenever the nose points along
    the error, about 2/pi of \e maxSpeed on average. \e gain = 0 disables it. Default: 0.5 1/s, 0.3 m/s.
    The hold is as good as the odometry over a search (seconds to a minute): it needs the velocity over the ground
    (a DVL or a visual odometry), not through the water.
    \exception vpException if a value is not finite or is < 0.
  */
  void setSearchHold(double gain, double maxSpeed);
  /*!
    Integral action on the range in HOME: the surge gets \e gain times the integral of (range - stand-off) over
    the time in HOME spent within half the stand-off of it (the approach from afar winds nothing up), that share
    bounded by half the law's surge limit; DOCK keeps the share HOME ended with. A proportional law alone leaves the
    offset at which its surge balances a head or tail current (0.5 m for 0.12 m/s with the default gains), enough to
    keep the auto-dock's range tolerance from ever being met. \e gain = 0 disables it (default); 0.05 1/s^2 with the
    default law settles in about 20 s.
    \exception vpException if \e gain is not finite or is < 0.
  */
  void setRangeIntegralGain(double gain);
  /*!
    Docking in transit across a current (needs update() with the odometry). An under-actuated vehicle cannot
    hold a stand-off in a cross current stronger than its sway thruster: the law keeps the target centred by
    yawing and the current carries the vehicle round the target until the sheet is seen edge-on and lost. It
    can still reach the board if it does not stop: heading upstream of the line of sight by the crab angle
    asin(c / u) makes the ground track a straight line to the target for a cross current c and a surge u.

    When enabled, the current is estimated from the odometry against the command (getCurrentEstimate()). Once
    the estimate has settled (10 s of odometry) and its component across the line of sight reaches
    \e crossCurrent (m/s) while the target is seen, ALIGN and HOME request docking at once instead of holding
    the stand-off. In DOCK, with a settled estimate, the law servoes the image of a virtual camera yawed by the
    crab angle, so that the target is held that far off the optical axis on the upstream side, with the law's
    surge limit lifted so that a saturated surge does not slow the turn; the surge is the docking law's closing
    speed along the line of sight minus the current (its direction is the crab angle, at most \e maxCrab; beyond,
    the surge grows to c / sin(\e maxCrab), bounded by the law's surge limit), faded in as the nose turns to
    the crab angle. Where the physics stops: across a current above the surge limit times sin(\e maxCrab)
    (0.17 m/s with the defaults) the vehicle drifts by the rest during the approach; the faster approach also
    means a harder contact. The 0.1 m/s default: below it the stand-off hold docks (doc/servo-simulation.md,
    "Docking in transit").
    Default: disabled; 0.1 m/s, 20 deg (the 640 x 480 camera's half field of view is 30 deg).
    \exception vpException if \e crossCurrent is not finite or < 0, or \e maxCrab is not in (0, pi/2).
  */
  void setDockInTransit(bool enable, double crossCurrent = 0.1, double maxCrab = 20. * M_PI / 180.);
  //! Whether docking in transit is enabled (setDockInTransit()).
  bool getDockInTransit() const { return m_transitEnabled; }
  /*!
    The water current estimated from the odometry: the velocity over the ground (odometry positions of
    successive update() calls) minus the velocity through the water, modelled as the autopilot's first-order
    response (0.5 s) to the commands, low-pass filtered with a 5 s time constant. Its errors are the odometry's
    (a 5 % scale error is 0.025 m/s at 0.5 m/s) and the vehicle's departures from the commands (sideslip in a
    turn, thrust saturation).
    \param cx, cy : current along the odometry frame's x and y axes (m/s).
    \return false (cx, cy NaN) before two steps with odometry.
  */
  bool getCurrentEstimate(double &cx, double &cy) const;
  //! Crab angle the last DOCK step servoed (rad, positive with the target starboard of the nose; 0 otherwise).
  double getCrabAngle() const { return m_crabAngle; }
  //! Requests docking: HOME -> DOCK at the next update() (ALIGN -> DOCK directly once aligned).
  void startDocking() { m_dockRequested = true; }
  //! Cancels a docking request; DOCK -> HOME at the next update().
  void stopDocking() { m_dockRequested = false; }
  //! Whether docking is requested.
  bool getDockingRequested() const { return m_dockRequested; }

  /*!
    One control step.
    \param t : time (s), non-decreasing; a non-finite or decreasing time keeps the previous one.
    \param input : the target at this frame (vpSSLServoInput::none() when nothing was found).
    \param vehicleDepth : vehicle depth (m, positive down; NaN if unknown: the search pattern then does not heave).
    \param collision : the front collision sensor.
    \return the vehicle-axes command (6-vector), always finite and within the law's limits.
  */
  vpColVector update(double t, const vpSSLServoInput &input, double vehicleDepth, bool collision);
  /*!
    The same step with the vehicle's odometry \e oMv (vehicle pose in a fixed frame with z down, e.g.
    vpSSLTracker's odometry input): SEARCH then holds its ground (setSearchHold()). A non-finite \e oMv counts as
    no odometry at this step.
  */
  vpColVector update(double t, const vpSSLServoInput &input, double vehicleDepth, bool collision,
                     const vpHomogeneousMatrix &oMv);

  /*!
    Sends the last command to \e robot: vpRobot::ARTICULAR_FRAME sends the vehicle-axes command (an AUV
    simulator or driver), vpRobot::CAMERA_FRAME its camera twist (vpSimulatorCamera, arms). Puts the robot in
    velocity control first if it is not.
    \exception vpException for any other frame.
  */
  void apply(vpRobot &robot, vpRobot::vpControlFrameType frame = vpRobot::ARTICULAR_FRAME) const;

  //! Back to SEARCH, timers and docking request cleared.
  void reset();

  //! Current state.
  vpSSLHomingState getState() const { return m_state; }
  //! Name of a state ("search", "align", "home", "dock", "docked").
  static std::string getStateName(vpSSLHomingState state);
  //! Time spent in the current state (s).
  double getTimeInState() const { return m_time - m_stateStart; }
  //! Whether the target was seen at the last update().
  bool getTargetSeen() const { return m_seen; }
  //! Time since the target was last seen (s; infinity if never).
  double getTimeSinceSeen() const;
  //! Range (depth of the target centre, m) of the last update()'s input; NaN when it was not usable.
  double getRange() const { return m_range; }
  //! Depth reference of the search pattern at the last update() (m; NaN outside SEARCH).
  double getSearchDepth() const { return m_searchDepth; }
  //! Last vehicle-axes command.
  const vpColVector &getVelocity() const { return m_velocity; }
  //! Camera twist of the last command (camera frame).
  const vpColVector &getCameraVelocity() const { return m_cameraVelocity; }
  //! Collisions seen by update() (rising edges).
  unsigned int getCollision() const { return m_nbCollisions; }

private:
  void setState(vpSSLHomingState state);
  vpColVector searchCommand(double vehicleDepth);
  vpColVector step(double t, const vpSSLServoInput &input, double vehicleDepth, bool collision,
                   const vpHomogeneousMatrix *oMv);
  vpColVector blindDockCommand() const;
  void updateCurrentEstimate(const vpHomogeneousMatrix &oMv);
  bool lineOfSightCurrent(bool usable, double xc, double &across, double &along) const;
  vpColVector transitDockCommand(const vpSSLServoInput &input, double range, double across, double along);

  vpSSLServoLaw m_law;
  double m_standOff;
  double m_searchYawRate;
  double m_searchDepthMin;
  double m_searchDepthMax;
  double m_searchPeriod;
  double m_searchDepthGain;
  double m_alignTolerance;
  double m_lostTimeout;
  unsigned int m_minPoints;
  double m_autoDockHold;
  double m_autoDockRangeTolerance;
  double m_autoDockAngleTolerance;
  double m_alignTimeout;
  double m_blindDockRange;
  double m_blindDockSpeed;
  double m_searchHoldGain;
  double m_searchHoldSpeed;
  double m_rangeIntegralGain;
  bool m_transitEnabled;
  double m_transitCrossCurrent;
  double m_transitMaxCrab;

  vpSSLHomingState m_state;
  bool m_dockRequested;
  bool m_started;
  double m_time;
  double m_stateStart;
  double m_lastSeen;
  double m_holdStart;
  bool m_seen;
  bool m_lastCollision;
  unsigned int m_nbCollisions;
  double m_lastRange;
  double m_range;
  double m_lastSurge;
  double m_searchDepth;
  bool m_hasOdometry;        // odometry at this step
  double m_position[2];      // horizontal odometry position at this step
  double m_heading[2];       // cos, sin of the vehicle's x axis in the odometry frame
  double m_anchor[2];        // where SEARCH holds the vehicle (NaN: no anchor yet)
  double m_targetCentre[2];  // horizontal odometry position of the target when last seen with a pose (NaN: never)
  double m_targetNormal[2];  // horizontal unit vector out of the target's face
  double m_rangeIntegral;    // integral of (range - stand-off) over the time in HOME (m s)
  double m_previousTime;     // time of the previous step
  double m_starboard[2];     // the vehicle's y axis in the odometry frame (horizontal, unit)
  bool m_hadOdometry;        // odometry at the previous step (m_position is then its position)
  double m_current[2];       // low-pass sum of (ground - commanded) velocity, divided by m_currentWeight when read
  double m_currentWeight;    // 1 - prod(1 - alpha): corrects the filter's start from 0
  double m_waterVelocity[2]; // modelled surge and sway through the water (m/s)
  double m_crabAngle;
  vpColVector m_velocity;
  vpColVector m_cameraVelocity;
};

#endif
