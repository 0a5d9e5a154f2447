#include <visp3/ssl/vpSSLConcentricReader.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include <visp3/core/vpException.h>

#include "vpSSLImageCheck.h"
#include "vpSSLSymmetryKernel.h"

namespace {
// Profile bins per period of the rings (a factor 1 / p of radius).
const int kBinsPerPeriod = 24;
// Rays of the radial profile (kRays / 8 per sector).
const int kRays = 64;
// The fit's disc grows by this factor per step, from kFirstRadius px.
const double kGrowth = 1.25;
const double kFirstRadius = 6.;
// Side of the grid of gradient samples over the disc (points): fine once the rings lock the fit, coarse before.
const double kFineGrid = 32.;
const double kCoarseGrid = 16.;
// The same on the box average, whose neighbouring gradients share most of their pixels.
const double kSmoothGrid = 12.;
// Smallest disc (px) whose gradients are taken on the 3x3 box average first (read()), and the share of its disc
// that the fit on the image's own gradients must reach to replace it.
const double kSmoothRadius = 10.;
const double kRawDisc = 0.75;
// Largest disc searched for the rings' concentric structure when none has been seen yet (px): the innermost ring a
// blur of sigma 4 px leaves readable lies at about 35 px.
const double kLockRadius = 48.;
// A fit explaining this share of the gradient energy is a landmark's rings; the disc stops growing once the share
// falls below kKeepShare of the best one (it has reached clutter, the sheet's edge or a neighbour).
const double kLocked = 0.8;
const double kKeepShare = 0.9;
const double kMinKept = 0.75;
// Narrowest ring whose phase is read (px).
const double kMinRingWidth = 1.2;
// Smallest ring contrast (grey levels) read, and the share of it that each direction's outer pair must show.
const double kMinContrast = 4.;
const double kSectorShare = 0.5;
// Share of the directions in view whose outer pair must show the contrast.
const double kSectorsNeeded = 0.75;
// How much lighter than the next black ring the outer one may be, relative to the contrast (same ink).
const double kInkTolerance = 0.35;
// Share of the contrast by which the white ring must be lighter than the black ring inside it. Only a tenth: an
// exposure that saturates the brightest colour channels on the paper (a blue-green cast) keeps the contrast of a
// ring only where the blur leaves it darker than saturation, and the narrower inner black ring, blurred towards the
// white around it, keeps much less than the outer one (a tenth of the outer pair's contrast on a B of 16 px blurred
// by 1.4 px in the independent corpus).
const double kInnerShare = 0.1;
// Largest axis ratio of the ellipses read (a landmark seen up to 78 degrees off its normal) and smallest semi-axis
// (px).
const double kMaxAxisRatio = 5.;
const double kMinMinorRadius = 2.5;
// Largest distance (in periods) of a printed edge from where the inner rings' phase puts it.
const double kEdgeWindow = 0.16;
// Smallest correlation of the resolved rings' profile with the square wave s_p.
const double kMinSimilarity = 0.5;
// A profile is that of equal rings when their best square wave in linear radius (pair period from two narrowest
// rings to R) correlates with it by kEqualRingMargin more than s_p does, and the rings in [0.2 R, 0.5 R) keep
// kInnerSpread of the contrast (standard deviation) of those in [0.5 R, R): blur greys a landmark's inner rings,
// which are narrower, but not a bull's-eye's. The wave's phase and duty are read in kFoldBins steps of a period.
const double kEqualRingMargin = 0.15;
const double kInnerSpread = 0.9;
const double kPeriodGrowth = 1.04;
const int kFoldBins = 20;
// How much lighter than its inner part the outer part of the outer ring may be, relative to the contrast.
const double kSolidShare = 0.5;
// Alternating ring pairs needed, counted inwards from the outer ring.
const int kMinPairs = 2;
// The blurred-ring model (setBlurredRingModel()): blur sigmas tried (px), the copy's edge moved by up to
// kModelShifts steps of kModelShift periods about the phase's, and what a copy must reach to be read.
const double kModelSigmas[] = {0.4, 0.7, 1., 1.4, 2., 2.8, 4.};
const int kModelShifts = 4;
const double kModelShift = 0.025;
const double kModelCorrelation = 0.945;
const double kModelDiscMargin = 0.1;
const double kModelSectorCorrelation = 0.3;
const double kModelSectorShare = 0.75;
const double kModelMinRadius = 8.;
const double kModelSnr = 2.;
// readAt(): the largest move of the given centre by the symmetry centring, in minor semi-axes.
const double kShapedShift = 0.35;
// readAt(): the outer ring read lies within this factor of the one given (either way).
const double kShapedSize = 0.7;

// The rings' radial profile at rho, blurred by a Gaussian of sigma (same units): white paper (1) outside the outer
// radius R, then each printed edge inwards a blurred step, down at R, up at R sqrt(p), down at R p, ... (edgeRatio =
// sqrt(p)), down to edges under a fifth of sigma, which the blur has merged.
double blurredRings(double rho, double R, double sigma, double edgeRatio)
{
  double m = 1., edge = R;
  for (int j = 0; j < 64 && edge > 0.2 * sigma; ++j, edge *= edgeRatio) {
    m += (j % 2 == 0 ? -0.5 : 0.5) * std::erfc((rho - edge) / (M_SQRT2 * sigma));
  }
  return m;
}
// Smallest inner disc (px, R p^2) whose own fit gives the centre, and the largest move of the centre it may make
// (share of that disc).
const double kMinInnerDisc = 8.;
const double kInnerShift = 0.1;
// Sobel gradient of the 3x3 box average at (u, v), 2 px or more inside the image: the 5x5 kernel smooths by
// [1 3 4 3 1] across the derivative [-1 -1 0 1 1]. In integers: every partial sum is exact (under 10^4).
void smoothedGradient(const vpImage<unsigned char> &I, int u, int v, double &gx, double &gy)
{
  int along[5], across[5];
  for (int j = 0; j < 5; ++j) {
    const unsigned char *r = I[v + j - 2] + u - 2;
    along[j] = (r[3] + r[4]) - (r[0] + r[1]);
    across[j] = r[0] + r[4] + 3 * (r[1] + r[3]) + 4 * r[2];
  }
  gx = along[0] + along[4] + 3 * (along[1] + along[3]) + 4 * along[2];
  gy = (across[3] + across[4]) - (across[0] + across[1]);
}

// Directions of the profile's rays, (cos t, sin t) at t = 2 pi (k + 1/2) / kRays: the same for every profile.
struct RayDirections
{
  double c[kRays], s[kRays];
  RayDirections()
  {
    for (int k = 0; k < kRays; ++k) {
      const double t = 2. * M_PI * (k + 0.5) / kRays;
      c[k] = std::cos(t);
      s[k] = std::sin(t);
    }
  }
};
const RayDirections &rayDirections()
{
  static const RayDirections directions;
  return directions;
}
} // namespace

