#include <visp3/ssl_servo/vpSSLHomingBehaviour.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <visp3/core/vpException.h>
#include <visp3/core/vpMath.h>

namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

double clamp(double v, double limit)
{
  return std::max(-limit, std::min(limit, v));
}
} // namespace

vpSSLHomingBehaviour::vpSSLHomingBehaviour()
    : m_law(), m_standOff(2.), m_searchYawRate(0.2), m_searchDepthMin(1.), m_searchDepthMax(3.), m_searchPeriod(40.),
      m_searchDepthGain(0.5), m_alignTolerance(vpMath::rad(5.)), m_lostTimeout(3.), m_minPoints(1), m_autoDockHold(-1.),
      m_autoDockRangeTolerance(0.1), m_autoDockAngleTolerance(vpMath::rad(5.)), m_alignTimeout(5.),
      m_blindDockRange(0.6), m_blindDockSpeed(0.1), m_searchHoldGain(0.5), m_searchHoldSpeed(0.3),
      m_rangeIntegralGain(0.), m_state(SSL_HOMING_SEARCH), m_dockRequested(false), m_started(false), m_time(0.),
      m_stateStart(0.), m_lastSeen(-kInf), m_holdStart(kNaN), m_seen(false), m_lastCollision(false), m_nbCollisions(0),
      m_lastRange(kInf), m_range(kNaN), m_lastSurge(0.), m_searchDepth(kNaN),
      m_hasOdometry(false), m_position{kNaN, kNaN}, m_heading{1., 0.}, m_anchor{kNaN, kNaN}, m_targetCentre{kNaN, kNaN},
      m_targetNormal{kNaN, kNaN}, m_rangeIntegral(0.), m_previousTime(0.), m_velocity(6, 0.), m_cameraVelocity(6, 0.)
{
  m_law.setStandOff(m_standOff);
}

void vpSSLHomingBehaviour::setStandOff(double Zstar)
{
  if (!std::isfinite(Zstar) || !(Zstar > 0.)) {
    throw vpException(vpException::badValue,
                      "vpSSLHomingBehaviour::setStandOff: Zstar: %g is not a finite value > 0 (dock with "
                      "startDocking())",
                      Zstar);
  }
  m_standOff = Zstar;
}

namespace {
// Search pattern bounds (setSearchPattern()): a vehicle's yaw rate, the deepest ocean, a day, a gain far above
// any tuning.
const double kMaxSearchYawRate = 10.;
const double kMaxSearchDepth = 11000.;
const double kMaxSearchPeriod = 86400.;
const double kMaxSearchDepthGain = 100.;
} // namespace

void vpSSLHomingBehaviour::setSearchPattern(double yawRate, double depthMin, double depthMax, double period,
                                            double depthGain)
{
  if (!std::isfinite(yawRate) || !std::isfinite(depthMin) || !std::isfinite(depthMax) || !std::isfinite(period) ||
      !std::isfinite(depthGain) || depthMin > depthMax || !(period > 0.) || !(depthGain > 0.)) {
    throw vpException(vpException::badValue,
                      "vpSSLHomingBehaviour::setSearchPattern: yawRate %g, depthMin %g, depthMax %g, period %g, "
                      "depthGain %g: need finite values, depthMin <= depthMax, period > 0 and depthGain > 0",
                      yawRate, depthMin, depthMax, period, depthGain);
  }
  // Bounds that keep the depth reference (the mean and half the span of the two depths) and the heave command
  // finite: +-1e308 m would make both infinite, and the saturation would turn that into a full heave.
  if (std::fabs(yawRate) > kMaxSearchYawRate || std::fabs(depthMin) > kMaxSearchDepth ||
      std::fabs(depthMax) > kMaxSearchDepth || period > kMaxSearchPeriod || depthGain > kMaxSearchDepthGain) {
    throw vpException(vpException::badValue,
                      "vpSSLHomingBehaviour::setSearchPattern: yawRate %g, depthMin %g, depthMax %g, period %g, "
                      "depthGain %g: need |yawRate| <= %g rad/s, |depthMin|, |depthMax| <= %g m, period <= %g s and "
                      "depthGain <= %g",
                      yawRate, depthMin, depthMax, period, depthGain, kMaxSearchYawRate, kMaxSearchDepth,
                      kMaxSearchPeriod, kMaxSearchDepthGain);
  }
  m_searchYawRate = yawRate;
  m_searchDepthMin = depthMin;
  m_searchDepthMax = depthMax;
  m_searchPeriod = period;
  m_searchDepthGain = depthGain;
}

