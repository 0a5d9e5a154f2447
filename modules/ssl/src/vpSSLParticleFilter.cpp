/*!
  \file vpSSLParticleFilter.cpp
  \brief Particle filter on the target pose (paper Sec. 3.3).
*/
#include <visp3/ssl/vpSSLParticleFilter.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <visp3/core/vpException.h>
#include <visp3/core/vpMath.h>

namespace {
// Quaternions here are (w, x, y, z); rotation matrices row-major double[9].
void qMul(const double a[4], const double b[4], double out[4])
{
  const double w = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
  const double x = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
  const double y = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
  const double z = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
  out[0] = w;
  out[1] = x;
  out[2] = y;
  out[3] = z;
}

void qNormalise(double q[4])
{
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (int i = 0; i < 4; ++i) {
    q[i] /= n;
  }
}

void qToRot(const double q[4], double R[9])
{
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  R[0] = 1 - 2 * (y * y + z * z);
  R[1] = 2 * (x * y - w * z);
  R[2] = 2 * (x * z + w * y);
  R[3] = 2 * (x * y + w * z);
  R[4] = 1 - 2 * (x * x + z * z);
  R[5] = 2 * (y * z - w * x);
  R[6] = 2 * (x * z - w * y);
  R[7] = 2 * (y * z + w * x);
  R[8] = 1 - 2 * (x * x + y * y);
}

// Shepperd's method: picks the largest of the four squared components to stay well conditioned.
void rotToQ(const double R[9], double q[4])
{
  const double tr = R[0] + R[4] + R[8];
  if (tr > 0) {
    const double s = 2 * std::sqrt(tr + 1);
    q[0] = 0.25 * s;
    q[1] = (R[7] - R[5]) / s;
    q[2] = (R[2] - R[6]) / s;
    q[3] = (R[3] - R[1]) / s;
  } else if (R[0] > R[4] && R[0] > R[8]) {
    const double s = 2 * std::sqrt(1 + R[0] - R[4] - R[8]);
    q[0] = (R[7] - R[5]) / s;
    q[1] = 0.25 * s;
    q[2] = (R[1] + R[3]) / s;
    q[3] = (R[2] + R[6]) / s;
  } else if (R[4] > R[8]) {
    const double s = 2 * std::sqrt(1 + R[4] - R[0] - R[8]);
    q[0] = (R[2] - R[6]) / s;
    q[1] = (R[1] + R[3]) / s;
    q[2] = 0.25 * s;
    q[3] = (R[5] + R[7]) / s;
  } else {
    const double s = 2 * std::sqrt(1 + R[8] - R[0] - R[4]);
    q[0] = (R[3] - R[1]) / s;
    q[1] = (R[2] + R[6]) / s;
    q[2] = (R[5] + R[7]) / s;
    q[3] = 0.25 * s;
  }
  qNormalise(q);
}

void rotVecToQ(const double r[3], double q[4])
{
  const double a = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
  q[0] = std::cos(0.5 * a);
  const double s = (a < 1e-12) ? 0.5 : std::sin(0.5 * a) / a; // sin(a/2)/a -> 1/2 as a -> 0
  q[1] = s * r[0];
  q[2] = s * r[1];
  q[3] = s * r[2];
}

void qToRotVec(const double qIn[4], double r[3])
{
  const double sgn = (qIn[0] < 0) ? -1. : 1.; // q and -q: take the rotation of angle <= pi
  const double w = sgn * qIn[0];
  const double n = std::sqrt(qIn[1] * qIn[1] + qIn[2] * qIn[2] + qIn[3] * qIn[3]);
  const double a = 2 * std::atan2(n, w);
  const double s = (n < 1e-12) ? 2. : a / n;
  for (int i = 0; i < 3; ++i) {
    r[i] = sgn * s * qIn[i + 1];
  }
}

// Eigenvector of the largest eigenvalue of a symmetric 4x4 matrix (cyclic Jacobi, allocation free).
void dominantEigenvector4(const double Min[16], double v[4])
{
  double A[16], V[16];
  for (int i = 0; i < 16; ++i) {
    A[i] = Min[i];
    V[i] = (i % 5 == 0) ? 1. : 0.;
  }
  for (int sweep = 0; sweep < 50; ++sweep) {
    double off = 0, diag = 0;
    for (int p = 0; p < 4; ++p) {
      diag += A[p * 5] * A[p * 5];
      for (int q = p + 1; q < 4; ++q) {
        off += A[p * 4 + q] * A[p * 4 + q];
      }
    }
    if (off <= 1e-30 * (diag + 1e-300)) {
      break;
    }
    for (int p = 0; p < 3; ++p) {
      for (int q = p + 1; q < 4; ++q) {
        const double apq = A[p * 4 + q];
        if (std::fabs(apq) < 1e-300) {
          continue;
        }
        const double theta = (A[q * 5] - A[p * 5]) / (2 * apq);
        const double t = ((theta >= 0) ? 1. : -1.) / (std::fabs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (int k = 0; k < 4; ++k) { // A <- A J
          const double akp = A[k * 4 + p], akq = A[k * 4 + q];
          A[k * 4 + p] = c * akp - s * akq;
          A[k * 4 + q] = s * akp + c * akq;
        }
        for (int k = 0; k < 4; ++k) { // A <- J^T A
          const double apk = A[p * 4 + k], aqk = A[q * 4 + k];
          A[p * 4 + k] = c * apk - s * aqk;
          A[q * 4 + k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 4; ++k) { // V <- V J
          const double vkp = V[k * 4 + p], vkq = V[k * 4 + q];
          V[k * 4 + p] = c * vkp - s * vkq;
          V[k * 4 + q] = s * vkp + c * vkq;
        }
      }
    }
  }
  int best = 0;
  for (int i = 1; i < 4; ++i) {
    if (A[i * 5] > A[best * 5]) {
      best = i;
    }
  }
  for (int k = 0; k < 4; ++k) {
    v[k] = V[k * 4 + best];
  }
  if (v[0] < 0) { // sign is arbitrary; w >= 0 keeps the output stable
    for (int k = 0; k < 4; ++k) {
      v[k] = -v[k];
    }
  }
  qNormalise(v);
}

bool allFinite(const vpHomogeneousMatrix &M)
{
  for (unsigned int i = 0; i < 4; ++i) {
    for (unsigned int j = 0; j < 4; ++j) {
      if (!std::isfinite(M[i][j])) {
        return false;
      }
    }
  }
  return true;
}

// A rigid motion: finite, orthonormal rotation with det +1, last row (0 0 0 1).
bool isRigid(const vpHomogeneousMatrix &M)
{
  if (!allFinite(M)) {
    return false;
  }
  for (unsigned int i = 0; i < 3; ++i) {
    for (unsigned int j = 0; j < 3; ++j) {
      double d = 0;
      for (unsigned int k = 0; k < 3; ++k) {
        d += M[k][i] * M[k][j];
      }
      if (std::fabs(d - (i == j ? 1. : 0.)) > 1e-6) {
        return false;
      }
    }
  }
  const double det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
                     M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                     M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
  return det > 0 && std::fabs(M[3][0]) + std::fabs(M[3][1]) + std::fabs(M[3][2]) + std::fabs(M[3][3] - 1) < 1e-9;
}

// Flat copies: composing vpHomogeneousMatrix objects would allocate at every prediction.
void toArray(const vpHomogeneousMatrix &M, double R[9], double t[3])
{
  for (unsigned int i = 0; i < 3; ++i) {
    for (unsigned int j = 0; j < 3; ++j) {
      R[i * 3 + j] = M[i][j];
    }
    t[i] = M[i][3];
  }
}

// (Ra, ta) * (Rb, tb)
void compose(const double Ra[9], const double ta[3], const double Rb[9], const double tb[3], double R[9], double t[3])
{
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      R[i * 3 + j] = Ra[i * 3] * Rb[j] + Ra[i * 3 + 1] * Rb[3 + j] + Ra[i * 3 + 2] * Rb[6 + j];
    }
    t[i] = Ra[i * 3] * tb[0] + Ra[i * 3 + 1] * tb[1] + Ra[i * 3 + 2] * tb[2] + ta[i];
  }
}

void invert(const double R[9], const double t[3], double Ri[9], double ti[3])
{
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      Ri[i * 3 + j] = R[j * 3 + i];
    }
  }
  for (int i = 0; i < 3; ++i) {
    ti[i] = -(Ri[i * 3] * t[0] + Ri[i * 3 + 1] * t[1] + Ri[i * 3 + 2] * t[2]);
  }
}