vpSSLConcentricReader::vpSSLConcentricReader()
    : m_p(0.5), m_logStep(std::log(2.)), m_minRadius(4.), m_maxRadius(300.), m_stage(0), m_quality(0.),
      m_similarity(0.), m_profileTauA(0.), m_profileTauR(0.), m_blurredRingModel(false), m_tau0(0.), m_nbBins(0)
{
}

void vpSSLConcentricReader::setP(double p)
{
  if (!(p > 0. && p < 1.)) {
    throw vpException(vpException::badValue, "vpSSLConcentricReader: p %g not in (0, 1)", p);
  }
  m_p = p;
  m_logStep = std::log(1. / p);
}

void vpSSLConcentricReader::setRadiusRange(double minRadius, double maxRadius)
{
  if (!(minRadius > 0. && minRadius < maxRadius)) {
    throw vpException(vpException::badValue, "vpSSLConcentricReader: radius range [%g, %g]", minRadius, maxRadius);
  }
  m_minRadius = minRadius;
  m_maxRadius = maxRadius;
}

bool vpSSLConcentricReader::fit(const vpImage<unsigned char> &I, double radius, int iterations, double gridSide,
                                bool smooth, Fit &f) const
{
  const int W = static_cast<int>(I.getWidth()), H = static_cast<int>(I.getHeight());
  // A few hundred gradients describe the ellipses as well as all of them: the disc is sampled on a grid of about
  // gridSide x gridSide points whatever its size.
  const int stride = std::max(1, static_cast<int>(2. * radius / gridSide));
  for (int iteration = 0; iteration < iterations; ++iteration) {
    const double *q = f.q;
    // Bounding box of the ellipse (x - c)^T Q (x - c) = radius^2 (det Q = 1).
    const double hu = radius * std::sqrt(q[2]), hv = radius * std::sqrt(q[0]);
    const int m = smooth ? 2 : 1; // the gradient's half support
    const int u0 = std::max(m, static_cast<int>(std::ceil(f.u - hu))),
              u1 = std::min(W - 1 - m, static_cast<int>(f.u + hu));
    const int v0 = std::max(m, static_cast<int>(std::ceil(f.v - hv))),
              v1 = std::min(H - 1 - m, static_cast<int>(f.v + hv));
    Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
    Eigen::Matrix2d A = Eigen::Matrix2d::Zero();
    Eigen::Vector2d b = Eigen::Vector2d::Zero();
    double explained = 0., energy = 0.;
    const double r2max = radius * radius;
    for (int v = v0; v <= v1; v += stride) {
      const unsigned char *above = I[v - 1], *row = I[v], *below = I[v + 1];
      for (int u = u0; u <= u1; u += stride) {
        const double y1 = u - f.u, y2 = v - f.v;
        const double n1 = q[0] * y1 + q[1] * y2, n2 = q[1] * y1 + q[2] * y2;
        const double r2 = y1 * n1 + y2 * n2;
        if (r2 > r2max || r2 < 1.) {
          continue;
        }
        // Sobel gradient, of the 3x3 box average on larger discs.
        double gx = 0., gy = 0.;
        if (smooth) {
          smoothedGradient(I, u, v, gx, gy);
        } else {
          gx = (above[u + 1] + 2. * row[u + 1] + below[u + 1]) - (above[u - 1] + 2. * row[u - 1] + below[u - 1]);
          gy = (below[u - 1] + 2. * below[u] + below[u + 1]) - (above[u - 1] + 2. * above[u] + above[u + 1]);
        }
        const double gg = gx * gx + gy * gy;
        if (gg == 0.) {
          continue;
        }
        // The gradient must be parallel to the ellipse's normal Q y: its cross product with Q y is linear in Q's
        // entries (shape, with c fixed) and in c (with Q fixed). Weighted by 1 / |Q y|^2, each residual is the
        // gradient's magnitude times the sine of its angle to the normal.
        const double nn = n1 * n1 + n2 * n2;
        const double w = 1. / nn;
        const Eigen::Vector3d a(-gy * y1, gx * y1 - gy * y2, gx * y2);
        M.noalias() += w * a * a.transpose();
        const double e = gx * n2 - gy * n1;
        const Eigen::Vector2d h(gx * q[1] - gy * q[0], gx * q[2] - gy * q[1]);
        A.noalias() += w * h * h.transpose();
        b.noalias() += w * e * h;
        const double c = gx * n1 + gy * n2;
        explained += c * c * w;
        energy += gg;
      }
    }
    if (!(energy > 0.)) {
      return false;
    }
    f.quality = explained / energy;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(M);
    Eigen::Vector3d s = solver.eigenvectors().col(0);
    if (s(0) < 0.) {
      s = -s;
    }
    const double det = s(0) * s(2) - s(1) * s(1);
    if (!(det > 0.)) {
      return false;
    }
    const double k = 1. / std::sqrt(det);
    // Axis ratio a / b: the trace of Q is (a / b) + (b / a) when its determinant is 1.
    const double tr = (s(0) + s(2)) * k;
    if (tr > kMaxAxisRatio + 1. / kMaxAxisRatio) {
      return false;
    }
    f.q[0] = s(0) * k;
    f.q[1] = s(1) * k;
    f.q[2] = s(2) * k;
    const double detA = A.determinant();
    if (!(std::fabs(detA) > 1e-12 * (A(0, 0) * A(1, 1) + 1e-30))) {
      return false;
    }
    Eigen::Vector2d step = A.inverse() * b;
    const double length = step.norm();
    if (length > 0.3 * radius) {
      step *= 0.3 * radius / length;
    }
    f.u += step(0);
    f.v += step(1);
    if (!(f.u >= 0. && f.v >= 0. && f.u <= W - 1. && f.v <= H - 1.)) {
      return false;
    }
    if (length < 0.01) {
      break;
    }
  }
  return true;
}

