/*!
  \file vpSSLDeadReckoning.cpp
  \brief Dead reckoning from IMU attitude, compass heading, depth sensor and integrated body velocity.
*/
#include <visp3/ssl_sim/vpSSLDeadReckoning.h>

#include <cmath>

#include <visp3/core/vpException.h>
#include <visp3/core/vpMath.h>
#include <visp3/core/vpRzyxVector.h>

namespace {
void checkSigma(double sigma, const char *what)
{
  if (!(sigma >= 0. && std::isfinite(sigma))) {
    throw vpException(vpException::badValue, "vpSSLDeadReckoning: %s %g must be finite and >= 0", what, sigma);
  }
}
} // namespace

vpSSLDeadReckoning::vpSSLDeadReckoning()
    // A MEMS IMU levels to a few tenths of a degree; a compass inside a small hull near thrusters is off by a
    // couple of degrees; a pressure sensor resolves centimetres; a propeller-speed velocity model is good to
    // about 5 %.
    : m_attitudeSigma(vpMath::rad(0.3)), m_headingBiasSigma(vpMath::rad(2.)), m_headingSigma(vpMath::rad(0.5)),
      m_depthSigma(0.02), m_scaleSigma(0.05), m_velocitySigma(0.03), m_started(false), m_noise(1., 0.),
      m_headingBias(0.), m_scale(1.), m_wMv0(), m_wMv(), m_oMv(), m_x(0.), m_y(0.)
{
}

void vpSSLDeadReckoning::setAttitudeNoise(double sigma)
{
  checkSigma(sigma, "attitude noise");
  m_attitudeSigma = sigma;
}

void vpSSLDeadReckoning::setHeadingNoise(double biasSigma, double sigma)
{
  checkSigma(biasSigma, "heading bias");
  checkSigma(sigma, "heading noise");
  m_headingBiasSigma = biasSigma;
  m_headingSigma = sigma;
}

void vpSSLDeadReckoning::setDepthNoise(double sigma)
{
  checkSigma(sigma, "depth noise");
  m_depthSigma = sigma;
}

void vpSSLDeadReckoning::setVelocityNoise(double scaleSigma, double sigma)
{
  checkSigma(scaleSigma, "velocity scale error");
  checkSigma(sigma, "velocity noise");
  m_scaleSigma = scaleSigma;
  m_velocitySigma = sigma;
}

vpHomogeneousMatrix vpSSLDeadReckoning::reset(const vpHomogeneousMatrix &wMv, long seed)
{
  m_noise = vpGaussRand(1., 0., seed);
  m_headingBias = m_headingBiasSigma * m_noise();
  m_scale = 1. + m_scaleSigma * m_noise();
  m_wMv0 = wMv;
  m_wMv = wMv;
  m_x = m_y = 0.;
  m_started = true;
  m_oMv = measure(wMv, m_x, m_y);
  return m_oMv;
}

vpHomogeneousMatrix vpSSLDeadReckoning::update(const vpHomogeneousMatrix &wMv, double dt)
{
  if (!m_started) {
    throw vpException(vpException::notInitialized, "vpSSLDeadReckoning: call reset() before update()");
  }
  if (!(dt > 0. && std::isfinite(dt))) {
    throw vpException(vpException::badValue, "vpSSLDeadReckoning: time step %g s must be > 0", dt);
  }
  // True body velocity over the step, as a DVL or a propeller model measures it, with its errors.
  const vpTranslationVector dp = wMv.getTranslationVector() - m_wMv.getTranslationVector();
  const vpColVector vb = wMv.getRotationMatrix().t() * vpColVector(dp) / dt;
  vpColVector vm(3);
  for (unsigned int i = 0; i < 3; ++i) {
    vm[i] = m_scale * vb[i] + m_velocitySigma * m_noise();
  }
  // Rotated into the odometry frame with the attitude the vehicle believes (that of the previous step).
  const vpColVector step = m_oMv.getRotationMatrix() * vm * dt;
  m_x += step[0];
  m_y += step[1];
  m_wMv = wMv;
  m_oMv = measure(wMv, m_x, m_y);
  return m_oMv;
}

vpHomogeneousMatrix vpSSLDeadReckoning::measure(const vpHomogeneousMatrix &wMv, double x, double y)
{
  // vpRzyxVector is (yaw about z, pitch about y, roll about x): R = Rz Ry Rx, the NED convention.
  const vpRzyxVector rzyx(wMv.getRotationMatrix());
  const double yaw = rzyx[0] + m_headingBias + m_headingSigma * m_noise();
  const double pitch = rzyx[1] + m_attitudeSigma * m_noise();
  const double roll = rzyx[2] + m_attitudeSigma * m_noise();
  const double depth = wMv[2][3] - m_wMv0[2][3] + m_depthSigma * m_noise();
  return vpHomogeneousMatrix(vpTranslationVector(x, y, depth), vpRotationMatrix(vpRzyxVector(yaw, pitch, roll)));
}

vpHomogeneousMatrix vpSSLDeadReckoning::getTrue_oMv() const
{
  return vpHomogeneousMatrix(m_wMv.getTranslationVector() - m_wMv0.getTranslationVector(), m_wMv.getRotationMatrix());
}
