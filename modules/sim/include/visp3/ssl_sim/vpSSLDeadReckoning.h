/*!
  \file vpSSLDeadReckoning.h
  \brief Simulated vehicle odometry: IMU, compass and depth-sensor dead reckoning with noise and drift.
*/
#ifndef VP_SSL_DEAD_RECKONING_H
#define VP_SSL_DEAD_RECKONING_H

#include <visp3/core/vpGaussRand.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/ssl/vpSSLConfig.h>

/*!
  \class vpSSLDeadReckoning
  \ingroup group_ssl_sim
  \brief The odometry oMv a small AUV computes from its own sensors, given its true motion.

  Frames: the world is North-East-Down (z down, depth positive); the vehicle frame is x forward, y
  starboard, z down. The odometry frame o has the world's axes (the compass gives north, gravity gives
  down) and its origin where the vehicle was at reset().

  Each update() measures, from the true pose:
  - roll and pitch from the IMU's gravity vector: the truth plus white noise;
  - heading from the compass: the truth plus a bias drawn once per run (local magnetic disturbance) plus
    white noise;
  - depth from the pressure sensor: the truth plus white noise, no drift (it is absolute);
  - the horizontal position by integrating the body velocity (a DVL or the propeller model) with a scale
    error drawn once per run and white noise, rotated by the \e measured attitude: so the position drifts
    with the distance travelled and with the heading bias, as a real dead-reckoning solution does.
  Deterministic for a seed.

  \code
  vpSSLDeadReckoning odometry;
  odometry.reset(wMv0, 42);
  for (...) {
    vpHomogeneousMatrix oMv = odometry.update(wMv, dt);  // dt: time since the last call
  }
  \endcode
  See vpSSLScenario, which fills the odometry columns of a simulated sequence with it.
*/
class VISP_SSL_EXPORT vpSSLDeadReckoning
{
public:
  //! Figures typical of a small AUV without a DVL (the paper's Starbug): see the setters.
  vpSSLDeadReckoning();

  //! Standard deviation of the roll and pitch noise (rad, default 0.3 deg).
  void setAttitudeNoise(double sigma);
  //! Compass bias standard deviation (drawn once per run) and white noise (rad, defaults 2 deg and 0.5 deg).
  void setHeadingNoise(double biasSigma, double sigma);
  //! Depth sensor noise standard deviation (m, default 0.02).
  void setDepthNoise(double sigma);
  /*!
    Velocity scale error standard deviation (drawn once per run, default 0.05 = 5 %) and white noise on each
    horizontal velocity component (m/s, default 0.03).
  */
  void setVelocityNoise(double scaleSigma, double sigma);

  /*!
    Starts a run at the true vehicle pose \e wMv (world frame): the odometry origin is there and the
    per-run biases are drawn from \e seed.
    \return the first odometry pose oMv.
  */
  vpHomogeneousMatrix reset(const vpHomogeneousMatrix &wMv, long seed);
  /*!
    Advances to the true pose \e wMv, \e dt seconds after the previous one.
    \return the odometry pose oMv.
    \exception vpException if reset() was not called or dt is not > 0.
  */
  vpHomogeneousMatrix update(const vpHomogeneousMatrix &wMv, double dt);

  //! Current odometry pose oMv.
  const vpHomogeneousMatrix &get_oMv() const { return m_oMv; }
  //! The true pose of the vehicle in the odometry frame (what get_oMv() estimates).
  vpHomogeneousMatrix getTrue_oMv() const;

private:
  vpHomogeneousMatrix measure(const vpHomogeneousMatrix &wMv, double x, double y);

  double m_attitudeSigma;
  double m_headingBiasSigma;
  double m_headingSigma;
  double m_depthSigma;
  double m_scaleSigma;
  double m_velocitySigma;

  bool m_started;
  vpGaussRand m_noise;
  double m_headingBias;
  double m_scale;
  vpHomogeneousMatrix m_wMv0; //!< true pose at reset()
  vpHomogeneousMatrix m_wMv;  //!< true pose at the last update
  vpHomogeneousMatrix m_oMv;  //!< odometry pose
  double m_x, m_y;            //!< integrated horizontal position in o
};

#endif
