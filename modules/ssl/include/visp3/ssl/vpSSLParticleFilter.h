/*!
  \file vpSSLParticleFilter.h
  \brief Particle filter on the target pose, fused with the vehicle odometry (paper Sec. 3.3).
*/
#ifndef VP_SSL_PARTICLE_FILTER_H
#define VP_SSL_PARTICLE_FILTER_H

#include <vector>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpColVector.h>
#include <visp3/core/vpGaussRand.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpMatrix.h>
#include <visp3/core/vpQuaternionVector.h>
#include <visp3/core/vpUniRand.h>
#include <visp3/ssl/vpSSLConfig.h>
#include <visp3/ssl/vpSSLPoseHypothesis.h>
#include <visp3/ssl/vpSSLTarget.h>

/*!
  \struct vpSSLObservation
  \ingroup group_ssl
  \brief One detected landmark given to vpSSLParticleFilter::update().
*/
struct VISP_SSL_EXPORT vpSSLObservation
{
  int label = -1;     ///< Index of the target landmark, or -1 when unknown (associated to the nearest one).
  double u = 0.;      ///< Centre column (px).
  double v = 0.;      ///< Centre row (px).
  double radius = 0.; ///< Apparent outer radius (px); <= 0 when unknown (the radius term is then skipped).
};

/*!
  \class vpSSLParticleFilter
  \ingroup group_ssl
  \brief Tracks the target pose cMo with particles (position and unit quaternion in the camera frame,
  the paper's 7-D state, Sec. 3.3).

  - init(): particles drawn around every pose hypothesis, in proportion to its weight.
  - predict(): the target moves by the inverse of the camera displacement derived from the vehicle
    odometry (paper: R = Rv^T, T = -Rv^T t), plus process noise; without odometry, a random walk.
    Odometry that is not finite, not a rigid motion or larger than setMaxOdometryStep() is rejected.
  - update(): each particle projects the target's landmarks; each detection goes to its labelled
    landmark, or else to the nearest projected one; the log-likelihood is a Gaussian of the summed
    pixel distance (sigma setPixelSigma(), the paper's Sigma_1) plus a Gaussian of the summed radius
    error (predicted radius px R / Z, sigma setRadiusSigma()). Weights are kept as logarithms so they
    never underflow; systematic resampling happens when the effective sample size falls below
    setResampleThreshold() times the number of particles, each copy jittered by a kernel shaped like the
    weighted covariance (regularised resampling, setRegularisation()) so that the cloud does not
    collapse onto a few particles in the 6-D pose space.
  - When even the best particle is hopeless (every particle's log-likelihood below
    setHopelessLogLikelihood()), the update is not applied: the filter re-initialises from the
    recovery hypotheses given to update(), or else keeps its prediction, and says so in the status.

  Buffers are allocated by init(); predict() and update() allocate nothing.
  The lens distortion is ignored: give undistorted pixel coordinates.

  \code
  vpSSLParticleFilter filter(vpSSLTarget::ssl3a3(), cam);
  filter.setSeed(42);
  filter.init(hypotheses);                      // from the single-frame pose (Sec. 3.2)
  for (;;) {
    filter.predict(v1Mv2, cMv);                 // vehicle odometry since the previous image
    filter.update(observations);                // detected landmarks of this image
    vpHomogeneousMatrix cMo = filter.getMeanPose();
  }
  \endcode
  See test/test_particle_filter.cpp for complete synthetic runs.
*/
class VISP_SSL_EXPORT vpSSLParticleFilter
{
public:
  //! Outcome of update().
  enum vpUpdateStatus
  {
    UPDATED,        ///< The observations were applied.
    NO_OBSERVATION, ///< Nothing to apply; the particles are unchanged.
    HOPELESS_KEPT,  ///< No particle explained the observations: they were ignored, the prediction kept.
    REINITIALISED   ///< No particle explained the observations: re-initialised from the recovery hypotheses.
  };

  /*!
    A filter for \e target seen by a camera of intrinsics \e cam (distortion ignored).
    \exception vpException if the target has no landmark.
  */
  vpSSLParticleFilter(const vpSSLTarget &target, const vpCameraParameters &cam);

  /*!
    Sets the number of particles (default 1000); the filter must then be initialised again with init().
    \exception vpException if \e n is 0.
  */
  void setNbParticles(unsigned int n);
  //! Restarts the random generators: two filters with the same seed and inputs give identical results.
  void setSeed(long seed);
  //! Process noise of predict(): per-axis translation (m) and per-axis theta-u (rad) standard deviations
  //! per prediction (default 0.005 m and 0.005 rad).
  void setProcessNoise(double translationSigma, double rotationSigma);
  /*!
    Process noise used instead when predict() rejects the odometry (default 0.02 m and 0.05 rad): the
    vehicle moved by an unknown amount, so the particles must spread enough for the next update to find it.
  */
  void setRejectedOdometryNoise(double translationSigma, double rotationSigma);
  //! Standard deviation of the summed landmark centre distance (px), the paper's Sigma_1 (default 3).
  void setPixelSigma(double sigma);
  //! Standard deviation of the summed apparent radius error (px, default 3); <= 0 disables the radius term.
  void setRadiusSigma(double sigma) { m_radiusSigma = sigma; }
  //! Resample when the effective sample size falls below \e fraction times the particle count (default 0.5).
  void setResampleThreshold(double fraction) { m_resampleFraction = fraction; }
  //! Largest odometry step accepted by predict(): translation (m) and rotation angle (rad)
  //! (default 1 m and pi/4).
  void setMaxOdometryStep(double translation, double rotation);
  //! Below this log-likelihood a particle is hopeless (default -0.5 * 50^2: a summed distance of 50 sigmas).
  void setHopelessLogLikelihood(double logLikelihood) { m_hopelessLogLikelihood = logLikelihood; }
  /*!
    Bandwidth of the regularised resampling, as a fraction of the weighted spread (default 0.5): each copy is
    jittered by a Gaussian of covariance fraction^2 times the covariance; 0 gives plain systematic resampling.
  */
  void setRegularisation(double fraction) { m_regularisation = fraction; }
  //! getConverged() is true when the RMS position spread is below \e spread (m, default 0.05).
  void setConvergenceThreshold(double spread) { m_convergenceSpread = spread; }

