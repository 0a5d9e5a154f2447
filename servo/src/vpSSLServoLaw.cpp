#include <visp3/ssl_servo/vpSSLServoLaw.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <visp3/core/vpException.h>
#include <visp3/core/vpMath.h>
#include <visp3/core/vpRotationMatrix.h>
#include <visp3/ssl/vpSSLFinite.h>
#include <visp3/ssl/vpSSLPointTransform.h>

namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();
// Beyond these a value is not a measurement but garbage: |x| = 1e3 is 89.94 deg off the optical axis, and
// squaring such values in the interaction matrix could overflow before any check on the output.
const double kMaxImageCoordinate = 1e3;
const double kMaxDistance = 1e6;

void checkAxis(vpSSLVehicleAxis axis)
{
  if (static_cast<int>(axis) < 0 || static_cast<int>(axis) > 5) {
    throw vpException(vpException::badValue, "vpSSLServoLaw: axis: %d is not in [0, 5]", static_cast<int>(axis));
  }
}

void objectCentroid(const vpSSLServoInput &input, double &X, double &Y, double &Z)
{
  X = Y = Z = 0.;
  for (const vpSSLServoPoint &p : input.points) {
    X += p.oX;
    Y += p.oY;
    Z += p.oZ;
  }
  const double n = static_cast<double>(input.points.size());
  X /= n;
  Y /= n;
  Z /= n;
}

// Target centre (centroid of the object points) in the image and its depth: through the pose when it is
// usable, else the mean of the points.
void targetCentre(const vpSSLServoInput &input, double &x, double &y, double &depth)
{
  double X, Y, Z;
  objectCentroid(input, X, Y, Z);
  if (input.hasPose && vpSSLFinite::isFinite(input.cMo)) {
    const vpHomogeneousMatrix &M = input.cMo;
    double c[3];
    vpSSLPointTransform::apply(M, X, Y, Z, c);
    const double cx = c[0], cy = c[1], cz = c[2];
    // A pose that disagrees with the points so much that the centre is behind the camera or off to infinity
    // is not trusted: the points' mean is used instead.
    if (cz > 0. && cz <= kMaxDistance && std::fabs(cx / cz) <= kMaxImageCoordinate &&
        std::fabs(cy / cz) <= kMaxImageCoordinate) {
      x = cx / cz;
      y = cy / cz;
      depth = cz;
      return;
    }
  }
  double sx = 0., sy = 0., sz = 0.;
  for (const vpSSLServoPoint &p : input.points) {
    sx += p.x;
    sy += p.y;
    sz += p.Z;
  }
  const double n = static_cast<double>(input.points.size());
  x = sx / n;
  y = sy / n;
  depth = sz / n;
}

} // namespace

vpSSLServoLaw::vpSSLServoLaw()
    : m_standOff(2.), m_minDepth(0.05), m_minPointStandOff(0.3), m_vMc(forwardCameraMount(0.)), m_enabled(), m_weight(),
      m_pseudoInverseThreshold(0.005), m_gain(0.8, 0.2, 15.), m_vmax(6), m_status(SSL_SERVO_NO_TARGET),
      m_saturated(false), m_velocity(6, 0.), m_cameraVelocity(6, 0.), m_error(), m_pointError(kNaN),
      m_centreDepth(kNaN), m_centreX(kNaN), m_centreY(kNaN)
{
  for (unsigned int i = 0; i < 6; ++i) {
    m_enabled[i] = true;
    m_weight[i] = 1.;
  }
  // Starbug (paper Sec. 5.1): thrusters drive surge, heave, roll, pitch and yaw; sway only marginally.
  m_enabled[SSL_AXIS_SWAY] = false;
  // The hull rights its roll and pitch (centre of gravity below the centre of buoyancy): turning it about those
  // axes costs thrust that heave and yaw do not, so the least-squares solution is told to prefer the others.
  m_weight[SSL_AXIS_ROLL] = 0.3;
  m_weight[SSL_AXIS_PITCH] = 0.3;
  m_vmax[SSL_AXIS_SURGE] = 0.5;
  m_vmax[SSL_AXIS_SWAY] = 0.2;
  m_vmax[SSL_AXIS_HEAVE] = 0.3;
  m_vmax[SSL_AXIS_ROLL] = 0.3;
  m_vmax[SSL_AXIS_PITCH] = 0.3;
  m_vmax[SSL_AXIS_YAW] = 0.5;
}

