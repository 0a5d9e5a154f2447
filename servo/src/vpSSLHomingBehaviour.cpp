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
      m_rangeIntegralGain(0.), m_transitEnabled(false), m_transitCrossCurrent(0.1), m_transitMaxCrab(vpMath::rad(20.)),
      m_state(SSL_HOMING_SEARCH), m_dockRequested(false), m_started(false), m_time(0.), m_stateStart(0.),
      m_lastSeen(-kInf), m_holdStart(kNaN), m_seen(false), m_lastCollision(false), m_nbCollisions(0), m_lastRange(kInf),
      m_range(kNaN), m_lastSurge(0.), m_searchDepth(kNaN),
      m_hasOdometry(false), m_position{kNaN, kNaN}, m_heading{1., 0.}, m_anchor{kNaN, kNaN}, m_targetCentre{kNaN, kNaN},
      m_targetNormal{kNaN, kNaN}, m_rangeIntegral(0.), m_previousTime(0.), m_starboard{0., 1.},
      m_hadOdometry(false), m_current{0., 0.}, m_currentWeight(0.), m_waterVelocity{0., 0.}, m_crabAngle(0.),
      m_velocity(6, 0.), m_cameraVelocity(6, 0.)
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

void vpSSLHomingBehaviour::setDockInTransit(bool enable, double crossCurrent, double maxCrab)
{
  if (!std::isfinite(crossCurrent) || crossCurrent < 0. || !std::isfinite(maxCrab) || !(maxCrab > 0.) ||
      maxCrab >= M_PI / 2.) {
    throw vpException(vpException::badValue,
                      "vpSSLHomingBehaviour::setDockInTransit: crossCurrent %g, maxCrab %g: need a finite "
                      "crossCurrent >= 0 and maxCrab in (0, pi/2) rad",
                      crossCurrent, maxCrab);
  }
  m_transitEnabled = enable;
  m_transitCrossCurrent = crossCurrent;
  m_transitMaxCrab = maxCrab;
}