bool vpSSLConcentricReader::readProfile(const vpImage<unsigned char> &I, const Fit &f, double tauLow, double tauHigh)
{
  // Rays in the frame where the ellipses are circles: x = c + rho Q^(-1/2) (cos t, sin t).
  Eigen::Matrix2d Q;
  Q << f.q[0], f.q[1], f.q[1], f.q[2];
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(Q);
  const Eigen::Matrix2d S = solver.eigenvectors() * solver.eigenvalues().cwiseInverse().cwiseSqrt().asDiagonal() *
                            solver.eigenvectors().transpose();
  m_tau0 = tauLow;
  m_nbBins = std::min(kMaxBins, static_cast<int>((tauHigh - tauLow) * kBinsPerPeriod) + 1);
  std::fill(&m_sum[0][0], &m_sum[0][0] + kMaxBins * kSectors, 0.f);
  std::fill(&m_count[0][0], &m_count[0][0] + kMaxBins * kSectors, static_cast<unsigned short>(0));
  const double W = I.getWidth() - 1., H = I.getHeight() - 1.;
  // The bins' radii are the same on every ray.
  double *rho = m_rho;
  for (int bin = 0; bin < m_nbBins; ++bin) {
    rho[bin] = std::exp((m_tau0 + (bin + 0.5) / kBinsPerPeriod) * m_logStep);
  }
  const RayDirections &directions = rayDirections();
  for (int k = 0; k < kRays; ++k) {
    const double ct = directions.c[k], st = directions.s[k];
    const double dx = S(0, 0) * ct + S(0, 1) * st;
    const double dy = S(1, 0) * ct + S(1, 1) * st;
    const int sector = k * kSectors / kRays;
    for (int bin = 0; bin < m_nbBins; ++bin) {
      const double x = f.u + rho[bin] * dx, y = f.v + rho[bin] * dy;
      if (!(x >= 0. && y >= 0. && x < W && y < H)) {
        break; // the rest of the ray is out of the image
      }
      const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
      const double fx = x - x0, fy = y - y0;
      const double value = (1. - fy) * ((1. - fx) * I[y0][x0] + fx * I[y0][x0 + 1]) +
                           fy * ((1. - fx) * I[y0 + 1][x0] + fx * I[y0 + 1][x0 + 1]);
      m_sum[bin][sector] += static_cast<float>(value);
      ++m_count[bin][sector];
    }
  }
  return m_nbBins > 0;
}

double vpSSLConcentricReader::band(double tau0, double tau1, int sector) const
{
  // Mean level of the profile over [tau0, tau1) (in periods), in one sector or all (sector < 0); -1 if unseen.
  const int b0 = std::max(0, static_cast<int>(std::ceil((tau0 - m_tau0) * kBinsPerPeriod - 0.5)));
  const int b1 = std::min(m_nbBins - 1, static_cast<int>(std::floor((tau1 - m_tau0) * kBinsPerPeriod - 0.5)));
  double sum = 0.;
  int count = 0;
  for (int bin = b0; bin <= b1; ++bin) {
    for (int s = 0; s < kSectors; ++s) {
      if (sector < 0 || s == sector) {
        sum += m_sum[bin][s];
        count += m_count[bin][s];
      }
    }
  }
  return count > 0 ? sum / count : -1.;
}

void vpSSLConcentricReader::allAround(double *level) const
{
  // The profile's mean level per bin over every sector, -1 where no ray reached.
  for (int bin = 0; bin < m_nbBins; ++bin) {
    double sum = 0.;
    int count = 0;
    for (int s = 0; s < kSectors; ++s) {
      sum += m_sum[bin][s];
      count += m_count[bin][s];
    }
    level[bin] = count > 0 ? sum / count : -1.;
  }
}

double vpSSLConcentricReader::profileSimilarity(const double *level, double tauA, double tR) const
{
  // Normalised correlation, over the bins in [tauA, tR), of the levels with the square wave whose black ring ends
  // at tR.
  double mean = 0.;
  int n = 0;
  for (int bin = 0; bin < m_nbBins; ++bin) {
    const double tau = m_tau0 + (bin + 0.5) / kBinsPerPeriod;
    if (tau >= tauA && tau < tR && level[bin] >= 0.) {
      mean += level[bin];
      ++n;
    }
  }
  mean /= std::max(1, n);
  double sf = 0., ff = 0.;
  for (int bin = 0; bin < m_nbBins; ++bin) {
    const double tau = m_tau0 + (bin + 0.5) / kBinsPerPeriod;
    if (tau >= tauA && tau < tR && level[bin] >= 0.) {
      double x = tR - tau;
      x -= std::floor(x);
      const double f = level[bin] - mean;
      sf += x < 0.5 ? -f : f;
      ff += f * f;
    }
  }
  return n > 0 && ff > 0. ? sf / std::sqrt(ff * n) : 0.;
}