void vpSSLHomingBehaviour::setAlignTolerance(double angle)
{
  if (!std::isfinite(angle) || !(angle > 0.) || angle >= M_PI / 2.) {
    throw vpException(vpException::badValue,
                      "vpSSLHomingBehaviour::setAlignTolerance: angle: %g rad is not in (0, pi/2)", angle);
  }
  m_alignTolerance = angle;
}

void vpSSLHomingBehaviour::setAlignTimeout(double seconds)
{
  if (!(seconds >= 0.)) {
    throw vpException(vpException::badValue, "vpSSLHomingBehaviour::setAlignTimeout: seconds: %g is not >= 0", seconds);
  }
  m_alignTimeout = seconds;
}

void vpSSLHomingBehaviour::setLostTimeout(double seconds)
{
  if (!std::isfinite(seconds) || seconds < 0.) {
    throw vpException(vpException::badValue,
                      "vpSSLHomingBehaviour::setLostTimeout: seconds: %g is not a finite value >= 0", seconds);
  }
  m_lostTimeout = seconds;
}

void vpSSLHomingBehaviour::setMinPoints(unsigned int n)
{
  if (n == 0) {
    throw vpException(vpException::badValue, "vpSSLHomingBehaviour::setMinPoints: n: 0, need at least 1");
  }
  m_minPoints = n;
}

void vpSSLHomingBehaviour::setAutoDock(double holdSeconds, double rangeTolerance, double angleTolerance)
{
  if (!std::isfinite(holdSeconds) || !std::isfinite(rangeTolerance) || !(rangeTolerance > 0.) ||
      !std::isfinite(angleTolerance) || !(angleTolerance > 0.)) {
    throw vpException(vpException::badValue,
                      "vpSSLHomingBehaviour::setAutoDock: holdSeconds %g, rangeTolerance %g, angleTolerance %g: need "
                      "finite values and tolerances > 0",
                      holdSeconds, rangeTolerance, angleTolerance);
  }
  m_autoDockHold = holdSeconds;
  m_autoDockRangeTolerance = rangeTolerance;
  m_autoDockAngleTolerance = angleTolerance;
}

void vpSSLHomingBehaviour::setBlindDock(double range, double minSpeed)
{
  if (!std::isfinite(range) || !std::isfinite(minSpeed) || range < 0. || minSpeed < 0.) {
    throw vpException(vpException::badValue,
                      "vpSSLHomingBehaviour::setBlindDock: range %g, minSpeed %g: need finite values >= 0", range,
                      minSpeed);
  }
  m_blindDockRange = range;
  m_blindDockSpeed = minSpeed;
}

void vpSSLHomingBehaviour::setSearchHold(double gain, double maxSpeed)
{
  if (!std::isfinite(gain) || !std::isfinite(maxSpeed) || gain < 0. || maxSpeed < 0.) {
    throw vpException(vpException::badValue,
                      "vpSSLHomingBehaviour::setSearchHold: gain %g, maxSpeed %g: need finite values >= 0", gain,
                      maxSpeed);
  }
  m_searchHoldGain = gain;
  m_searchHoldSpeed = maxSpeed;
}

void vpSSLHomingBehaviour::setRangeIntegralGain(double gain)
{
  if (!std::isfinite(gain) || gain < 0.) {
    throw vpException(vpException::badValue,
                      "vpSSLHomingBehaviour::setRangeIntegralGain: gain: %g is not a finite value >= 0", gain);
  }
  m_rangeIntegralGain = gain;
}

std::string vpSSLHomingBehaviour::getStateName(vpSSLHomingState state)
{
  switch (state) {
  case SSL_HOMING_SEARCH:
    return "search";
  case SSL_HOMING_ALIGN:
    return "align";
  case SSL_HOMING_HOME:
    return "home";
  case SSL_HOMING_DOCK:
    return "dock";
  case SSL_HOMING_DOCKED:
    return "docked";
  }
  return "unknown";
}

double vpSSLHomingBehaviour::getTimeSinceSeen() const
{
  return m_time - m_lastSeen;
}

void vpSSLHomingBehaviour::reset()
{
  m_state = SSL_HOMING_SEARCH;
  m_dockRequested = false;
  m_started = false;
  m_time = 0.;
  m_stateStart = 0.;
  m_lastSeen = -kInf;
  m_holdStart = kNaN;
  m_seen = false;
  m_lastCollision = false;
  m_nbCollisions = 0;
  m_lastRange = kInf;
  m_range = kNaN;
  m_lastSurge = 0.;
  m_searchDepth = kNaN;
  m_hasOdometry = false;
  m_position[0] = m_position[1] = kNaN;
  m_heading[0] = 1.;
  m_heading[1] = 0.;
  m_anchor[0] = m_anchor[1] = kNaN;
  m_targetCentre[0] = m_targetCentre[1] = kNaN;
  m_targetNormal[0] = m_targetNormal[1] = kNaN;
  m_rangeIntegral = 0.;
  m_previousTime = 0.;
  m_velocity = vpColVector(6, 0.);
  m_cameraVelocity = vpColVector(6, 0.);
}

