/*!
  \file vpSSLParticleFilter.cpp
  \brief Particle filter on the target pose (paper Sec. 3.3).
*/
#include <visp3/ssl/vpSSLParticleFilter.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <visp3/core/vpException.h>
#include <visp3/core/vpMath.h>
#include <visp3/ssl/vpSSLFinite.h>

namespace {
// Particle::q holds Eigen's coefficient order (x, y, z, w), so that it maps onto an Eigen::Quaterniond in place.
using Quat = Eigen::Map<Eigen::Quaterniond>;
using ConstQuat = Eigen::Map<const Eigen::Quaterniond>;
using Vec3 = Eigen::Map<Eigen::Vector3d>;
using ConstVec3 = Eigen::Map<const Eigen::Vector3d>;
using RowMajor4d = Eigen::Matrix<double, 4, 4, Eigen::RowMajor>;

// Exponential map of a rotation vector (angle times axis). Eigen::AngleAxisd needs a unit axis, which a zero
// rotation does not have: sin(a/2)/a tends to 1/2 as a tends to 0.
Eigen::Quaterniond rotationVectorToQuaternion(const Eigen::Vector3d &r)
{
  const double a = r.norm();
  const double s = (a < 1e-12) ? 0.5 : std::sin(0.5 * a) / a;
  Eigen::Quaterniond q;
  q.w() = std::cos(0.5 * a);
  q.vec() = s * r;
  return q;
}

// Rotation vector of the rotation of angle <= pi that q and -q both stand for.
Eigen::Vector3d quaternionToRotationVector(const Eigen::Quaterniond &q)
{
  const Eigen::AngleAxisd aa(q);
  return aa.angle() * aa.axis();
}

// Unit eigenvector of the largest eigenvalue of a symmetric 4x4 matrix, sign chosen so that w >= 0 (the
// eigenvector's sign is arbitrary; a fixed one keeps the output stable). Fixed size: no allocation.
Eigen::Quaterniond dominantQuaternion(const Eigen::Matrix4d &M)
{
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> solver(M);
  Eigen::Vector4d v = solver.eigenvectors().col(3); // eigenvalues in increasing order
  if (v[3] < 0) {
    v = -v;
  }
  Eigen::Quaterniond q(v); // coefficients (x, y, z, w)
  q.normalize();
  return q;
}

// The 4x4 of a vpHomogeneousMatrix, read in place (its storage is row-major): no allocation.
Eigen::Map<const RowMajor4d> asEigen(const vpHomogeneousMatrix &M)
{
  return Eigen::Map<const RowMajor4d>(M.data);
}

// A rigid motion: finite, orthonormal rotation with det +1, last row (0 0 0 1).
bool isRigid(const vpHomogeneousMatrix &M)
{
  if (!vpSSLFinite::isFinite(M)) {
    return false;
  }
  const Eigen::Map<const RowMajor4d> E = asEigen(M);
  const Eigen::Matrix3d R = E.topLeftCorner<3, 3>();
  if (((R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().array() > 1e-6).any()) {
    return false;
  }
  return R.determinant() > 0 && (E.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().sum() < 1e-9;
}

Eigen::Isometry3d toIsometry(const vpHomogeneousMatrix &M)
{
  Eigen::Isometry3d T;
  T.matrix() = asEigen(M);
  return T;
}

void setPose(vpHomogeneousMatrix &M, const double t[3], const double q[4])
{
  Eigen::Map<RowMajor4d> E(M.data);
  E.topLeftCorner<3, 3>() = ConstQuat(q).toRotationMatrix();
  E.topRightCorner<3, 1>() = ConstVec3(t);
}

// A detection with no projectable landmark costs this distance: larger than any image, yet finite.
const double kMissingDistance = 1e4;
} // namespace

vpSSLParticleFilter::vpSSLParticleFilter(const vpSSLTarget &target, const vpCameraParameters &cam)
    : m_target(target), m_cam(cam), m_landmarks(), m_nbParticles(1000), m_particles(), m_scratch(), m_logWeights(),
      m_weights(), m_proj(), m_uni(), m_gauss(1., 0.), m_transSigma(0.005), m_rotSigma(0.005), m_pixelSigma(3.),
      m_radiusSigma(3.), m_resampleFraction(0.5), m_maxOdoTranslation(1.), m_maxOdoRotation(M_PI / 4),
      m_rejectedTransSigma(0.02), m_rejectedRotSigma(0.05), m_hopelessLogLikelihood(-0.5 * 50 * 50),
      m_regularisation(0.5), m_convergenceSpread(0.05), m_initialised(false), m_nbResamplings(0), m_meanPose(),
      m_bestPose(), m_covariance(6, 6, 0.), m_converged(false), m_ess(0.)
{
  if (target.size() == 0) {
    throw vpException(vpException::badValue, "vpSSLParticleFilter: the target has no landmark");
  }
  for (const vpSSLTargetLandmark &l : target.getLandmarks()) {
    m_landmarks.push_back(l.x);
    m_landmarks.push_back(l.y);
    m_landmarks.push_back(l.z);
    m_landmarks.push_back(l.radius);
  }
  m_proj.resize(4 * target.size());
  setSeed(0);
}

void vpSSLParticleFilter::setNbParticles(unsigned int n)
{
  if (n == 0) {
    throw vpException(vpException::badValue, "vpSSLParticleFilter::setNbParticles: need at least one particle");
  }
  m_nbParticles = n;
  m_initialised = false;
}

void vpSSLParticleFilter::setSeed(long seed)
{
  m_uni = vpUniRand(static_cast<uint64_t>(seed));
  m_gauss = vpGaussRand(1., 0., seed + 7919); // a different stream from m_uni
}

void vpSSLParticleFilter::setProcessNoise(double translationSigma, double rotationSigma)
{
  if (!(translationSigma >= 0) || !(rotationSigma >= 0)) {
    throw vpException(vpException::badValue, "vpSSLParticleFilter::setProcessNoise: sigmas must be >= 0");
  }
  m_transSigma = translationSigma;
  m_rotSigma = rotationSigma;
}

void vpSSLParticleFilter::setRejectedOdometryNoise(double translationSigma, double rotationSigma)
{
  if (!(translationSigma >= 0) || !(rotationSigma >= 0)) {
    throw vpException(vpException::badValue, "vpSSLParticleFilter::setRejectedOdometryNoise: sigmas must be >= 0");
  }
  m_rejectedTransSigma = translationSigma;
  m_rejectedRotSigma = rotationSigma;
}

void vpSSLParticleFilter::setPixelSigma(double sigma)
{
  if (!(sigma > 0)) {
    throw vpException(vpException::badValue, "vpSSLParticleFilter::setPixelSigma: sigma must be > 0");
  }
  m_pixelSigma = sigma;
}

void vpSSLParticleFilter::setMaxOdometryStep(double translation, double rotation)
{
  if (!(translation > 0) || !(rotation > 0)) {
    throw vpException(vpException::badValue, "vpSSLParticleFilter::setMaxOdometryStep: limits must be > 0");
  }
  m_maxOdoTranslation = translation;
  m_maxOdoRotation = rotation;
}

void vpSSLParticleFilter::checkInitialised(const char *where) const
{
  if (!m_initialised) {
    throw vpException(vpException::notInitialized, "vpSSLParticleFilter::%s: call init() first", where);
  }
}

void vpSSLParticleFilter::init(const std::vector<vpSSLPoseHypothesis> &hypotheses)
{
  if (hypotheses.empty()) {
    throw vpException(vpException::badValue, "vpSSLParticleFilter::init: no pose hypothesis");
  }
  double total = 0;
  for (size_t k = 0; k < hypotheses.size(); ++k) {
    const vpSSLPoseHypothesis &h = hypotheses[k];
    if (!isRigid(h.cMo) || !(h.weight > 0) || !std::isfinite(h.weight) || !(h.positionSigma >= 0) ||
        !std::isfinite(h.depthSigma) || !(h.rotationSigma >= 0)) {
      std::ostringstream os;
      os << "vpSSLParticleFilter::init: hypothesis " << k
         << ": pose must be a finite rigid motion, weight > 0 and sigmas finite and >= 0";
      throw vpException(vpException::badValue, os.str());
    }
    total += h.weight;
  }
  const unsigned int n = m_nbParticles;
  m_particles.resize(n);
  m_scratch.resize(n);
  m_logWeights.assign(n, -std::log(static_cast<double>(n)));
  m_weights.assign(n, 1. / n);

  // Shares proportional to the weights, assigned deterministically (like systematic resampling).
  size_t k = 0;
  double cumul = hypotheses[0].weight / total;
  for (unsigned int i = 0; i < n; ++i) {
    const double u = (i + 0.5) / n;
    while (u > cumul && k + 1 < hypotheses.size()) {
      ++k;
      cumul += hypotheses[k].weight / total;
    }
    const vpSSLPoseHypothesis &h = hypotheses[k];
    Particle &p = m_particles[i];
    const Eigen::Map<const RowMajor4d> cMo = asEigen(h.cMo);
    const double sz = (h.depthSigma > 0) ? h.depthSigma : h.positionSigma;
    p.t[0] = cMo(0, 3) + h.positionSigma * m_gauss();
    p.t[1] = cMo(1, 3) + h.positionSigma * m_gauss();
    p.t[2] = cMo(2, 3) + sz * m_gauss();
    Quat q(p.q);
    if (h.orientationKnown) {
      Eigen::Quaterniond q0(Eigen::Matrix3d(cMo.topLeftCorner<3, 3>()));
      q0.normalize();
      Eigen::Vector3d r;
      for (int j = 0; j < 3; ++j) {
        r[j] = h.rotationSigma * m_gauss();
      }
      q = rotationVectorToQuaternion(r) * q0;
    } else {
      // Uniform rotation (Shoemake 1992), then turned to face the camera: the printed side is seen.
      const double u1 = m_uni(), u2 = 2 * M_PI * m_uni(), u3 = 2 * M_PI * m_uni();
      const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
      const Eigen::Quaterniond qu(b * std::cos(u3), a * std::sin(u2), a * std::cos(u2), b * std::sin(u3));
      // Target Z points into the sheet: facing means it points away from the camera (along p.t).
      if (qu.toRotationMatrix().col(2).dot(ConstVec3(p.t)) < 0) {
        const Eigen::Quaterniond flip(0., 1., 0., 0.); // half turn about the target X axis
        q = qu * flip;
      } else {
        q = qu;
      }
    }
    q.normalize();
  }
  m_initialised = true;
  m_nbResamplings = 0;
  updateEstimate();
}

void vpSSLParticleFilter::addProcessNoise(Particle &p)
{
  for (int j = 0; j < 3; ++j) {
    p.t[j] += m_transSigma * m_gauss();
  }
  if (m_rotSigma > 0) {
    Eigen::Vector3d r;
    for (int j = 0; j < 3; ++j) {
      r[j] = m_rotSigma * m_gauss();
    }
    Quat q(p.q);
    q = (rotationVectorToQuaternion(r) * q).normalized();
  }
}

void vpSSLParticleFilter::predict()
{
  checkInitialised("predict");
  for (Particle &p : m_particles) {
    addProcessNoise(p);
  }
  updateEstimate();
}

bool vpSSLParticleFilter::predict(const vpHomogeneousMatrix &v1Mv2, const vpHomogeneousMatrix &cMv)
{
  checkInitialised("predict");
  if (!isRigid(cMv)) {
    throw vpException(vpException::badValue,
                      "vpSSLParticleFilter::predict: the camera mounting cMv is not a finite rigid motion");
  }
  bool accepted = isRigid(v1Mv2);
  if (accepted) {
    const Eigen::Map<const RowMajor4d> E = asEigen(v1Mv2);
    const double tn = E.topRightCorner<3, 1>().norm();
    const double angle = std::acos(std::max(-1., std::min(1., 0.5 * (E.topLeftCorner<3, 3>().trace() - 1))));
    accepted = tn <= m_maxOdoTranslation && angle <= m_maxOdoRotation;
  }
  if (!accepted) {
    // The camera moved by an unknown amount: each particle gets its own random camera displacement, which
    // turns the target position about the camera together with its orientation (not independent noise).
    for (Particle &p : m_particles) {
      Eigen::Vector3d r;
      for (int i = 0; i < 3; ++i) {
        r[i] = m_rejectedRotSigma * m_gauss();
      }
      const Eigen::Quaterniond dq = rotationVectorToQuaternion(r);
      const Eigen::Matrix3d dR = dq.toRotationMatrix();
      Vec3 t(p.t);
      Eigen::Vector3d moved;
      for (int i = 0; i < 3; ++i) {
        moved[i] = dR.row(i).dot(t) + m_rejectedTransSigma * m_gauss();
      }
      t = moved;
      Quat q(p.q);
      q = (dq * q).normalized();
    }
    predict();
    return false;
  }
  // Camera displacement c1Mc2 = cMv v1Mv2 vMc; the target moves by its inverse c2Mc1 (paper: Rv^T, -Rv^T t).
  const Eigen::Isometry3d cMv_ = toIsometry(cMv);
  const Eigen::Isometry3d c2Mc1 = (cMv_ * toIsometry(v1Mv2) * cMv_.inverse(Eigen::Isometry)).inverse(Eigen::Isometry);
  Eigen::Quaterniond q21(c2Mc1.linear());
  q21.normalize();
  for (Particle &p : m_particles) {
    Vec3 t(p.t);
    t = c2Mc1 * Eigen::Vector3d(t);
    Quat q(p.q);
    q = q21 * q;
    addProcessNoise(p);
  }
  updateEstimate();
  return true;
}

double vpSSLParticleFilter::logLikelihood(const Particle &p, const std::vector<vpSSLObservation> &observations)
{
  const double px = m_cam.get_px(), py = m_cam.get_py(), u0 = m_cam.get_u0(), v0 = m_cam.get_v0();
  const Eigen::Matrix3d R = ConstQuat(p.q).toRotationMatrix();
  const size_t nl = m_landmarks.size() / 4;
  for (size_t j = 0; j < nl; ++j) {
    const double *L = &m_landmarks[4 * j];
    const Eigen::Vector3d c = R * ConstVec3(L) + ConstVec3(p.t);
    const double X = c[0], Y = c[1], Z = c[2];
    double *P = &m_proj[4 * j];
    P[3] = (Z > 1e-3) ? 1. : 0.; // behind or at the camera: cannot be seen
    if (P[3] > 0) {
      P[0] = u0 + px * X / Z;
      P[1] = v0 + py * Y / Z;
      P[2] = px * L[3] / Z; // apparent radius, paper Eq. 6
    }
  }
  double d = 0, dr = 0;
  for (const vpSSLObservation &o : observations) {
    int best = -1;
    double bestD2 = std::numeric_limits<double>::max();
    if (o.label >= 0) {
      if (m_proj[4 * o.label + 3] > 0) {
        best = o.label;
        const double du = m_proj[4 * best] - o.u, dv = m_proj[4 * best + 1] - o.v;
        bestD2 = du * du + dv * dv;
      }
    } else {
      for (size_t j = 0; j < nl; ++j) {
        if (m_proj[4 * j + 3] > 0) {
          const double du = m_proj[4 * j] - o.u, dv = m_proj[4 * j + 1] - o.v;
          const double d2 = du * du + dv * dv;
          if (d2 < bestD2) {
            bestD2 = d2;
            best = static_cast<int>(j);
          }
        }
      }
    }
    if (best < 0) {
      d += kMissingDistance;
      continue;
    }
    d += std::min(std::sqrt(bestD2), kMissingDistance);
    if (o.radius > 0 && m_radiusSigma > 0) {
      dr += std::min(std::fabs(m_proj[4 * best + 2] - o.radius), kMissingDistance);
    }
  }
  // Paper: P(Z|X) ~ G(0, Sigma_1) on the summed distance d; the radii add their own Gaussian.
  double ll = -0.5 * (d / m_pixelSigma) * (d / m_pixelSigma);
  if (m_radiusSigma > 0) {
    ll -= 0.5 * (dr / m_radiusSigma) * (dr / m_radiusSigma);
  }
  return ll;
}

vpSSLParticleFilter::vpUpdateStatus vpSSLParticleFilter::update(const std::vector<vpSSLObservation> &observations,
                                                                const std::vector<vpSSLPoseHypothesis> &recovery)
{
  checkInitialised("update");
  const int nl = static_cast<int>(m_landmarks.size() / 4);
  for (size_t i = 0; i < observations.size(); ++i) {
    const vpSSLObservation &o = observations[i];
    if (o.label < -1 || o.label >= nl || !std::isfinite(o.u) || !std::isfinite(o.v) || !std::isfinite(o.radius)) {
      std::ostringstream os;
      os << "vpSSLParticleFilter::update: observation " << i << ": label must be -1 or in [0, " << nl - 1
         << "] and u, v, radius finite (got label " << o.label << ", u " << o.u << ", v " << o.v << ", radius "
         << o.radius << ")";
      throw vpException(vpException::badValue, os.str());
    }
  }
  if (observations.empty()) {
    return NO_OBSERVATION;
  }
  // The likelihoods go to m_scratch-free storage: m_weights holds them until we know the update is applied.
  double maxLl = -std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < m_particles.size(); ++i) {
    m_weights[i] = logLikelihood(m_particles[i], observations);
    maxLl = std::max(maxLl, m_weights[i]);
  }
  if (!(maxLl >= m_hopelessLogLikelihood)) {
    if (!recovery.empty()) {
      init(recovery);
      return REINITIALISED;
    }
    normaliseWeights(); // restores m_weights from the untouched log-weights
    return HOPELESS_KEPT;
  }
  for (size_t i = 0; i < m_particles.size(); ++i) {
    m_logWeights[i] += m_weights[i];
  }
  normaliseWeights();
  if (m_ess < m_resampleFraction * m_particles.size()) {
    resample();
  }
  updateEstimate();
  return UPDATED;
}

void vpSSLParticleFilter::normaliseWeights()
{
  const size_t n = m_logWeights.size();
  const double m = *std::max_element(m_logWeights.begin(), m_logWeights.end());
  double sum = 0;
  for (size_t i = 0; i < n; ++i) {
    // Clamped so that exp() never underflows to 0 and log(w) stays finite: a particle keeps a tiny weight.
    m_logWeights[i] = std::max(m_logWeights[i] - m, -700.);
    m_weights[i] = std::exp(m_logWeights[i]);
    sum += m_weights[i];
  }
  const double logSum = std::log(sum);
  double sum2 = 0;
  for (size_t i = 0; i < n; ++i) {
    m_weights[i] /= sum;
    m_logWeights[i] -= logSum;
    sum2 += m_weights[i] * m_weights[i];
  }
  m_ess = 1. / sum2;
}

void vpSSLParticleFilter::resample()
{
  const size_t n = m_particles.size();
  // Regularised resampling (Musso et al., 2001): copies are jittered by a kernel shaped like the weighted
  // covariance, so that a few heavy particles do not collapse the cloud onto a biased point.
  double L[36] = {0};
  bool jitter = m_regularisation > 0;
  if (jitter) {
    updateEstimate();
    const double h2 = m_regularisation * m_regularisation;
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j <= i; ++j) {
        double sum = h2 * m_covariance[i][j] + (i == j ? 1e-12 : 0.);
        for (int k = 0; k < j; ++k) {
          sum -= L[i * 6 + k] * L[j * 6 + k];
        }
        if (i == j) {
          if (!(sum > 0)) {
            jitter = false;
            break;
          }
          L[i * 6 + i] = std::sqrt(sum);
        } else {
          L[i * 6 + j] = sum / L[j * 6 + j];
        }
      }
      if (!jitter) {
        break;
      }
    }
  }
  const double step = 1. / n;
  double u = m_uni() * step;
  double cumul = m_weights[0];
  size_t j = 0;
  for (size_t i = 0; i < n; ++i) {
    while (u > cumul && j + 1 < n) {
      ++j;
      cumul += m_weights[j];
    }
    m_scratch[i] = m_particles[j];
    u += step;
  }
  m_particles.swap(m_scratch);
  if (jitter) {
    for (Particle &p : m_particles) {
      double g[6], e[6] = {0, 0, 0, 0, 0, 0};
      for (int i = 0; i < 6; ++i) {
        g[i] = m_gauss();
        for (int k = 0; k <= i; ++k) {
          e[i] += L[i * 6 + k] * g[k];
        }
      }
      for (int i = 0; i < 3; ++i) {
        p.t[i] += e[i];
      }
      Quat q(p.q);
      q = (rotationVectorToQuaternion(ConstVec3(e + 3)) * q).normalized();
    }
  }
  std::fill(m_weights.begin(), m_weights.end(), step);
  std::fill(m_logWeights.begin(), m_logWeights.end(), -std::log(static_cast<double>(n)));
  m_ess = static_cast<double>(n);
  ++m_nbResamplings;
}

