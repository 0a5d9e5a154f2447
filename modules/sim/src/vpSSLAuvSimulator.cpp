/*!
  \file vpSSLAuvSimulator.cpp
  \brief Rigid-body dynamics (Fossen's diagonal model), autopilot, current, contact and sensors of the simulated AUV.
*/
#include <visp3/ssl_sim/vpSSLAuvSimulator.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <visp3/core/vpException.h>
#include <visp3/core/vpExponentialMap.h>
#include <visp3/core/vpPoseVector.h>
#include <visp3/core/vpVelocityTwistMatrix.h>
#include <visp3/ssl/vpSSLFinite.h>
#include <visp3/ssl_sim/vpSSLScenario.h>

namespace {
const double kGravity = 9.81;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

bool isFiniteRigid(const vpHomogeneousMatrix &M)
{
  return vpSSLFinite::isFinite(M) && M.isAnHomogeneousMatrix(1e-6);
}

void checkPositive(double v, const char *what)
{
  if (!(v > 0. && std::isfinite(v))) {
    throw vpException(vpException::badValue, "vpSSLAuvSimulator: %s = %g must be finite and > 0", what, v);
  }
}

// Largest v >= 0 with a v + b v^2 = f.
double balance(double a, double b, double f)
{
  if (b <= 0.) {
    return a > 0. ? f / a : std::numeric_limits<double>::infinity();
  }
  return (-a + std::sqrt(a * a + 4. * b * f)) / (2. * b);
}

vpColVector cross(const vpColVector &a, const vpColVector &b)
{
  vpColVector c(3);
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
  return c;
}
} // namespace

vpSSLAuvSimulator::vpSSLAuvSimulator()
    : m_param(), m_dt(0.04), m_h(0.005), m_vMc(vpSSLScenario::getDefaultCameraToVehicle()), m_current(0., 0., 0.),
      m_swayAmplitude(0.), m_swayPeriod(10.), m_swayHeading(M_PI / 2.), m_wMo(), m_targetInWater(true),
      m_boardWidth(0.6), m_boardHeight(0.45), m_collisionThreshold(0.02), m_rangeMax(5.), m_rangeSigma(0.01), m_t(0.),
      m_wMv(), m_wMvLastDisplacement(), m_nu(6, 0.), m_demand(6, 0.), m_integral(6, 0.), m_tau(6, 0.), m_nbSaturated(0),
      m_collision(false), m_firstCollision(kNaN), m_odometry(), m_depthNoise(), m_rangeNoise()
{
  nDof = 6;
  // The vpRobot limits are informative only: the thrusters limit the vehicle (getTopSpeed()).
  maxTranslationVelocity = getTopSpeed(0);
  maxRotationVelocity = getTopSpeed(5);
  // No target until one is set: far below the vehicle, out of the water.
  m_targetInWater = false;
  reset(vpHomogeneousMatrix(), 0);
}

void vpSSLAuvSimulator::init()
{
  m_nu = 0.;
  m_demand = 0.;
  m_integral = 0.;
  m_tau = 0.;
  m_nbSaturated = 0;
}

void vpSSLAuvSimulator::reset(const vpHomogeneousMatrix &wMv, long seed)
{
  if (!isFiniteRigid(wMv)) {
    throw vpException(vpException::badValue, "vpSSLAuvSimulator::reset(): wMv is not a finite rigid transform");
  }
  init();
  m_t = 0.;
  m_wMv = wMv;
  m_wMvLastDisplacement = wMv;
  m_collision = false;
  m_firstCollision = kNaN;
  // Independent streams per sensor, so that reading one sensor more often does not change another's noise.
  m_odometry.reset(wMv, seed);
  m_depthNoise = vpGaussRand(0.02, 0., seed * 7919L + 1L);
  m_rangeNoise = vpGaussRand(1., 0., seed * 7919L + 2L);
  setRobotState(vpRobot::STATE_VELOCITY_CONTROL);
}