void setPose(vpHomogeneousMatrix &M, const double t[3], const double q[4])
{
  double R[9];
  qToRot(q, R);
  for (unsigned int i = 0; i < 3; ++i) {
    for (unsigned int j = 0; j < 3; ++j) {
      M[i][j] = R[i * 3 + j];
    }
    M[i][3] = t[i];
  }
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
    double R[9], t[3];
    toArray(h.cMo, R, t);
    const double sz = (h.depthSigma > 0) ? h.depthSigma : h.positionSigma;
    p.t[0] = t[0] + h.positionSigma * m_gauss();
    p.t[1] = t[1] + h.positionSigma * m_gauss();
    p.t[2] = t[2] + sz * m_gauss();
    if (h.orientationKnown) {
      double q0[4], r[3], dq[4];
      rotToQ(R, q0);
      for (int j = 0; j < 3; ++j) {
        r[j] = h.rotationSigma * m_gauss();
      }
      rotVecToQ(r, dq);
      qMul(dq, q0, p.q);
    } else {
      // Uniform rotation (Shoemake 1992), then turned to face the camera: the printed side is seen.
      const double u1 = m_uni(), u2 = 2 * M_PI * m_uni(), u3 = 2 * M_PI * m_uni();
      const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
      double q[4] = {b * std::cos(u3), a * std::sin(u2), a * std::cos(u2), b * std::sin(u3)};
      double Rq[9];
      qToRot(q, Rq);
      // Target Z points into the sheet: facing means it points away from the camera (along p.t).
      if (Rq[2] * p.t[0] + Rq[5] * p.t[1] + Rq[8] * p.t[2] < 0) {
        const double flip[4] = {0., 1., 0., 0.}; // half turn about the target X axis
        qMul(q, flip, p.q);
      } else {
        std::copy(q, q + 4, p.q);
      }
    }
    qNormalise(p.q);
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
    double r[3], dq[4], q[4];
    for (int j = 0; j < 3; ++j) {
      r[j] = m_rotSigma * m_gauss();
    }
    rotVecToQ(r, dq);
    qMul(dq, p.q, q);
    qNormalise(q);
    std::copy(q, q + 4, p.q);
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
    double Rv[9], tv[3];
    toArray(v1Mv2, Rv, tv);
    const double tn = std::sqrt(tv[0] * tv[0] + tv[1] * tv[1] + tv[2] * tv[2]);
    const double angle = std::acos(std::max(-1., std::min(1., 0.5 * (Rv[0] + Rv[4] + Rv[8] - 1))));
    accepted = tn <= m_maxOdoTranslation && angle <= m_maxOdoRotation;
  }
  if (!accepted) {
    // The camera moved by an unknown amount: each particle gets its own random camera displacement, which
    // turns the target position about the camera together with its orientation (not independent noise).
    for (Particle &p : m_particles) {
      double r[3], dq[4], dR[9], t[3], q[4];
      for (int i = 0; i < 3; ++i) {
        r[i] = m_rejectedRotSigma * m_gauss();
      }
      rotVecToQ(r, dq);
      qToRot(dq, dR);
      for (int i = 0; i < 3; ++i) {
        t[i] = dR[i * 3] * p.t[0] + dR[i * 3 + 1] * p.t[1] + dR[i * 3 + 2] * p.t[2] + m_rejectedTransSigma * m_gauss();
      }
      std::copy(t, t + 3, p.t);
      qMul(dq, p.q, q);
      qNormalise(q);
      std::copy(q, q + 4, p.q);
    }
    predict();
    return false;
  }
  // Camera displacement c1Mc2 = cMv v1Mv2 vMc; the target moves by its inverse c2Mc1 (paper: Rv^T, -Rv^T t).
  double Rcv[9], tcv[3], Rvc[9], tvc[3], Rv[9], tv[3], Ra[9], ta[3], R12[9], t12[3], R21[9], t21[3], q21[4];
  toArray(cMv, Rcv, tcv);
  invert(Rcv, tcv, Rvc, tvc);
  toArray(v1Mv2, Rv, tv);
  compose(Rcv, tcv, Rv, tv, Ra, ta);
  compose(Ra, ta, Rvc, tvc, R12, t12);
  invert(R12, t12, R21, t21);
  rotToQ(R21, q21);
  for (Particle &p : m_particles) {
    double t[3], q[4];
    for (int i = 0; i < 3; ++i) {
      t[i] = R21[i * 3] * p.t[0] + R21[i * 3 + 1] * p.t[1] + R21[i * 3 + 2] * p.t[2] + t21[i];
    }
    std::copy(t, t + 3, p.t);
    qMul(q21, p.q, q);
    std::copy(q, q + 4, p.q);
    addProcessNoise(p);
  }
  updateEstimate();
  return true;
}