void vpSSLParticleFilter::updateEstimate()
{
  const size_t n = m_particles.size();
  double t[3] = {0, 0, 0}, sum2 = 0;
  Eigen::Matrix4d M = Eigen::Matrix4d::Zero();
  size_t best = 0;
  for (size_t i = 0; i < n; ++i) {
    const Particle &p = m_particles[i];
    const double w = m_weights[i];
    sum2 += w * w;
    if (w > m_weights[best]) {
      best = i;
    }
    for (int a = 0; a < 3; ++a) {
      t[a] += w * p.t[a];
    }
    const Eigen::Map<const Eigen::Vector4d> qi(p.q);
    M.noalias() += w * qi * qi.transpose();
  }
  m_ess = 1. / sum2;
  const Eigen::Quaterniond qm = dominantQuaternion(M);
  setPose(m_meanPose, t, qm.coeffs().data());
  setPose(m_bestPose, m_particles[best].t, m_particles[best].q);

  const Eigen::Quaterniond qmInv = qm.conjugate();
  double C[36] = {0};
  for (size_t i = 0; i < n; ++i) {
    const Particle &p = m_particles[i];
    double e[6];
    for (int a = 0; a < 3; ++a) {
      e[a] = p.t[a] - t[a];
    }
    Vec3(e + 3) = quaternionToRotationVector(ConstQuat(p.q) * qmInv); // R_i R_mean^T, camera frame
    for (int a = 0; a < 6; ++a) {
      for (int b = 0; b < 6; ++b) {
        C[a * 6 + b] += m_weights[i] * e[a] * e[b];
      }
    }
  }
  for (unsigned int a = 0; a < 6; ++a) {
    for (unsigned int b = 0; b < 6; ++b) {
      m_covariance[a][b] = C[a * 6 + b];
    }
  }
  m_converged = std::sqrt(C[0] + C[7] + C[14]) < m_convergenceSpread;
}