void vpSSLAuvSimulator::setParameters(const vpSSLAuvParameters &p)
{
  checkPositive(p.mass, "mass");
  checkPositive(p.length, "length");
  if (!(p.zg >= 0. && std::isfinite(p.zg))) {
    throw vpException(vpException::badValue, "vpSSLAuvSimulator: zg = %g must be finite and >= 0", p.zg);
  }
  for (unsigned int i = 0; i < 3; ++i) {
    checkPositive(p.inertia[i], "inertia");
  }
  for (unsigned int i = 0; i < 6; ++i) {
    checkPositive(p.thrustLimit[i], "thrustLimit");
    checkPositive(p.velocityGain[i], "velocityGain");
    if (!(p.addedMass[i] >= 0. && p.linearDrag[i] >= 0. && p.quadraticDrag[i] >= 0. &&
          p.velocityIntegralGain[i] >= 0. &&
          std::isfinite(p.addedMass[i] + p.linearDrag[i] + p.quadraticDrag[i] + p.velocityIntegralGain[i]))) {
      throw vpException(vpException::badValue,
                        "vpSSLAuvSimulator: added mass, drag and integral gain of axis %u must be finite and >= 0", i);
    }
    if (p.linearDrag[i] + p.quadraticDrag[i] <= 0.) {
      throw vpException(vpException::badValue, "vpSSLAuvSimulator: axis %u has no drag: its speed would be unbounded",
                        i);
    }
  }
  m_param = p;
  maxTranslationVelocity = getTopSpeed(0);
  maxRotationVelocity = getTopSpeed(5);
}

double vpSSLAuvSimulator::getTopSpeed(unsigned int axis) const
{
  if (axis > 5) {
    throw vpException(vpException::dimensionError, "vpSSLAuvSimulator::getTopSpeed(): axis %u not in [0, 5]", axis);
  }
  return balance(m_param.linearDrag[axis], m_param.quadraticDrag[axis], m_param.thrustLimit[axis]);
}

void vpSSLAuvSimulator::setTimeStep(double dt)
{
  checkPositive(dt, "time step");
  m_dt = dt;
}

void vpSSLAuvSimulator::setIntegrationStep(double h)
{
  if (!(h > 0. && h <= 0.05)) {
    throw vpException(vpException::badValue, "vpSSLAuvSimulator: integration step %g s must be in (0, 0.05]", h);
  }
  m_h = h;
}

void vpSSLAuvSimulator::setCurrent(const vpTranslationVector &constant, double amplitude, double period, double heading)
{
  if (!std::isfinite(constant[0] + constant[1] + constant[2] + amplitude + period + heading) ||
      (amplitude != 0. && !(period > 0.))) {
    throw vpException(vpException::badValue,
                      "vpSSLAuvSimulator::setCurrent(): the current must be finite and its period > 0");
  }
  m_current = constant;
  m_swayAmplitude = amplitude;
  m_swayPeriod = period;
  m_swayHeading = heading;
}

vpTranslationVector vpSSLAuvSimulator::getCurrent(double t) const
{
  vpTranslationVector c = m_current;
  if (m_swayAmplitude != 0.) {
    const double s = m_swayAmplitude * std::sin(2. * M_PI * t / m_swayPeriod);
    c[0] += s * std::cos(m_swayHeading);
    c[1] += s * std::sin(m_swayHeading);
  }
  return c;
}

void vpSSLAuvSimulator::setTargetPose(const vpHomogeneousMatrix &wMo)
{
  if (!isFiniteRigid(wMo)) {
    throw vpException(vpException::badValue, "vpSSLAuvSimulator::setTargetPose(): wMo is not a finite rigid transform");
  }
  m_wMo = wMo;
  m_targetInWater = true;
}

void vpSSLAuvSimulator::setTargetBoard(double width, double height)
{
  checkPositive(width, "board width");
  checkPositive(height, "board height");
  m_boardWidth = width;
  m_boardHeight = height;
}

void vpSSLAuvSimulator::setCollisionThreshold(double distance)
{
  if (!(distance >= 0. && std::isfinite(distance))) {
    throw vpException(vpException::badValue, "vpSSLAuvSimulator: collision threshold %g m must be >= 0", distance);
  }
  m_collisionThreshold = distance;
}

void vpSSLAuvSimulator::setRangeSensor(double maxRange, double sigma)
{
  checkPositive(maxRange, "range sensor maximum");
  if (!(sigma >= 0. && std::isfinite(sigma))) {
    throw vpException(vpException::badValue, "vpSSLAuvSimulator: range sensor noise %g m must be >= 0", sigma);
  }
  m_rangeMax = maxRange;
  m_rangeSigma = sigma;
}