double vpSSLParticleFilter::logLikelihood(const Particle &p, const std::vector<vpSSLObservation> &observations)
{
  const double px = m_cam.get_px(), py = m_cam.get_py(), u0 = m_cam.get_u0(), v0 = m_cam.get_v0();
  double R[9];
  qToRot(p.q, R);
  const size_t nl = m_landmarks.size() / 4;
  for (size_t j = 0; j < nl; ++j) {
    const double *L = &m_landmarks[4 * j];
    const double X = R[0] * L[0] + R[1] * L[1] + R[2] * L[2] + p.t[0];
    const double Y = R[3] * L[0] + R[4] * L[1] + R[5] * L[2] + p.t[1];
    const double Z = R[6] * L[0] + R[7] * L[1] + R[8] * L[2] + p.t[2];
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
      double g[6], e[6] = {0, 0, 0, 0, 0, 0}, dq[4], q[4];
      for (int i = 0; i < 6; ++i) {
        g[i] = m_gauss();
        for (int k = 0; k <= i; ++k) {
          e[i] += L[i * 6 + k] * g[k];
        }
      }
      for (int i = 0; i < 3; ++i) {
        p.t[i] += e[i];
      }
      rotVecToQ(e + 3, dq);
      qMul(dq, p.q, q);
      qNormalise(q);
      std::copy(q, q + 4, p.q);
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
  double t[3] = {0, 0, 0}, M[16] = {0}, sum2 = 0;
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
    for (int a = 0; a < 4; ++a) {
      for (int b = 0; b < 4; ++b) {
        M[a * 4 + b] += w * p.q[a] * p.q[b];
      }
    }
  }
  m_ess = 1. / sum2;
  double qm[4];
  dominantEigenvector4(M, qm);
  setPose(m_meanPose, t, qm);
  setPose(m_bestPose, m_particles[best].t, m_particles[best].q);

  const double qmInv[4] = {qm[0], -qm[1], -qm[2], -qm[3]};
  double C[36] = {0};
  for (size_t i = 0; i < n; ++i) {
    const Particle &p = m_particles[i];
    double e[6], dq[4];
    for (int a = 0; a < 3; ++a) {
      e[a] = p.t[a] - t[a];
    }
    qMul(p.q, qmInv, dq); // R_i R_mean^T, camera frame
    qToRotVec(dq, e + 3);
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
  double M[16] = {0}, total = 0;
  for (size_t i = 0; i < q.size(); ++i) {
    double v[4] = {q[i].w(), q[i].x(), q[i].y(), q[i].z()};
    qNormalise(v);
    for (int a = 0; a < 4; ++a) {
      for (int b = 0; b < 4; ++b) {
        M[a * 4 + b] += w[i] * v[a] * v[b];
      }
    }
    total += w[i];
  }
  if (!(total > 0)) {
    throw vpException(vpException::badValue, "vpSSLParticleFilter::meanQuaternion: the weights must sum to > 0");
  }
  double m[4];
  dominantEigenvector4(M, m);
  return vpQuaternionVector(m[1], m[2], m[3], m[0]);
}