bool vpSSLConcentricReader::isEqualRings() const
{
  if (!(m_profileTauR > m_profileTauA)) {
    return false; // no profile read by similarity()
  }
  double level[kMaxBins];
  allAround(level);
  return equalRings(level, m_profileTauA, m_profileTauR);
}

bool vpSSLConcentricReader::equalRings(const double *level, double tauA, double tR) const
{
  const double R = std::exp(tR * m_logStep);
  double rho[kMaxBins], g[kMaxBins];
  int n = 0;
  double mean = 0.;
  for (int bin = 0; bin < m_nbBins; ++bin) {
    const double tau = m_tau0 + (bin + 0.5) / kBinsPerPeriod;
    if (tau >= tauA && tau < tR && level[bin] >= 0.) {
      rho[n] = std::exp(tau * m_logStep);
      g[n] = level[bin];
      mean += g[n];
      ++n;
    }
  }
  if (n < kBinsPerPeriod) {
    return false;
  }
  mean /= n;
  // Spread of the levels over [r0, r1) R; -1 on fewer than three bins.
  auto spread = [&](double r0, double r1) {
    double m = 0., q = 0.;
    int k = 0;
    for (int i = 0; i < n; ++i) {
      if (rho[i] >= r0 * R && rho[i] < r1 * R) {
        m += g[i];
        q += g[i] * g[i];
        ++k;
      }
    }
    if (k < 3) {
      return -1.;
    }
    m /= k;
    return std::sqrt(std::max(0., q / k - m * m));
  };
  const double inner = spread(0.2, 0.5), outer = spread(0.5, 1.);
  if (!(inner >= 0. && outer > 0. && inner > kInnerSpread * outer)) {
    return false;
  }
  double gg = 0.;
  for (int i = 0; i < n; ++i) {
    g[i] -= mean;
    gg += g[i] * g[i];
  }
  if (!(gg > 0.)) {
    return false;
  }
  // Pearson correlation with a +-1 wave, from the sum of the centred levels where it is -1 and their number.
  auto correlation = [&](double darkSum, int dark) {
    const double mw = static_cast<double>(n - 2 * dark) / n;
    const double ww = n * (1. - mw * mw);
    return ww > 0. ? -2. * darkSum / std::sqrt(gg * ww) : 0.;
  };
  double darkSum = 0.;
  int dark = 0;
  for (int i = 0; i < n; ++i) {
    double x = tR - std::log(rho[i]) / m_logStep;
    x -= std::floor(x);
    if (x < 0.5) {
      darkSum += g[i];
      ++dark;
    }
  }
  const double selfSimilar = correlation(darkSum, dark);
  // Rings of one width: the levels folded modulo the pair period, then every phase and duty from prefix sums.
  double best = -1.;
  for (double period = 2. * kMinRingWidth; period <= R; period *= kPeriodGrowth) {
    double foldSum[2 * kFoldBins + 1] = {0.};
    int foldCount[2 * kFoldBins + 1] = {0};
    for (int i = 0; i < n; ++i) {
      double x = (R - rho[i]) / period;
      x -= std::floor(x);
      const int q = std::min(kFoldBins - 1, static_cast<int>(x * kFoldBins));
      foldSum[q + 1] += g[i];
      ++foldCount[q + 1];
    }
    for (int q = 1; q <= kFoldBins; ++q) {
      foldSum[q + kFoldBins] = foldSum[q];
      foldCount[q + kFoldBins] = foldCount[q];
    }
    for (int q = 1; q <= 2 * kFoldBins; ++q) {
      foldSum[q] += foldSum[q - 1];
      foldCount[q] += foldCount[q - 1];
    }
    for (int start = 0; start < kFoldBins; ++start) {
      for (int width = kFoldBins / 5; width <= 4 * kFoldBins / 5; width += kFoldBins / 10) {
        best = std::max(
            best, correlation(foldSum[start + width] - foldSum[start], foldCount[start + width] - foldCount[start]));
      }
    }
  }
  return best > selfSimilar + kEqualRingMargin;
}

double vpSSLConcentricReader::similarity(const vpImage<unsigned char> &I, const vpSSLLandmark &landmark)
{
  // The landmark's ellipse as a quadratic form of determinant 1: rho = sqrt(a b) on the outer ellipse.
  const double a = landmark.radius, b = landmark.minorRadius > 0. ? landmark.minorRadius : landmark.radius;
  m_profileTauR = 0.;
  if (!(a > 0. && b > 0.) || I.getWidth() < 2 || I.getHeight() < 2) {
    return 0.;
  }
  const double c = std::cos(landmark.theta), s = std::sin(landmark.theta);
  const double major = b / a, minor = a / b; // Q's eigenvalues along the major and the minor axis
  Fit f;
  f.u = landmark.u;
  f.v = landmark.v;
  f.q[0] = major * c * c + minor * s * s;
  f.q[1] = (major - minor) * c * s;
  f.q[2] = major * s * s + minor * c * c;
  const double L = m_logStep;
  const double tR = std::log(std::sqrt(a * b)) / L;
  const double ringShare = 1. - std::sqrt(m_p);
  const double tauA = std::log(kMinRingWidth / ringShare) / L;
  if (!(tR > tauA)) {
    return 0.;
  }
  readProfile(I, f, tauA - 0.5, tR);
  double level[kMaxBins];
  allAround(level);
  m_profileTauA = tauA;
  m_profileTauR = tR;
  return profileSimilarity(level, tauA, tR);
}