void vpSSLAuvSimulator::setVelocity(const vpRobot::vpControlFrameType frame, const vpColVector &vel)
{
  if (vel.getRows() != 6) {
    throw vpException(vpException::dimensionError, "vpSSLAuvSimulator::setVelocity(): vel has %u rows, expected 6",
                      vel.getRows());
  }
  for (unsigned int i = 0; i < 6; ++i) {
    if (!std::isfinite(vel[i])) {
      throw vpException(vpException::badValue, "vpSSLAuvSimulator::setVelocity(): vel[%u] is not finite", i);
    }
  }
  vpColVector v;
  switch (frame) {
  case vpRobot::ARTICULAR_FRAME:
  case vpRobot::END_EFFECTOR_FRAME:
    v = vel;
    break;
  case vpRobot::CAMERA_FRAME:
    // A twist of the camera frame is the same rigid motion as a twist of the vehicle frame vVc v_c.
    v = vpVelocityTwistMatrix(m_vMc) * vel;
    break;
  default:
    throw vpException(vpException::notImplementedError,
                      "vpSSLAuvSimulator::setVelocity(): use ARTICULAR_FRAME, END_EFFECTOR_FRAME or CAMERA_FRAME");
  }
  // Like vpSimulatorCamera: commanding a velocity puts the robot in velocity control.
  if (getRobotState() != vpRobot::STATE_VELOCITY_CONTROL) {
    setRobotState(vpRobot::STATE_VELOCITY_CONTROL);
  }
  m_demand = v;
  step(m_dt);
}

void vpSSLAuvSimulator::step(double duration)
{
  if (!(duration >= 0. && std::isfinite(duration))) {
    throw vpException(vpException::badValue, "vpSSLAuvSimulator::step(): duration %g s must be >= 0", duration);
  }
  if (duration == 0.) {
    return;
  }
  const unsigned int n = std::max(1u, static_cast<unsigned int>(std::ceil(duration / m_h - 1e-9)));
  const double h = duration / n;
  for (unsigned int k = 0; k < n; ++k) {
    integrate(h);
  }
  m_odometry.update(m_wMv, duration);
}

vpColVector vpSSLAuvSimulator::getWaterVelocity() const
{
  const vpColVector c = m_wMv.getRotationMatrix().t() * vpColVector(getCurrent(m_t));
  vpColVector nuR = m_nu;
  for (unsigned int i = 0; i < 3; ++i) {
    nuR[i] -= c[i];
  }
  return nuR;
}

void vpSSLAuvSimulator::autopilot(const vpColVector &nuR, double h)
{
  const vpSSLAuvParameters &p = m_param;
  const double rigid[6] = {p.mass, p.mass, p.mass, p.inertia[0], p.inertia[1], p.inertia[2]};
  m_nbSaturated = 0;
  for (unsigned int i = 0; i < 6; ++i) {
    const double d = m_demand[i];
    const double e = d - nuR[i];
    const double m = rigid[i] + p.addedMass[i];
    // The drag at the demanded speed as feed-forward (a thruster map), a PI loop scaled by the inertia for the rest.
    const double ff = p.linearDrag[i] * d + p.quadraticDrag[i] * std::fabs(d) * d;
    const double raw = ff + m * (p.velocityGain[i] * e + p.velocityIntegralGain[i] * m_integral[i]);
    const double limit = p.thrustLimit[i];
    const double tau = std::min(limit, std::max(-limit, raw));
    // Anti-windup: the integrator stops while the thrusters are saturated in the direction it would push.
    if (tau == raw || (raw > limit && e < 0.) || (raw < -limit && e > 0.)) {
      m_integral[i] += e * h;
    }
    if (tau != raw) {
      m_nbSaturated++;
    }
    m_tau[i] = tau;
  }
}