vpHomogeneousMatrix vpSSLServoLaw::forwardCameraMount(double ahead)
{
  // Columns: camera x, y, z axes in the vehicle frame (starboard, down, forward).
  vpRotationMatrix vRc;
  vRc[0][0] = 0.;
  vRc[0][1] = 0.;
  vRc[0][2] = 1.;
  vRc[1][0] = 1.;
  vRc[1][1] = 0.;
  vRc[1][2] = 0.;
  vRc[2][0] = 0.;
  vRc[2][1] = 1.;
  vRc[2][2] = 0.;
  return vpHomogeneousMatrix(vpTranslationVector(ahead, 0., 0.), vRc);
}

void vpSSLServoLaw::setStandOff(double Zstar)
{
  if (!std::isfinite(Zstar) || Zstar < 0.) {
    throw vpException(vpException::badValue, "vpSSLServoLaw::setStandOff: Zstar: %g is not a finite value >= 0", Zstar);
  }
  m_standOff = Zstar;
}

void vpSSLServoLaw::setMinDepth(double Zmin)
{
  if (!std::isfinite(Zmin) || !(Zmin > 0.)) {
    throw vpException(vpException::badValue, "vpSSLServoLaw::setMinDepth: Zmin: %g is not a finite value > 0", Zmin);
  }
  m_minDepth = Zmin;
}

void vpSSLServoLaw::setMinPointStandOff(double Zmin)
{
  if (!std::isfinite(Zmin) || !(Zmin > 0.)) {
    throw vpException(vpException::badValue, "vpSSLServoLaw::setMinPointStandOff: Zmin: %g is not a finite value > 0",
                      Zmin);
  }
  m_minPointStandOff = Zmin;
}

void vpSSLServoLaw::setCameraToVehicle(const vpHomogeneousMatrix &vMc)
{
  if (!vpSSLFinite::isFinite(vMc)) {
    throw vpException(vpException::badValue, "vpSSLServoLaw::setCameraToVehicle: vMc: not finite");
  }
  m_vMc = vMc;
}

void vpSSLServoLaw::setCameraRobot()
{
  m_vMc.eye();
  for (unsigned int i = 0; i < 6; ++i) {
    m_enabled[i] = true;
    m_weight[i] = 1.;
  }
  // A camera that follows every twist at once has no lag to turn a weak direction into a limit cycle, and it
  // needs that direction (the facing rotation) to reach the desired pose.
  m_pseudoInverseThreshold = 1e-6;
}

void vpSSLServoLaw::setAxisEnabled(vpSSLVehicleAxis axis, bool enabled)
{
  checkAxis(axis);
  m_enabled[axis] = enabled;
}

bool vpSSLServoLaw::getAxisEnabled(vpSSLVehicleAxis axis) const
{
  checkAxis(axis);
  return m_enabled[axis];
}

void vpSSLServoLaw::setAxisWeight(vpSSLVehicleAxis axis, double weight)
{
  checkAxis(axis);
  if (!(weight > 0.) || !(weight <= 1.)) {
    throw vpException(vpException::badValue, "vpSSLServoLaw::setAxisWeight: weight: %g is not in (0, 1]", weight);
  }
  m_weight[axis] = weight;
}

double vpSSLServoLaw::getAxisWeight(vpSSLVehicleAxis axis) const
{
  checkAxis(axis);
  return m_weight[axis];
}

void vpSSLServoLaw::setPseudoInverseThreshold(double ratio)
{
  if (!(ratio >= 0.) || !(ratio < 1.)) {
    throw vpException(vpException::badValue, "vpSSLServoLaw::setPseudoInverseThreshold: ratio: %g is not in [0, 1)",
                      ratio);
  }
  m_pseudoInverseThreshold = ratio;
}