bool vpSSLConcentricReader::grow(const vpImage<unsigned char> &I, double u, double v, bool smooth, Fit &best,
                                 double &bestRadius) const
{
  // The disc grows from (u, v) while its gradients stay normal to one family of concentric ellipses.
  Fit current;
  current.u = u;
  current.v = v;
  bestRadius = 0.;
  double qmax = 0.;
  const double limit = 1.5 * m_maxRadius;
  for (double r = kFirstRadius; r <= limit; r *= kGrowth) {
    if (qmax < kLocked && r > kLockRadius) {
      break; // no ring structure where the rings of any readable landmark would be
    }
    Fit trial = current;
    // Until the rings lock the fit, each disc starts afresh from the candidate and a few steps on a coarse grid
    // tell whether they are there (most candidates end here); once locked, the fit is refined to convergence on
    // the fine grid.
    const bool locked = qmax >= kLocked;
    const bool average = smooth && r >= kSmoothRadius;
    if (!fit(I, r, locked ? 6 : 3, locked ? kFineGrid : (average ? kSmoothGrid : kCoarseGrid), average, trial)) {
      if (qmax >= kLocked) {
        break;
      }
      continue;
    }
    if (qmax >= kLocked && trial.quality < std::max(kMinKept, kKeepShare * qmax)) {
      break;
    }
    if (std::hypot(trial.u - u, trial.v - v) > std::max(4., 0.5 * r)) {
      // Another structure pulled the centre away: once locked, the disc has grown past the landmark; before, a
      // small disc round a blurred centre or a candidate a few pixels off says nothing yet, and a larger one may.
      if (locked) {
        break;
      }
      continue;
    }
    // Until the rings lock the fit, each disc starts afresh from the candidate: a poor fit of a blurred centre
    // would only mislead the next one.
    if (trial.quality >= kLocked || qmax >= kLocked) {
      current = trial;
    }
    if (trial.quality >= kLocked && trial.quality >= 0.97 * qmax) {
      best = trial;
      bestRadius = r;
    }
    qmax = std::max(qmax, trial.quality);
  }
  return bestRadius > 0.;
}

bool vpSSLConcentricReader::read(const vpImage<unsigned char> &I, vpSSLLandmark &landmark)
{
  m_stage = 1;
  m_quality = 0.;
  m_similarity = 0.;
  m_profileTauR = 0.; // the profile read here is not similarity()'s
  if (I.getWidth() < 8 || I.getHeight() < 8) {
    return false;
  }
  // 1. The disc grows while its gradients stay normal to one family of concentric ellipses. On discs of
  //    kSmoothRadius and more the gradients are first those of the 3x3 box average: averaging takes the noise's
  //    gradients, in random directions, out of the share of the energy the rings explain, which would keep landmarks
  //    a few times above the noise from locking. Where the image's own gradients lock the fit as well, from that
  //    centre and to about the same disc, the fit is theirs: the innermost rings, a pixel or two wide, which the
  //    average greys, pin the image of the landmark's centre under perspective (the outer rings' centres drift).
  Fit best, raw;
  double bestRadius = 0., rawRadius = 0.;
  if (!grow(I, landmark.u, landmark.v, true, best, bestRadius)) {
    return false;
  }
  if (bestRadius >= kSmoothRadius && grow(I, best.u, best.v, false, raw, rawRadius) &&
      rawRadius >= kRawDisc * bestRadius && rawRadius * kRawDisc <= bestRadius) {
    best = raw;
    bestRadius = rawRadius;
  }
  m_quality = best.quality;
  m_outerLow = 0.;
  m_outerHigh = std::numeric_limits<double>::infinity();
  return readRings(I, best, bestRadius, landmark);
}

bool vpSSLConcentricReader::readAt(const vpImage<unsigned char> &I, vpSSLLandmark &landmark)
{
  m_stage = 1;
  m_quality = 0.;
  m_similarity = 0.;
  m_profileTauR = 0.;
  // The symmetry kernel's sums hold for images within the kernels' bounds only.
  vpSSLImageCheck::kernel(I, "vpSSLConcentricReader::readAt");
  const double a = landmark.radius, b = landmark.minorRadius;
  if (I.getWidth() < 8 || I.getHeight() < 8 || !(b > 0. && a >= b) || !std::isfinite(landmark.u) ||
      !std::isfinite(landmark.v) || !std::isfinite(landmark.theta)) {
    return false;
  }
  // The ellipses of the given shape, (x - c)^T Q (x - c) = rho^2 with det Q = 1: rho is the geometric mean of the
  // semi-axes, and the outer ring lies at rho = sqrt(a b).
  const double c = std::cos(landmark.theta), s = std::sin(landmark.theta), ab = a * b;
  Fit f;
  f.u = landmark.u;
  f.v = landmark.v;
  f.q[0] = ab * (c * c / (a * a) + s * s / (b * b));
  f.q[1] = ab * c * s * (1. / (a * a) - 1. / (b * b));
  f.q[2] = ab * (s * s / (a * a) + c * c / (b * b));
  f.quality = 1.;
  const double rho = std::sqrt(ab);
  // The centre where the disc inside the outer ring best matches its half-turn (a landmark is point-symmetric under
  // any affine view and symmetric blur, however blurred its rings), followed over a few search windows, as long as
  // it stays within kShapedShift minor semi-axes of the centre given; the shape stays the one given, which a faint
  // landmark's few gradients would pull about.
  const int radius = std::max(2, std::min(vpSSLSymmetryKernel::kMaxRadius, static_cast<int>(std::lround(b))));
  if (radius != m_symmetryRadius) {
    vpSSLSymmetryKernel::halfDisc(radius, m_symmetrySpans);
    m_symmetryRadius = radius;
  }
  double u = f.u, v = f.v, asymmetry = 0.;
  for (int step = 0; step < 4; ++step) {
    const double u0 = u, v0 = v;
    if (!vpSSLSymmetryKernel::centre(I, radius, m_symmetrySpans, 0., m_symmetryBuffer, u, v, asymmetry) ||
        std::hypot(u - f.u, v - f.v) > kShapedShift * b) {
      u = u0;
      v = v0;
      break;
    }
    if (std::fabs(u - u0) < 2.5 && std::fabs(v - v0) < 2.5) {
      break;
    }
  }
  f.u = u;
  f.v = v;
  // Only a copy of about the size given: the rings of one landmark hold copies of every size below its own.
  m_outerLow = kShapedSize * rho;
  m_outerHigh = rho / kShapedSize;
  return readRings(I, f, rho, landmark);
}