void vpSSLAuvSimulator::accelerations(const vpColVector &nuR, const vpColVector &tau, vpColVector &nuDot) const
{
  const vpSSLAuvParameters &p = m_param;
  vpColVector v(3), w(3), Mv(3), Iw(3);
  for (unsigned int i = 0; i < 3; ++i) {
    v[i] = nuR[i];
    w[i] = nuR[3 + i];
    Mv[i] = (p.mass + p.addedMass[i]) * v[i];
    Iw[i] = (p.inertia[i] + p.addedMass[3 + i]) * w[i];
  }
  // Coriolis and centripetal terms of a diagonal mass matrix (Fossen 2011, Eq. 6.43): w x Mv; v x Mv + w x Iw.
  const vpColVector cf = cross(w, Mv);
  const vpColVector cm = cross(v, Mv) + cross(w, Iw);
  // Righting moment of the centre of gravity zg below the centre of buoyancy: r_g x (weight in the body frame).
  const vpRotationMatrix R = m_wMv.getRotationMatrix();
  const double W = p.mass * kGravity;
  const double fy = W * R[2][1], fx = W * R[2][0]; // R^T (0, 0, W)
  const double g[6] = {0., 0., 0., -p.zg * fy, p.zg * fx, 0.};
  const double rigid[6] = {p.mass, p.mass, p.mass, p.inertia[0], p.inertia[1], p.inertia[2]};
  nuDot.resize(6, false);
  for (unsigned int i = 0; i < 6; ++i) {
    const double c = i < 3 ? cf[i] : cm[i - 3];
    const double drag = (p.linearDrag[i] + p.quadraticDrag[i] * std::fabs(nuR[i])) * nuR[i];
    // g is the moment the weight applies: it enters with a plus sign.
    nuDot[i] = (tau[i] - c - drag + g[i]) / (rigid[i] + p.addedMass[i]);
  }
}

void vpSSLAuvSimulator::integrate(double h)
{
  const vpColVector nuR = getWaterVelocity();
  autopilot(nuR, h);
  vpColVector nuDot;
  accelerations(nuR, m_tau, nuDot);
  // Semi-implicit Euler: the pose moves with the updated velocity, which keeps the oscillatory modes (roll and
  // pitch righting) from gaining energy as explicit Euler would.
  m_nu += h * nuDot;
  m_wMv = m_wMv * vpExponentialMap::direct(m_nu, h);
  m_t += h;
  contact();
}

void vpSSLAuvSimulator::contact()
{
  if (!m_targetInWater) {
    m_collision = false;
    return;
  }
  const vpHomogeneousMatrix oMv = m_wMo.inverse() * m_wMv;
  const double half = 0.5 * m_param.length;
  // Nose in the target frame: the printed side is at Z < 0.
  const double nx = oMv[0][0] * half + oMv[0][3];
  const double ny = oMv[1][0] * half + oMv[1][3];
  const double nz = oMv[2][0] * half + oMv[2][3];
  const bool onBoard = std::fabs(nx) <= 0.5 * m_boardWidth && std::fabs(ny) <= 0.5 * m_boardHeight;
  // A nose just through the board (within a hull length) came from the front: push it back onto the surface and
  // cancel the velocity into the board; the board is rigid and much heavier than the vehicle.
  if (onBoard && nz > 0. && nz < half) {
    const vpColVector nW = m_wMo.getRotationMatrix() * vpColVector(vpTranslationVector(0., 0., 1.));
    for (unsigned int i = 0; i < 3; ++i) {
      m_wMv[i][3] -= nz * nW[i];
    }
    const vpColVector nV = m_wMv.getRotationMatrix().t() * nW;
    const double into = m_nu[0] * nV[0] + m_nu[1] * nV[1] + m_nu[2] * nV[2];
    if (into > 0.) {
      for (unsigned int i = 0; i < 3; ++i) {
        m_nu[i] -= into * nV[i];
      }
    }
  }
  double d;
  const bool ray = frontRay(d);
  m_collision = (onBoard && nz > -m_collisionThreshold && nz < half) || (ray && d < m_collisionThreshold);
  if (m_collision && !std::isfinite(m_firstCollision)) {
    m_firstCollision = m_t;
  }
}