bool vpSSLHomingBehaviour::getCurrentEstimate(double &cx, double &cy) const
{
  if (!(m_currentWeight > 0.)) {
    cx = cy = kNaN;
    return false;
  }
  cx = m_current[0] / m_currentWeight;
  cy = m_current[1] / m_currentWeight;
  return true;
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
  m_starboard[0] = 0.;
  m_starboard[1] = 1.;
  m_hadOdometry = false;
  m_current[0] = m_current[1] = 0.;
  m_currentWeight = 0.;
  m_waterVelocity[0] = m_waterVelocity[1] = 0.;
  m_crabAngle = 0.;
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
  // does not carry the vehicle away from where the target was.
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

namespace {
// Time constant of the current estimate (s): long against the autopilot's half-second lag, so that the
// command's transients average out, short against a mission.
const double kCurrentTimeConstant = 5.;
// The simulated autopilot's response lag (s), modelled to first order (doc/servo-simulation.md).
const double kAutopilotLag = 0.5;
// The estimate is used once it has averaged two time constants of odometry.
const double kCurrentSettled = 1. - std::exp(-2.);
} // namespace

void vpSSLHomingBehaviour::updateCurrentEstimate(const vpHomogeneousMatrix &oMv)
{
  const double dt = m_time - m_previousTime;
  if (dt > 0.) {
    // The velocity through the water over the interval: the autopilot's first-order response to the previous
    // command, averaged over the interval and rotated into the odometry frame with the heading halfway through
    // it. What the odometry moved beyond it is the current.
    const double decay = std::exp(-dt / kAutopilotLag);
    const double mean = kAutopilotLag / dt * (1. - decay);
    const double command[2] = {m_velocity[SSL_AXIS_SURGE], m_velocity[SSL_AXIS_SWAY]};
    double water[2];
    for (int i = 0; i < 2; ++i) {
      water[i] = command[i] + (m_waterVelocity[i] - command[i]) * mean;
      m_waterVelocity[i] = command[i] + (m_waterVelocity[i] - command[i]) * decay;
    }
    double forward[2] = {m_heading[0] + oMv[0][0], m_heading[1] + oMv[1][0]};
    const double norm = std::sqrt(forward[0] * forward[0] + forward[1] * forward[1]);
    if (!(norm > 1e-6)) {
      return; // turned half a turn in one step: no heading for the interval
    }
    forward[0] /= norm;
    forward[1] /= norm;
    const double sign = m_starboard[0] * -m_heading[1] + m_starboard[1] * m_heading[0] >= 0. ? 1. : -1.;
    const double side[2] = {-sign * forward[1], sign * forward[0]};
    double sample[2];
    for (int i = 0; i < 2; ++i) {
      const double ground = (oMv[i][3] - m_position[i]) / dt;
      sample[i] = ground - (water[0] * forward[i] + water[1] * side[i]);
    }
    if (std::isfinite(sample[0]) && std::isfinite(sample[1])) {
      const double alpha = dt / (kCurrentTimeConstant + dt);
      for (int i = 0; i < 2; ++i) {
        m_current[i] += alpha * (sample[i] - m_current[i]);
      }
      m_currentWeight += alpha * (1. - m_currentWeight);
    }
  }
}

bool vpSSLHomingBehaviour::lineOfSightCurrent(bool usable, double xc, double &across, double &along) const
{
  across = along = 0.;
  double cx, cy;
  if (!usable || !m_hasOdometry || m_currentWeight < kCurrentSettled || !getCurrentEstimate(cx, cy)) {
    return false;
  }
  // The line of sight is the heading turned towards starboard by the target's bearing in the image (camera x
  // along the vehicle's y). along: the current towards the target; across: towards the line's starboard side.
  const double bearing = std::atan(xc);
  const double c = std::cos(bearing), s = std::sin(bearing);
  const double los[2] = {c * m_heading[0] + s * m_starboard[0], c * m_heading[1] + s * m_starboard[1]};
  const double side[2] = {-s * m_heading[0] + c * m_starboard[0], -s * m_heading[1] + c * m_starboard[1]};
  along = cx * los[0] + cy * los[1];
  across = cx * side[0] + cy * side[1];
  return true;
}

vpColVector vpSSLHomingBehaviour::transitDockCommand(const vpSSLServoInput &input, double range, double across,
                                                     double along)
{
  // The docking law's surge is the closing speed it asks for over the ground; the velocity through the water that
  // gives it is that closing speed along the line of sight minus the current. Its direction is the crab angle, at
  // most setDockInTransit()'s: beyond, the surge grows so that the current across the line is still cancelled.
  m_law.setStandOff(0.);
  const vpColVector straight = m_law.computeControlLaw(input);
  if (m_law.getStatus() != SSL_SERVO_OK || !m_law.getAxisEnabled(SSL_AXIS_SURGE)) {
    return straight;
  }
  const double vmax = m_law.getVelocityLimits()[SSL_AXIS_SURGE];
  const double closing = std::max(straight[SSL_AXIS_SURGE], m_blindDockSpeed);
  const double forward = closing - along;
  double surge = std::sqrt(forward * forward + across * across);
  m_crabAngle = std::atan2(across, forward);
  if (std::fabs(m_crabAngle) > m_transitMaxCrab) {
    m_crabAngle = m_crabAngle > 0. ? m_transitMaxCrab : -m_transitMaxCrab;
    surge = std::fabs(across) / std::sin(m_transitMaxCrab);
  }
  // A virtual camera c' yawed by the crab angle towards the target (camera y is down: +angle turns the optical
  // axis towards +x): the law centres the target in c', so the real nose points upstream of it by that angle.
  const vpHomogeneousMatrix cMcp(vpTranslationVector(0., 0., 0.), vpRotationMatrix(vpRxyzVector(0., m_crabAngle, 0.)));
  const vpHomogeneousMatrix cpMc = cMcp.inverse();
  vpSSLServoInput virtualInput = input;
  for (vpSSLServoPoint &p : virtualInput.points) {
    const double X = p.x * p.Z, Y = p.y * p.Z;
    const double Xp = cpMc[0][0] * X + cpMc[0][1] * Y + cpMc[0][2] * p.Z;
    const double Yp = cpMc[1][0] * X + cpMc[1][1] * Y + cpMc[1][2] * p.Z;
    const double Zp = cpMc[2][0] * X + cpMc[2][1] * Y + cpMc[2][2] * p.Z;
    p.x = Xp / Zp;
    p.y = Yp / Zp;
    p.Z = Zp;
  }
  if (virtualInput.hasPose) {
    virtualInput.cMo = cpMc * input.cMo;
  }
  // The law steers; the surge is the feed-forward's. With its own surge limit the law's surge from afar would
  // saturate and scale the turn down with it, while the current carries the target out of view.
  const vpHomogeneousMatrix vMc = m_law.getCameraToVehicle();
  const vpColVector limits = m_law.getVelocityLimits();
  vpColVector steerLimits = limits;
  steerLimits[SSL_AXIS_SURGE] = 1e3;
  m_law.setCameraToVehicle(vMc * cMcp);
  m_law.setVelocityLimits(steerLimits);
  vpColVector v = m_law.computeControlLaw(virtualInput);
  m_law.setCameraToVehicle(vMc);
  m_law.setVelocityLimits(limits);
  if (m_law.getStatus() == SSL_SERVO_OK) {
    // The feed-forward fades in as the law turns the nose to the crab angle: surging hard while the nose points
    // elsewhere (the end of a search turn) would drive the vehicle off the line of sight.
    double xv, yv, Zv;
    const double error =
        vpSSLServoLaw::getTargetCentre(virtualInput, xv, yv, Zv) ? std::atan(std::sqrt(xv * xv + yv * yv)) : kInf;
    const double weight = std::max(0., 1. - error / m_transitMaxCrab);
    v[SSL_AXIS_SURGE] = std::min(weight * surge, vmax);
    // While the current carries the vehicle across, the line of sight turns at the vehicle's velocity across it
    // over the range: a proportional law lags behind it by the error that gives that rate, the crab angle is never
    // reached and the surge not faded in. Turning with the line of sight removes that lag.
    double xc, yc, Zc;
    if (m_law.getAxisEnabled(SSL_AXIS_YAW) && vpSSLServoLaw::getTargetCentre(input, xc, yc, Zc) && Zc > 0.) {
      const double bearing = std::atan(xc);
      const double acrossGround = across - m_waterVelocity[0] * std::sin(bearing);
      const double ymax = m_law.getVelocityLimits()[SSL_AXIS_YAW];
      v[SSL_AXIS_YAW] = clamp(v[SSL_AXIS_YAW] - acrossGround / Zc, ymax);
    }
  }
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
  m_crabAngle = 0.;
  const bool hadOdometry = m_hadOdometry;
  m_hadOdometry = false;
  if (oMv != nullptr) {
    const double hx = (*oMv)[0][0], hy = (*oMv)[1][0];
    const double norm = std::sqrt(hx * hx + hy * hy);
    if (std::isfinite(norm) && norm > 1e-6 && std::isfinite((*oMv)[0][3]) && std::isfinite((*oMv)[1][3])) {
      m_hasOdometry = true;
      if (hadOdometry) {
        updateCurrentEstimate(*oMv); // before the position and heading become this step's
      }
      m_hadOdometry = true;
      m_position[0] = (*oMv)[0][3];
      m_position[1] = (*oMv)[1][3];
      m_heading[0] = hx / norm;
      m_heading[1] = hy / norm;
      // Starboard: the horizontal normal of the heading on the side of the vehicle's y axis (z down: x cross y).
      const double side = (*oMv)[0][1] * -m_heading[1] + (*oMv)[1][1] * m_heading[0];
      m_starboard[0] = side >= 0. ? -m_heading[1] : m_heading[1];
      m_starboard[1] = side >= 0. ? m_heading[0] : -m_heading[0];
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
  double across = 0., along = 0.;
  const bool currentKnown = m_transitEnabled && lineOfSightCurrent(usable, xc, across, along);
  const bool transit = currentKnown && m_seen && std::fabs(across) >= m_transitCrossCurrent;
  if (transit && (m_state == SSL_HOMING_ALIGN || m_state == SSL_HOMING_HOME)) {
    // Holding the stand-off is not possible across this current: dock without stopping.
    m_dockRequested = true;
  }

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
      } else if (m_seen && (centreAngle < m_alignTolerance || getTimeInState() >= m_alignTimeout || transit)) {
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
      v = currentKnown ? transitDockCommand(input, Zc, across, along) : m_law.computeControlLaw(input);
      // The current's feed-forward already balances what HOME's integral did.
      if (!currentKnown && m_law.getStatus() == SSL_SERVO_OK && m_law.getAxisEnabled(SSL_AXIS_SURGE)) {
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