bool vpSSLConcentricReader::readRings(const vpImage<unsigned char> &I, Fit best, double bestRadius,
                                      vpSSLLandmark &landmark)
{
  const double limit = 1.5 * m_maxRadius;

  // 2. The rings' phase from the radial profile of every resolved ring inside the fitted disc. In
  //    tau = log_{1/p}(rho), s_p is a square wave of period 1, black just inside the outer radius tau_R.
  m_stage = 2;
  const double L = m_logStep;
  const double tauLow = std::log(1.5) / L, tauHigh = std::log(std::min(limit, 2.5 * bestRadius)) / L;
  readProfile(I, best, tauLow, tauHigh);
  const double ringShare = 1. - std::sqrt(m_p); // width of the ring at radius rho, over rho
  const double tauA = std::log(kMinRingWidth / ringShare) / L, tauB = std::log(bestRadius) / L;
  double level[kMaxBins];
  allAround(level);
  // The window seldom holds a whole number of periods: the levels are correlated about their mean, or the half
  // of the wave with more bins in the window would win by the mean level alone.
  double mean = 0.;
  int used = 0;
  for (int bin = 0; bin < m_nbBins; ++bin) {
    const double tau = m_tau0 + (bin + 0.5) / kBinsPerPeriod;
    if (tau >= tauA && tau <= tauB && level[bin] >= 0.) {
      mean += level[bin];
      ++used;
    }
  }
  if (used < kBinsPerPeriod) {
    return false; // less than one period of resolved rings
  }
  mean /= used;
  double bestCorrelation = -1e30, phase = 0.;
  for (int k = 0; k < 4 * kBinsPerPeriod; ++k) {
    const double tauR = k / (4. * kBinsPerPeriod);
    double correlation = 0.;
    for (int bin = 0; bin < m_nbBins; ++bin) {
      const double tau = m_tau0 + (bin + 0.5) / kBinsPerPeriod;
      if (tau < tauA || tau > tauB || level[bin] < 0.) {
        continue;
      }
      double x = tauR - tau;
      x -= std::floor(x);
      correlation += x < 0.5 ? mean - level[bin] : level[bin] - mean;
    }
    if (correlation > bestCorrelation) {
      bestCorrelation = correlation;
      phase = tauR;
    }
  }

  // 3. The outer ring: the outermost p-similar copy whose black ring is dark against the white one inside it in
  //    nearly every direction, as dark as the next black ring, with the rings alternating inwards.
  m_stage = 3;
  double outer = 0.;
  int good = 0;
  for (int k = static_cast<int>(std::floor(tauHigh - phase)); k >= -2; --k) {
    const double tR = phase + k;
    const double R = std::exp(tR * L);
    if (tR > tauHigh - 0.05 || R < m_minRadius || R < m_outerLow || R > m_outerHigh) {
      continue;
    }
    const double black = band(tR - 0.4, tR - 0.1, -1), white = band(tR - 0.9, tR - 0.6, -1);
    const double black2 = band(tR - 1.4, tR - 1.1, -1);
    if (black < 0. || white < 0.) {
      continue;
    }
    const double contrast = white - black;
    if (contrast < kMinContrast) {
      continue;
    }
    int seen = 0;
    good = 0;
    for (int s = 0; s < kSectors; ++s) {
      const double b = band(tR - 0.42, tR - 0.08, s), w = band(tR - 0.92, tR - 0.58, s);
      if (b < 0. || w < 0.) {
        continue;
      }
      ++seen;
      good += w - b > kSectorShare * contrast ? 1 : 0;
    }
    if (seen < kSectors / 2 || good < kSectorsNeeded * seen) {
      continue;
    }
    if (black2 >= 0. && ringShare * R * m_p > 2.5 && black > black2 + kInkTolerance * contrast) {
      continue;
    }
    // The outer ring is printed solid out to R: its outer part is as dark as its inner part, but for the blur of the
    // edge (rings that end inside it, a bull's-eye, leave it half light).
    const double innerPart = band(tR - 0.4, tR - 0.25, -1), outerPart = band(tR - 0.2, tR - 0.1, -1);
    if (innerPart < 0. || outerPart < 0. || outerPart - innerPart > kSolidShare * contrast) {
      continue;
    }
    int pairs = 0;
    for (int j = 0; j < 8; ++j) {
      const double b = band(tR - j - 0.4, tR - j - 0.1, -1), w = band(tR - j - 0.9, tR - j - 0.6, -1);
      if (b < 0. || w < 0. || w - b < 0.25 * contrast) {
        break;
      }
      ++pairs;
    }
    // Pairs inside a ring narrower than the blur of a sharp lens (two camera pixels) may have faded.
    int resolvable = 0;
    for (int j = 0; j < kMinPairs; ++j) {
      resolvable += ringShare * R * std::pow(m_p, j + 1) >= 2. ? 1 : 0;
    }
    // Whatever the blur, the white ring is lighter than the black ring inside it: a lone disc (a dot, a blob) has one
    // edge, which passes for the outer pair only.
    const double black1 = band(tR - 1.4, tR - 1.1, -1);
    if (pairs < std::max(1, resolvable) || black1 < 0. || white - black1 < kInnerShare * contrast) {
      continue;
    }
    outer = R;
    // The scale from the two printed edges inside the outer ring (R sqrt(p): white to black, R p: black to white,
    // going outwards), where the profile crosses the mid level between the rings: the widest rings, the least
    // blurred, and both edges printed (the outer edge's outside is unknown).
    // Each edge is crossed at the mid level of its own two rings: the inner black ring, narrower, is greyed by the
    // blur more than the outer one, and a common level would move the inner edge.
    const double mids[2] = {0.5 * (black + white), 0.5 * (black1 + white)};
    double shift = 0.;
    int edges = 0;
    for (int e = 0; e < 2; ++e) {
      const double expected = tR - 0.5 * (e + 1); // in periods
      const bool rising = e == 1;                 // outwards: black to white at R p... inwards white to black
      double bestTau = 0., bestDistance = kEdgeWindow;
      for (int bin = 0; bin + 1 < m_nbBins; ++bin) {
        if (level[bin] < 0. || level[bin + 1] < 0.) {
          continue;
        }
        const double a = level[bin] - mids[e], c = level[bin + 1] - mids[e];
        // Outwards, the edge at R sqrt(p) goes from white to black, the one at R p from black to white.
        const bool crosses = rising ? (a < 0. && c >= 0.) : (a > 0. && c <= 0.);
        if (!crosses) {
          continue;
        }
        const double tau = m_tau0 + (bin + 0.5 + a / (a - c)) / kBinsPerPeriod;
        if (std::fabs(tau - expected) < bestDistance) {
          bestDistance = std::fabs(tau - expected);
          bestTau = tau;
        }
      }
      if (bestDistance < kEdgeWindow) {
        shift += bestTau - expected;
        ++edges;
      }
    }
    // Self-similarity: a printed edge within kEdgeWindow of where the inner rings' phase puts it, and the profile of
    // the resolved rings inside R following the square wave (rings of equal width, a bull's-eye, follow it over a
    // ring or two).
    if (edges == 0) {
      outer = 0.;
      continue;
    }
    // The profile is compared with the wave whose outer edge is the one reported, the same that similarity() sees
    // at the landmark read.
    const double tEdges = tR + shift / edges;
    m_similarity = profileSimilarity(level, tauA, tEdges);
    if (m_similarity < kMinSimilarity) {
      outer = 0.;
      continue;
    }
    outer = std::exp(tEdges * L);
    break;
  }
  if (outer == 0. && m_blurredRingModel) {
    outer = blurredOuter(level, phase, tauHigh, best, m_similarity);
  }
  if (outer == 0.) {
    return false;
  }

  // 4. The centre: the image of the landmark's centre under perspective is the centre of its smallest ellipses, to
  //    which the outer rings' centres drift (the widest ones dominate the fit of the whole disc). Where the disc
  //    inside the third ring, R p^2, is wide enough for its gradients to pin a centre, its own fit gives the centre,
  //    unless the rings there do not lock it or pull it away (a blur that greys them).
  const double disc = outer * m_p * m_p;
  if (disc >= kMinInnerDisc) {
    Fit inner = best;
    if (fit(I, disc, 6, std::max(kFineGrid, 2. * disc), false, inner) && inner.quality >= kLocked &&
        std::hypot(inner.u - best.u, inner.v - best.v) <= kInnerShift * disc) {
      best.u = inner.u;
      best.v = inner.v;
    }
  }

  // 5. The outer ellipse: the level set rho = R of the fitted quadratic form.
  m_stage = 4;
  Eigen::Matrix2d Q;
  Q << best.q[0], best.q[1], best.q[1], best.q[2];
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(Q);
  const double lmin = solver.eigenvalues()(0), lmax = solver.eigenvalues()(1);
  landmark.u = best.u;
  landmark.v = best.v;
  landmark.radius = outer / std::sqrt(lmin);
  landmark.minorRadius = outer / std::sqrt(lmax);
  landmark.theta = std::atan2(solver.eigenvectors()(1, 0), solver.eigenvectors()(0, 0));
  landmark.nbDirections = static_cast<unsigned int>(good);
  const double c45 = M_SQRT1_2;
  const double dirs[8][2] = {{1., 0.},  {c45, c45},   {0., 1.},  {-c45, c45},
                             {-1., 0.}, {-c45, -c45}, {0., -1.}, {c45, -c45}};
  for (int d = 0; d < 8; ++d) {
    const double x = dirs[d][0], y = dirs[d][1];
    landmark.directionalRadius[d] = outer / std::sqrt(best.q[0] * x * x + 2. * best.q[1] * x * y + best.q[2] * y * y);
  }
  return landmark.radius <= m_maxRadius && landmark.minorRadius >= kMinMinorRadius;
}