void vpSSLHomingBehaviour::setState(vpSSLHomingState state)
{
  if (state != m_state) {
    m_state = state;
    m_stateStart = m_time;
    m_holdStart = kNaN;
    // DOCK keeps the integral HOME built: it is the surge that balances the current along the axis.
    if (state != SSL_HOMING_DOCK) {
      m_rangeIntegral = 0.;
    }
  }
}

vpColVector vpSSLHomingBehaviour::searchCommand(double vehicleDepth)
{
  const vpColVector &vmax = m_law.getVelocityLimits();
  vpColVector v(6, 0.);
  // Triangle wave between the two depths, starting at the shallow one, so that the camera sweeps the water
  // column at a constant heave speed (a sine would linger at the extremes).
  const double phase = std::fmod(std::max(0., getTimeInState()), m_searchPeriod) / m_searchPeriod;
  const double tri = phase < 0.5 ? 2. * phase : 2. - 2. * phase;
  m_searchDepth = m_searchDepthMin + (m_searchDepthMax - m_searchDepthMin) * tri;
  if (m_law.getAxisEnabled(SSL_AXIS_YAW)) {
    v[SSL_AXIS_YAW] = clamp(m_searchYawRate, vmax[SSL_AXIS_YAW]);
  }
  if (m_law.getAxisEnabled(SSL_AXIS_HEAVE) && std::isfinite(vehicleDepth)) {
    v[SSL_AXIS_HEAVE] = clamp(m_searchDepthGain * (m_searchDepth - vehicleDepth), vmax[SSL_AXIS_HEAVE]);
  }
  // Station keeping on the odometry: the error to the anchor in the vehicle frame. While the vehicle turns, the
  // surge pushes back whenever the nose points along the error, so a current slower than the mean of that push
  // no longer carries the vehicle away from where the target was.
  if (m_hasOdometry && m_searchHoldGain > 0. && std::isfinite(m_anchor[0])) {
    double goal[2] = {m_anchor[0], m_anchor[1]};
    if (std::isfinite(m_targetCentre[0])) {
      // The target was located: go to the point on its axis at the stand-off, from where it is in view whatever
      // the vehicle drifted to. From closer to the board's plane than that, first straight out along the axis, so
      // that the way there does not cross the board.
      const double out = (m_position[0] - m_targetCentre[0]) * m_targetNormal[0] +
                         (m_position[1] - m_targetCentre[1]) * m_targetNormal[1];
      const double gap = m_standOff - out;
      if (gap > 0.25 * m_standOff) {
        goal[0] = m_position[0] + gap * m_targetNormal[0];
        goal[1] = m_position[1] + gap * m_targetNormal[1];
      } else {
        goal[0] = m_targetCentre[0] + m_standOff * m_targetNormal[0];
        goal[1] = m_targetCentre[1] + m_standOff * m_targetNormal[1];
      }
    }
    const double ex = goal[0] - m_position[0];
    const double ey = goal[1] - m_position[1];
    const double forward = m_heading[0] * ex + m_heading[1] * ey;
    const double starboard = -m_heading[1] * ex + m_heading[0] * ey;
    if (m_law.getAxisEnabled(SSL_AXIS_SURGE)) {
      v[SSL_AXIS_SURGE] = clamp(m_searchHoldGain * forward, std::min(m_searchHoldSpeed, vmax[SSL_AXIS_SURGE]));
    }
    if (m_law.getAxisEnabled(SSL_AXIS_SWAY)) {
      v[SSL_AXIS_SWAY] = clamp(m_searchHoldGain * starboard, std::min(m_searchHoldSpeed, vmax[SSL_AXIS_SWAY]));
    }
  }
  return v;
}

vpColVector vpSSLHomingBehaviour::blindDockCommand() const
{
  vpColVector v(6, 0.);
  const double vmax = m_law.getVelocityLimits()[SSL_AXIS_SURGE];
  v[SSL_AXIS_SURGE] = std::min(std::max(m_lastSurge, m_blindDockSpeed), vmax);
  return v;
}

vpColVector vpSSLHomingBehaviour::update(double t, const vpSSLServoInput &input, double vehicleDepth, bool collision)
{
  return step(t, input, vehicleDepth, collision, nullptr);
}