void vpSSLServoLaw::setGain(double lambda)
{
  if (!std::isfinite(lambda) || !(lambda > 0.)) {
    throw vpException(vpException::badValue, "vpSSLServoLaw::setGain: lambda: %g is not a finite value > 0", lambda);
  }
  m_gain.initFromConstant(lambda);
}

void vpSSLServoLaw::setGain(double gain0, double gainInf, double slope0)
{
  if (!std::isfinite(gain0) || !std::isfinite(gainInf) || !std::isfinite(slope0) || !(gain0 > 0.) || !(gainInf > 0.) ||
      gainInf > gain0 || slope0 < 0.) {
    throw vpException(vpException::badValue,
                      "vpSSLServoLaw::setGain: gain0 %g, gainInf %g, slope0 %g: need gain0 >= gainInf > 0 and "
                      "slope0 >= 0, all finite",
                      gain0, gainInf, slope0);
  }
  if (gain0 == gainInf || slope0 == 0.) {
    m_gain.initFromConstant(gain0);
  } else {
    m_gain.initStandard(gain0, gainInf, slope0);
  }
}

void vpSSLServoLaw::setVelocityLimits(const vpColVector &vmax)
{
  if (vmax.size() != 6) {
    throw vpException(vpException::dimensionError, "vpSSLServoLaw::setVelocityLimits: vmax: size %u, expected 6",
                      vmax.size());
  }
  for (unsigned int i = 0; i < 6; ++i) {
    if (!std::isfinite(vmax[i]) || !(vmax[i] > 0.)) {
      throw vpException(vpException::badValue,
                        "vpSSLServoLaw::setVelocityLimits: vmax[%u]: %g is not a finite value > 0", i, vmax[i]);
    }
  }
  m_vmax = vmax;
}

std::string vpSSLServoLaw::getStatusName(vpSSLServoStatus status)
{
  switch (status) {
  case SSL_SERVO_OK:
    return "ok";
  case SSL_SERVO_NO_TARGET:
    return "no-target";
  case SSL_SERVO_INVALID_INPUT:
    return "invalid-input";
  case SSL_SERVO_BEHIND_CAMERA:
    return "behind-camera";
  case SSL_SERVO_NUMERICAL_FAILURE:
    return "numerical-failure";
  }
  return "unknown";
}

vpColVector vpSSLServoLaw::toCameraVelocity(const vpColVector &v) const
{
  if (v.size() != 6) {
    throw vpException(vpException::dimensionError, "vpSSLServoLaw::toCameraVelocity: v: size %u, expected 6", v.size());
  }
  return vpVelocityTwistMatrix(m_vMc.inverse()) * v;
}

vpMatrix vpSSLServoLaw::getVehicleJacobian() const
{
  unsigned int n = 0;
  for (unsigned int i = 0; i < 6; ++i) {
    n += m_enabled[i] ? 1 : 0;
  }
  vpMatrix eJe(6, n, 0.);
  unsigned int k = 0;
  for (unsigned int i = 0; i < 6; ++i) {
    if (m_enabled[i]) {
      eJe[i][k++] = m_weight[i];
    }
  }
  return eJe;
}

void vpSSLServoLaw::fail(vpSSLServoStatus status)
{
  m_status = status;
  m_saturated = false;
  m_velocity = vpColVector(6, 0.);
  m_cameraVelocity = vpColVector(6, 0.);
  m_error = vpColVector();
  m_taskJacobian = vpMatrix();
  m_pointError = kNaN;
  m_centreDepth = kNaN;
  m_centreX = kNaN;
  m_centreY = kNaN;
}

vpSSLServoStatus vpSSLServoLaw::checkInput(const vpSSLServoInput &input)
{
  if (!input.valid || input.points.empty()) {
    return SSL_SERVO_NO_TARGET;
  }
  for (const vpSSLServoPoint &p : input.points) {
    const double v[6] = {p.oX, p.oY, p.oZ, p.x, p.y, p.Z};
    for (double a : v) {
      if (!std::isfinite(a)) {
        return SSL_SERVO_INVALID_INPUT;
      }
    }
    if (std::fabs(p.x) > kMaxImageCoordinate || std::fabs(p.y) > kMaxImageCoordinate ||
        std::fabs(p.oX) > kMaxDistance || std::fabs(p.oY) > kMaxDistance || std::fabs(p.oZ) > kMaxDistance ||
        p.Z > kMaxDistance) {
      return SSL_SERVO_INVALID_INPUT;
    }
    if (!(p.Z > 0.)) {
      return SSL_SERVO_BEHIND_CAMERA;
    }
  }
  return SSL_SERVO_OK;
}