vpHomogeneousMatrix vpSSLParticleFilter::getParticlePose(unsigned int i) const
{
  if (i >= m_particles.size()) {
    throw vpException(vpException::badValue, "vpSSLParticleFilter::getParticlePose: index %u out of range [0, %u)", i,
                      static_cast<unsigned int>(m_particles.size()));
  }
  vpHomogeneousMatrix M;
  setPose(M, m_particles[i].t, m_particles[i].q);
  return M;
}

double vpSSLParticleFilter::getParticleWeight(unsigned int i) const
{
  if (i >= m_weights.size()) {
    throw vpException(vpException::badValue, "vpSSLParticleFilter::getParticleWeight: index %u out of range [0, %u)", i,
                      static_cast<unsigned int>(m_weights.size()));
  }
  return m_weights[i];
}

vpQuaternionVector vpSSLParticleFilter::meanQuaternion(const std::vector<vpQuaternionVector> &q,
                                                       const std::vector<double> &w)
{
  if (q.empty() || q.size() != w.size()) {
    throw vpException(vpException::dimensionError,
                      "vpSSLParticleFilter::meanQuaternion: need as many weights as quaternions, at least one");
  }
  Eigen::Matrix4d M = Eigen::Matrix4d::Zero();
  double total = 0;
  for (size_t i = 0; i < q.size(); ++i) {
    const Eigen::Vector4d v = Eigen::Vector4d(q[i].x(), q[i].y(), q[i].z(), q[i].w()).normalized();
    M.noalias() += w[i] * v * v.transpose();
    total += w[i];
  }
  if (!(total > 0)) {
    throw vpException(vpException::badValue, "vpSSLParticleFilter::meanQuaternion: the weights must sum to > 0");
  }
  const Eigen::Quaterniond m = dominantQuaternion(M);
  return vpQuaternionVector(m.x(), m.y(), m.z(), m.w());
}