bool vpSSLAuvSimulator::frontRay(double &distance) const
{
  distance = kNaN;
  if (!m_targetInWater) {
    return false;
  }
  const vpHomogeneousMatrix oMv = m_wMo.inverse() * m_wMv;
  const double half = 0.5 * m_param.length;
  const double p[3] = {oMv[0][0] * half + oMv[0][3], oMv[1][0] * half + oMv[1][3], oMv[2][0] * half + oMv[2][3]};
  const double d[3] = {oMv[0][0], oMv[1][0], oMv[2][0]};
  if (std::fabs(d[2]) < 1e-9) {
    return false;
  }
  double s = -p[2] / d[2];
  // A nose resting on the board (after contact()) may be a hair past it.
  if (s < 0.) {
    if (s < -1e-6) {
      return false;
    }
    s = 0.;
  }
  const double X = p[0] + s * d[0], Y = p[1] + s * d[1];
  if (std::fabs(X) > 0.5 * m_boardWidth || std::fabs(Y) > 0.5 * m_boardHeight) {
    return false;
  }
  distance = s;
  return true;
}

double vpSSLAuvSimulator::getTrueFrontRange() const
{
  double d;
  frontRay(d);
  return d;
}

double vpSSLAuvSimulator::getFrontRange()
{
  const double noise = m_rangeSigma * m_rangeNoise();
  const double d = getTrueFrontRange();
  if (!std::isfinite(d) || d > m_rangeMax) {
    return kNaN;
  }
  return std::max(0., d + noise);
}

double vpSSLAuvSimulator::getDepthMeasurement()
{
  return m_wMv[2][3] + m_depthNoise();
}

vpHomogeneousMatrix vpSSLAuvSimulator::get_cMo() const
{
  return get_wMc().inverse() * m_wMo;
}

void vpSSLAuvSimulator::setPosition(const vpRobot::vpControlFrameType frame, const vpColVector &q)
{
  if (q.getRows() != 6) {
    throw vpException(vpException::dimensionError, "vpSSLAuvSimulator::setPosition(): q has %u rows, expected 6",
                      q.getRows());
  }
  const vpHomogeneousMatrix M(vpPoseVector(q[0], q[1], q[2], q[3], q[4], q[5]));
  if (!isFiniteRigid(M)) {
    throw vpException(vpException::badValue, "vpSSLAuvSimulator::setPosition(): q is not finite");
  }
  switch (frame) {
  case vpRobot::REFERENCE_FRAME:
  case vpRobot::ARTICULAR_FRAME:
  case vpRobot::END_EFFECTOR_FRAME:
    m_wMv = M;
    break;
  case vpRobot::CAMERA_FRAME:
    m_wMv = M * m_vMc.inverse();
    break;
  default:
    throw vpException(vpException::notImplementedError, "vpSSLAuvSimulator::setPosition(): unsupported frame");
  }
  init();
}

void vpSSLAuvSimulator::getPosition(const vpRobot::vpControlFrameType frame, vpColVector &q)
{
  vpPoseVector r;
  if (frame == vpRobot::CAMERA_FRAME) {
    r.buildFrom(get_wMc());
  } else if (frame == vpRobot::REFERENCE_FRAME || frame == vpRobot::ARTICULAR_FRAME ||
             frame == vpRobot::END_EFFECTOR_FRAME) {
    r.buildFrom(m_wMv);
  } else {
    throw vpException(vpException::notImplementedError, "vpSSLAuvSimulator::getPosition(): unsupported frame");
  }
  q = r;
}

void vpSSLAuvSimulator::getDisplacement(const vpRobot::vpControlFrameType frame, vpColVector &q)
{
  const vpHomogeneousMatrix vMv = m_wMvLastDisplacement.inverse() * m_wMv;
  m_wMvLastDisplacement = m_wMv;
  vpPoseVector r;
  if (frame == vpRobot::CAMERA_FRAME) {
    r.buildFrom(m_vMc.inverse() * vMv * m_vMc);
  } else {
    r.buildFrom(vMv);
  }
  q = r;
}

void vpSSLAuvSimulator::get_eJe(vpMatrix &eJe)
{
  eJe.eye(6);
}

void vpSSLAuvSimulator::get_fJe(vpMatrix &fJe)
{
  const vpRotationMatrix R = m_wMv.getRotationMatrix();
  fJe.resize(6, 6, true);
  for (unsigned int i = 0; i < 3; ++i) {
    for (unsigned int j = 0; j < 3; ++j) {
      fJe[i][j] = R[i][j];
      fJe[3 + i][3 + j] = R[i][j];
    }
  }
}