double vpSSLConcentricReader::modelCorrelation(const double *level, int sector, double R, double sigma, bool rings,
                                               double pxPerRho, double &amplitude) const
{
  // Normalised correlation of the profile (all around, or one sector) with the rings' profile blurred by sigma
  // (rho units), or with a blurred solid disc, over rho from max(2 sigma, 1.5 px) to 1.1 R. amplitude: the profile's
  // grey levels per unit of the model (paper minus ink). -1 where fewer than a period of bins are seen.
  const double rhoLow = std::max(2. * sigma, 1.5 / pxPerRho), rhoHigh = 1.1 * R, edgeRatio = std::sqrt(m_p);
  double sl = 0., sm = 0., sll = 0., smm = 0., slm = 0.;
  int n = 0;
  for (int bin = 0; bin < m_nbBins; ++bin) {
    double l = level[bin];
    if (sector >= 0) {
      l = m_count[bin][sector] > 0 ? m_sum[bin][sector] / m_count[bin][sector] : -1.;
    }
    const double rho = m_rho[bin];
    if (l < 0. || rho < rhoLow || rho > rhoHigh) {
      continue;
    }
    const double m =
        rings ? blurredRings(rho, R, sigma, edgeRatio) : 1. - 0.5 * std::erfc((rho - R) / (M_SQRT2 * sigma));
    sl += l;
    sm += m;
    sll += l * l;
    smm += m * m;
    slm += l * m;
    ++n;
  }
  amplitude = 0.;
  if (n < kBinsPerPeriod) {
    return -1.;
  }
  const double vl = sll - sl * sl / n, vm = smm - sm * sm / n, c = slm - sl * sm / n;
  if (!(vl > 0. && vm > 1e-9)) {
    return -1.;
  }
  amplitude = c / vm;
  return c / std::sqrt(vl * vm);
}