void vpSSLServoLaw::computeCentre(const vpSSLServoInput &input)
{
  targetCentre(input, m_centreX, m_centreY, m_centreDepth);
}

bool vpSSLServoLaw::getTargetCentre(const vpSSLServoInput &input, double &x, double &y, double &Z)
{
  if (checkInput(input) != SSL_SERVO_OK) {
    x = y = Z = kNaN;
    return false;
  }
  targetCentre(input, x, y, Z);
  return true;
}

vpHomogeneousMatrix vpSSLServoLaw::getDesiredPose(const vpSSLServoInput &input) const
{
  if (input.points.empty()) {
    return vpHomogeneousMatrix(0., 0., std::max(m_standOff, m_minPointStandOff), 0., 0., 0.);
  }
  double X, Y, Z;
  objectCentroid(input, X, Y, Z);
  double Zp = m_standOff;
  if (Zp < m_minPointStandOff) {
    // Docking: below the point stand-off the desired image is the centred, facing target at the current range,
    // so that the points only steer and the depth feature alone closes the range (doc/servo.md).
    double xc, yc, Zc;
    targetCentre(input, xc, yc, Zc);
    if (!std::isfinite(Zc)) {
      Zc = m_minPointStandOff;
    }
    Zp = std::max(Zc, m_minDepth);
  }
  return vpHomogeneousMatrix(vpTranslationVector(-X, -Y, Zp - Z), vpRotationMatrix());
}

vpColVector vpSSLServoLaw::computeControlLaw(const vpSSLServoInput &input)
{
  return solve(input, false);
}

vpColVector vpSSLServoLaw::computeCentringLaw(const vpSSLServoInput &input)
{
  return solve(input, true);
}