vpColVector vpSSLHomingBehaviour::update(double t, const vpSSLServoInput &input, double vehicleDepth, bool collision,
                                         const vpHomogeneousMatrix &oMv)
{
  return step(t, input, vehicleDepth, collision, &oMv);
}

vpColVector vpSSLHomingBehaviour::step(double t, const vpSSLServoInput &input, double vehicleDepth, bool collision,
                                       const vpHomogeneousMatrix *oMv)
{
  m_previousTime = m_time;
  if (!m_started) {
    m_started = true;
    m_time = std::isfinite(t) ? t : 0.;
    m_stateStart = m_time;
    m_previousTime = m_time;
  } else if (std::isfinite(t) && t >= m_time) {
    m_time = t;
  }
  if (collision && !m_lastCollision) {
    ++m_nbCollisions;
  }
  m_lastCollision = collision;

  double xc, yc, Zc;
  const bool usable = vpSSLServoLaw::getTargetCentre(input, xc, yc, Zc);
  m_range = Zc;
  const double previousRange = m_lastRange;
  if (usable) {
    m_lastRange = Zc;
  }
  m_seen = usable && input.nbPoints >= m_minPoints;
  if (m_seen) {
    m_lastSeen = m_time;
  }
  // The vehicle's x axis projected on the horizontal plane gives the heading; a vehicle pointing straight up or
  // down has none, and that step counts as without odometry.
  m_hasOdometry = false;
  if (oMv != nullptr) {
    const double hx = (*oMv)[0][0], hy = (*oMv)[1][0];
    const double norm = std::sqrt(hx * hx + hy * hy);
    if (std::isfinite(norm) && norm > 1e-6 && std::isfinite((*oMv)[0][3]) && std::isfinite((*oMv)[1][3])) {
      m_hasOdometry = true;
      m_position[0] = (*oMv)[0][3];
      m_position[1] = (*oMv)[1][3];
      m_heading[0] = hx / norm;
      m_heading[1] = hy / norm;
      if (m_seen && input.hasPose) {
        // The target's centre and the horizontal direction out of its face (object Z points into the sheet).
        const vpHomogeneousMatrix oMt = (*oMv) * m_law.getCameraToVehicle() * input.cMo;
        const double nx = -oMt[0][2], ny = -oMt[1][2];
        const double nn = std::sqrt(nx * nx + ny * ny);
        if (std::isfinite(nn) && nn > 1e-3 && std::isfinite(oMt[0][3]) && std::isfinite(oMt[1][3])) {
          m_targetCentre[0] = oMt[0][3];
          m_targetCentre[1] = oMt[1][3];
          m_targetNormal[0] = nx / nn;
          m_targetNormal[1] = ny / nn;
        }
      }
      if (m_seen || !std::isfinite(m_anchor[0])) {
        m_anchor[0] = m_position[0];
        m_anchor[1] = m_position[1];
      }
    }
  }
  const bool lostTooLong = !m_seen && (m_time - m_lastSeen > m_lostTimeout);
  // Angle between the optical axis and the ray to the target centre.
  const double centreAngle = usable ? std::atan(std::sqrt(xc * xc + yc * yc)) : kInf;

  // Transitions; a chain (SEARCH -> ALIGN -> HOME) may happen in one step, the guard bounds it.
  for (int guard = 0; guard < 5; ++guard) {
    const vpSSLHomingState before = m_state;
    switch (m_state) {
    case SSL_HOMING_SEARCH:
      if (m_seen) {
        setState(SSL_HOMING_ALIGN);
      }
      break;
    case SSL_HOMING_ALIGN:
      if (lostTooLong) {
        setState(SSL_HOMING_SEARCH);
      } else if (m_seen && (centreAngle < m_alignTolerance || getTimeInState() >= m_alignTimeout)) {
        // After the timeout the full law takes over the centring: a cross current can hold the target off-centre
        // beyond the tolerance while the vehicle drifts away with the range uncontrolled.
        setState(m_dockRequested ? SSL_HOMING_DOCK : SSL_HOMING_HOME);
      }
      break;
    case SSL_HOMING_HOME:
      if (lostTooLong) {
        setState(SSL_HOMING_SEARCH);
      } else if (m_dockRequested) {
        setState(SSL_HOMING_DOCK);
      }
      break;
    case SSL_HOMING_DOCK:
      if (collision) {
        setState(SSL_HOMING_DOCKED);
      } else if (lostTooLong) {
        setState(SSL_HOMING_SEARCH);
      } else if (!m_dockRequested) {
        setState(SSL_HOMING_HOME);
      }
      break;
    case SSL_HOMING_DOCKED:
      break;
    }
    if (m_state == before) {
      break;
    }
  }

  vpColVector v(6, 0.);
  if (m_state != SSL_HOMING_SEARCH) {
    m_searchDepth = kNaN;
  }
  switch (m_state) {
  case SSL_HOMING_SEARCH:
    v = searchCommand(vehicleDepth);
    m_lastRange = kInf;
    break;
  case SSL_HOMING_ALIGN:
    if (usable) {
      v = m_law.computeCentringLaw(input);
    }
    break;
  case SSL_HOMING_HOME:
    if (usable) {
      m_law.setStandOff(m_standOff);
      v = m_law.computeControlLaw(input);
      if (m_rangeIntegralGain > 0. && m_law.getStatus() == SSL_SERVO_OK && m_law.getAxisEnabled(SSL_AXIS_SURGE)) {
        // Integrates only once the proportional law has settled (within half the stand-off of it, the range
        // changing by less than 5 cm/s), so that neither the approach from afar nor the overshoot of a fast one
        // winds anything up; bounded so that the integral alone asks for at most half the surge limit.
        const double vmax = m_law.getVelocityLimits()[SSL_AXIS_SURGE];
        const double error = Zc - m_standOff;
        const double dt = m_time - m_previousTime;
        const bool settled = dt > 0. && std::fabs(Zc - previousRange) < 0.05 * dt;
        if (settled && std::fabs(error) < 0.5 * m_standOff) {
          m_rangeIntegral = clamp(m_rangeIntegral + error * dt, 0.5 * vmax / m_rangeIntegralGain);
        }
        v[SSL_AXIS_SURGE] = clamp(v[SSL_AXIS_SURGE] + m_rangeIntegralGain * m_rangeIntegral, vmax);
      }
      const bool holding = m_seen && std::fabs(Zc - m_standOff) < m_autoDockRangeTolerance &&
                           centreAngle < m_autoDockAngleTolerance && m_law.getStatus() == SSL_SERVO_OK;
      if (m_autoDockHold >= 0. && holding) {
        if (!std::isfinite(m_holdStart)) {
          m_holdStart = m_time;
        }
        if (m_time - m_holdStart >= m_autoDockHold) {
          m_dockRequested = true; // DOCK from the next update()
        }
      } else {
        m_holdStart = kNaN;
      }
    }
    break;
  case SSL_HOMING_DOCK:
    if (usable) {
      m_law.setStandOff(0.);
      v = m_law.computeControlLaw(input);
      if (m_law.getStatus() == SSL_SERVO_OK && m_law.getAxisEnabled(SSL_AXIS_SURGE)) {
        const double vmax = m_law.getVelocityLimits()[SSL_AXIS_SURGE];
        v[SSL_AXIS_SURGE] = clamp(v[SSL_AXIS_SURGE] + m_rangeIntegralGain * m_rangeIntegral, vmax);
      }
      if (m_law.getStatus() == SSL_SERVO_OK && Zc < m_blindDockRange) {
        // Final approach: the log-depth feature slows down exponentially near its floor, so a minimum surge
        // makes sure the nose reaches the target and trips the collision sensor.
        const double vmax = m_law.getVelocityLimits()[SSL_AXIS_SURGE];
        v[SSL_AXIS_SURGE] = std::min(std::max(v[SSL_AXIS_SURGE], m_blindDockSpeed), vmax);
      }
      m_lastSurge = v[SSL_AXIS_SURGE];
    } else if (m_lastRange < m_blindDockRange) {
      v = blindDockCommand();
    }
    break;
  case SSL_HOMING_DOCKED:
    break;
  }
  m_velocity = v;
  m_cameraVelocity = m_law.toCameraVelocity(v);
  return m_velocity;
}

void vpSSLHomingBehaviour::apply(vpRobot &robot, vpRobot::vpControlFrameType frame) const
{
  if (frame != vpRobot::ARTICULAR_FRAME && frame != vpRobot::CAMERA_FRAME) {
    throw vpException(vpException::badValue,
                      "vpSSLHomingBehaviour::apply: frame: %d, expected vpRobot::ARTICULAR_FRAME (vehicle axes) or "
                      "vpRobot::CAMERA_FRAME",
                      static_cast<int>(frame));
  }
  if (robot.getRobotState() != vpRobot::STATE_VELOCITY_CONTROL) {
    robot.setRobotState(vpRobot::STATE_VELOCITY_CONTROL);
  }
  robot.setVelocity(frame, frame == vpRobot::CAMERA_FRAME ? m_cameraVelocity : m_velocity);
}