double vpSSLConcentricReader::blurredOuter(const double *level, double phase, double tauHigh, const Fit &f,
                                           double &correlation) const
{
  // The rings' profile is in rho, the radius of the fitted ellipses; a pixel is about (det Q)^(1/4) = 1 of it, the
  // geometric mean of the ellipse's semi-axes per unit of rho.
  Eigen::Matrix2d Q;
  Q << f.q[0], f.q[1], f.q[1], f.q[2];
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(Q);
  const double pxPerRho = std::pow(solver.eigenvalues()(0) * solver.eigenvalues()(1), -0.25);
  for (int k = static_cast<int>(std::floor(tauHigh - phase)); k >= -2; --k) {
    // The blur first, at the phase's edge; then the edge about it at that blur.
    double best = -1., bestR = 0., bestSigma = 0., amplitude = 0., a = 0.;
    auto tryEdge = [&](double tR, double sigmaPx) {
      const double R = std::exp(tR * m_logStep);
      if (tR > tauHigh - 0.15 || R * pxPerRho < kModelMinRadius || R < m_minRadius || R < m_outerLow ||
          R > m_outerHigh) {
        return;
      }
      const double c = modelCorrelation(level, -1, R, sigmaPx / pxPerRho, true, pxPerRho, a);
      if (c > best) {
        best = c;
        bestR = R;
        bestSigma = sigmaPx / pxPerRho;
        amplitude = a;
      }
    };
    for (double sigmaPx : kModelSigmas) {
      tryEdge(phase + k, sigmaPx);
    }
    const double sigmaPx = bestSigma * pxPerRho;
    for (int j = -kModelShifts; j <= kModelShifts && best > -1.; ++j) {
      if (j != 0) {
        tryEdge(phase + k + j * kModelShift, sigmaPx);
      }
    }
    // Blur that greys every ring leaves a dark disc, which a dark blob matches as well.
    double disc = -1.;
    for (double scale : {0.9, 1., 1.1}) {
      for (double s : kModelSigmas) {
        disc = std::max(disc, modelCorrelation(level, -1, scale * bestR, s / pxPerRho, false, pxPerRho, a));
      }
    }
    if (best < kModelCorrelation || amplitude <= 0.) {
      continue;
    }
    if (best - disc < kModelDiscMargin) {
      continue;
    }
    // The rings all around: most directions follow the model on their own.
    int seen = 0, good = 0;
    for (int s = 0; s < kSectors; ++s) {
      const double c = modelCorrelation(level, s, bestR, bestSigma, true, pxPerRho, a);
      if (c == -1. && a == 0.) {
        continue;
      }
      ++seen;
      good += c >= kModelSectorCorrelation ? 1 : 0;
    }
    if (seen < kSectors - 2 || good < kModelSectorShare * seen) {
      continue;
    }
    // The model's variance over the bins against the noise of the profile's mean, from the spread of the sectors.
    const double rhoLow = std::max(2. * bestSigma, 1.5 / pxPerRho), edgeRatio = std::sqrt(m_p);
    double noise = 0., sm = 0., smm = 0.;
    int n = 0;
    for (int bin = 0; bin < m_nbBins; ++bin) {
      const double rho = m_rho[bin];
      if (level[bin] < 0. || rho < rhoLow || rho > 1.1 * bestR) {
        continue;
      }
      double ls[kSectors], mean = 0.;
      int ns = 0;
      for (int s = 0; s < kSectors; ++s) {
        if (m_count[bin][s] > 0) {
          ls[ns] = m_sum[bin][s] / m_count[bin][s];
          mean += ls[ns++];
        }
      }
      if (ns < 2) {
        continue;
      }
      mean /= ns;
      double spread = 0.;
      for (int j = 0; j < ns; ++j) {
        spread += (ls[j] - mean) * (ls[j] - mean);
      }
      noise += spread / (ns - 1) / ns;
      const double m = blurredRings(rho, bestR, bestSigma, edgeRatio);
      sm += m;
      smm += m * m;
      ++n;
    }
    if (n < 2 || !(amplitude * amplitude * (smm - sm * sm / n) >= kModelSnr * noise)) {
      continue;
    }
    correlation = best;
    return bestR;
  }
  return 0.;
}