vpColVector vpSSLServoLaw::solve(const vpSSLServoInput &input, bool centringOnly)
{
  const vpSSLServoStatus status = checkInput(input);
  if (status != SSL_SERVO_OK) {
    fail(status);
    return m_velocity;
  }
  computeCentre(input);
  const double xc = m_centreX, yc = m_centreY, Zc = m_centreDepth;

  // Axes driven by this law.
  const vpHomogeneousMatrix cMv = m_vMc.inverse();
  std::vector<unsigned int> axes;
  for (unsigned int i = 0; i < 6; ++i) {
    if (!m_enabled[i]) {
      continue;
    }
    if (centringOnly) {
      // Translations across the optical axis and rotations that turn it; a motion along the optical axis (the
      // surge of a forward camera, the roll about it) cannot centre. Heave is kept: a hull that rights its pitch
      // cannot hold a target 15 deg below with pitch alone (the ALIGN stall of fig7).
      const double alongOpticalAxis = std::fabs(cMv[2][i < 3 ? i : i - 3]);
      if (alongOpticalAxis > 0.9) {
        continue;
      }
    }
    axes.push_back(i);
  }
  if (axes.empty()) {
    fail(SSL_SERVO_OK);
    m_centreX = xc;
    m_centreY = yc;
    m_centreDepth = Zc;
    return m_velocity;
  }
  vpMatrix eJe(6, static_cast<unsigned int>(axes.size()), 0.);
  for (size_t k = 0; k < axes.size(); ++k) {
    // Weighted minimum norm: v = W qdot with qdot = -lambda (L cVe eJe W)^+ e, so that of the motions that give
    // the same feature velocity the one using the heavier-weighted axes is chosen.
    eJe[axes[k]][static_cast<unsigned int>(k)] = m_weight[axes[k]];
  }

  vpColVector qdot;
  double pointError = 0.;
  try {
    vpServo task;
    task.setServo(vpServo::EYEINHAND_L_cVe_eJe);
    task.setInteractionMatrixType(vpServo::CURRENT, vpServo::PSEUDO_INVERSE);
    task.setLambda(m_gain);
    // For a distant target heave and pitch move the image alike (v_y = Z w_x), so L cVe eJe has a singular
    // value ~1e-4 of the largest; inverted, it turned a small inconsistency of the docking error into a
    // heave-pitch command at the limits (the vehicle dived under the board in fig9). Truncate it.
    task.setPseudoInverseThreshold(m_pseudoInverseThreshold);
    task.set_cVe(vpVelocityTwistMatrix(cMv));
    task.set_eJe(eJe);

    if (centringOnly) {
      m_s.assign(1, vpFeaturePoint());
      m_sd.assign(1, vpFeaturePoint());
      m_s[0].buildFrom(xc, yc, std::max(Zc, m_minDepth));
      m_sd[0].buildFrom(0., 0., std::max(Zc, m_minDepth));
      task.addFeature(m_s[0], m_sd[0]);
      pointError = std::sqrt(xc * xc + yc * yc);
    } else {
      const vpHomogeneousMatrix cdMo = getDesiredPose(input);
      const size_t n = input.points.size();
      // Sized before any addFeature(): vpServo keeps pointers to these features.
      m_s.assign(n, vpFeaturePoint());
      m_sd.assign(n, vpFeaturePoint());
      for (size_t i = 0; i < n; ++i) {
        const vpSSLServoPoint &p = input.points[i];
        m_s[i].buildFrom(p.x, p.y, std::max(p.Z, m_minDepth));
        double c[3];
        vpSSLPointTransform::apply(cdMo, p.oX, p.oY, p.oZ, c);
        const double X = c[0], Y = c[1], Z = std::max(c[2], m_minDepth);
        m_sd[i].buildFrom(X / Z, Y / Z, Z);
        task.addFeature(m_s[i], m_sd[i]);
        pointError += vpMath::sqr(p.x - X / Z) + vpMath::sqr(p.y - Y / Z);
      }
      pointError = std::sqrt(pointError / static_cast<double>(n));
      // log(Z/Z*) with both depths floored: Z* = 0 (docking) would make it undefined.
      const double Zs = std::max(m_standOff, m_minDepth);
      const double Zf = std::max(Zc, m_minDepth);
      m_depth.buildFrom(xc, yc, Zf, std::log(Zf / Zs));
      m_depthDesired.buildFrom(0., 0., Zs, 0.);
      task.addFeature(m_depth, m_depthDesired);
    }
    qdot = task.computeControlLaw();
    m_error = task.getError();
    m_taskJacobian = task.getTaskJacobian();
  } catch (const std::exception &) {
    fail(SSL_SERVO_NUMERICAL_FAILURE);
    return m_velocity;
  }
  if (qdot.size() != axes.size() || !vpSSLFinite::isFinite(qdot)) {
    fail(SSL_SERVO_NUMERICAL_FAILURE);
    return m_velocity;
  }

  vpColVector v(6, 0.);
  for (size_t k = 0; k < axes.size(); ++k) {
    v[axes[k]] = m_weight[axes[k]] * qdot[static_cast<unsigned int>(k)];
  }
  // Scale the whole command, not each axis alone, so that its direction (the descent direction) is kept.
  double scale = 1.;
  for (unsigned int i = 0; i < 6; ++i) {
    scale = std::max(scale, std::fabs(v[i]) / m_vmax[i]);
  }
  m_saturated = scale > 1.;
  if (m_saturated) {
    v /= scale;
  }
  const vpColVector vc = vpVelocityTwistMatrix(cMv) * v;
  if (!vpSSLFinite::isFinite(v) || !vpSSLFinite::isFinite(vc)) {
    fail(SSL_SERVO_NUMERICAL_FAILURE);
    return m_velocity;
  }
  m_status = SSL_SERVO_OK;
  m_velocity = v;
  m_cameraVelocity = vc;
  m_pointError = pointError;
  m_centreX = xc;
  m_centreY = yc;
  m_centreDepth = Zc;
  return m_velocity;
}
