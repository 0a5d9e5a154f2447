#include <visp3/ssl_harness/vpSSLBenchMath.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <visp3/core/vpMath.h>

double vpSSLBenchMath::nan()
{
  return std::numeric_limits<double>::quiet_NaN();
}

double vpSSLBenchMath::positionError(const vpHomogeneousMatrix &est, const vpHomogeneousMatrix &truth)
{
  return (est.getTranslationVector() - truth.getTranslationVector()).frobeniusNorm();
}

double vpSSLBenchMath::angleError(const vpHomogeneousMatrix &est, const vpHomogeneousMatrix &truth)
{
  vpRotationMatrix R = truth.getRotationMatrix().t() * est.getRotationMatrix();
  double c = (R[0][0] + R[1][1] + R[2][2] - 1.) / 2.;
  c = std::max(-1., std::min(1., c));
  return vpMath::deg(std::acos(c));
}

std::string vpSSLBenchMath::fmt(double x, int digits)
{
  if (!std::isfinite(x))
    return "-";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", digits, x);
  return buf;
}

std::string vpSSLBenchMath::csvNumber(double x, int digits)
{
  return std::isfinite(x) ? fmt(x, digits) : std::string();
}

const std::vector<double> &vpSSLBenchMath::bandEdges()
{
  static const std::vector<double> edges = {0., 1., 2., 4., 8., 12.};
  return edges;
}

std::string vpSSLBenchMath::bandLabel(size_t b)
{
  const std::vector<double> &e = bandEdges();
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%g-%g", e[b], e[b + 1]);
  return buf;
}

int vpSSLBenchMath::bandIndex(double range)
{
  const std::vector<double> &e = bandEdges();
  if (!std::isfinite(range) || range < e.front() || range > e.back())
    return -1;
  for (size_t b = 0; b + 1 < e.size(); ++b)
    if (range < e[b + 1])
      return static_cast<int>(b);
  return static_cast<int>(e.size()) - 2;
}

double vpSSLBenchMath::percentile(std::vector<double> v, double p)
{
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (v.empty())
    return nan();
  std::sort(v.begin(), v.end());
  const double pos = p / 100. * static_cast<double>(v.size() - 1);
  const size_t lo = static_cast<size_t>(std::floor(pos));
  const size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
}