  /*!
    Draws the particles around \e hypotheses, each getting a share proportional to its weight.
    \exception vpException if the list is empty or a hypothesis has a non-finite pose or a weight <= 0.
  */
  void init(const std::vector<vpSSLPoseHypothesis> &hypotheses);

  /*!
    Moves the particles by the vehicle displacement \e v1Mv2 (pose of the vehicle at this image in its
    frame at the previous image) seen through the camera mounting \e cMv (pose of the vehicle frame in
    the camera frame, like ViSP's cMe), then adds process noise.
    \return true if the odometry was used, false if it was rejected (not finite, not a rigid motion, or
    larger than setMaxOdometryStep()) and only the process noise was applied.
  */
  bool predict(const vpHomogeneousMatrix &v1Mv2, const vpHomogeneousMatrix &cMv = vpHomogeneousMatrix());

  //! Random-walk prediction (process noise only), when no odometry is available.
  void predict();

  /*!
    Weighs the particles by \e observations and resamples when needed. \e recovery (may be empty) is
    used to re-initialise when no particle explains the observations.
    \exception vpException if a label is outside the target or a value is not finite.
  */
  vpUpdateStatus update(const std::vector<vpSSLObservation> &observations,
                        const std::vector<vpSSLPoseHypothesis> &recovery = std::vector<vpSSLPoseHypothesis>());

  //! Weighted mean pose: mean position, quaternion mean as the dominant eigenvector of sum w q q^T.
  vpHomogeneousMatrix getMeanPose() const { return m_meanPose; }
  //! Pose of the particle with the largest weight.
  vpHomogeneousMatrix getBestPose() const { return m_bestPose; }
  /*!
    6x6 weighted covariance about the mean pose: translation (m) then theta-u (rad) of the rotation
    R_i R_mean^T, both in the camera frame.
  */
  vpMatrix getCovariance() const { return m_covariance; }
  //! True when the RMS position spread is below the convergence threshold.
  bool getConverged() const { return m_converged; }
  //! Effective sample size 1 / sum w_i^2 of the normalised weights.
  double getEffectiveSampleSize() const { return m_ess; }
  //! Number of particles.
  unsigned int getNbParticles() const { return m_nbParticles; }
  //! True once init() was called.
  bool isInitialised() const { return m_initialised; }
  //! Pose of particle \e i. \exception vpException if out of range.
  vpHomogeneousMatrix getParticlePose(unsigned int i) const;
  //! Normalised weight of particle \e i. \exception vpException if out of range.
  double getParticleWeight(unsigned int i) const;
  //! Number of resamplings since init().
  unsigned int getNbResamplings() const { return m_nbResamplings; }

  /*!
    Weighted mean of unit quaternions, insensitive to their sign (q and -q are the same rotation): the
    eigenvector of the largest eigenvalue of sum w_i q_i q_i^T (Markley et al., 2007).
    \exception vpException if the sizes differ, the list is empty or the weights sum to 0.
  */
  static vpQuaternionVector meanQuaternion(const std::vector<vpQuaternionVector> &q, const std::vector<double> &w);

private:
  struct Particle
  {
    double t[3]; // target position in the camera frame (m)
    double q[4]; // unit quaternion of cRo, in Eigen's coefficient order (x, y, z, w)
  };

  vpSSLTarget m_target;
  vpCameraParameters m_cam;
  std::vector<double> m_landmarks; // x, y, z, radius per landmark, target frame
  unsigned int m_nbParticles;
  std::vector<Particle> m_particles;
  std::vector<Particle> m_scratch; // resampling target, swapped with m_particles
  std::vector<double> m_logWeights;
  std::vector<double> m_weights;
  std::vector<double> m_proj; // u, v, r, valid per landmark, reused for each particle
  vpUniRand m_uni;
  vpGaussRand m_gauss;
  double m_transSigma;
  double m_rotSigma;
  double m_pixelSigma;
  double m_radiusSigma;
  double m_resampleFraction;
  double m_maxOdoTranslation;
  double m_maxOdoRotation;
  double m_rejectedTransSigma;
  double m_rejectedRotSigma;
  double m_hopelessLogLikelihood;
  double m_regularisation;
  double m_convergenceSpread;
  bool m_initialised;
  unsigned int m_nbResamplings;
  vpHomogeneousMatrix m_meanPose;
  vpHomogeneousMatrix m_bestPose;
  vpMatrix m_covariance;
  bool m_converged;
  double m_ess;

  void checkInitialised(const char *where) const;
  void addProcessNoise(Particle &p);
  double logLikelihood(const Particle &p, const std::vector<vpSSLObservation> &observations);
  void normaliseWeights();
  void resample();
  void updateEstimate();
};

#endif
