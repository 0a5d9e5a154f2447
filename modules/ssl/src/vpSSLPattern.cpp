/*!
  \file vpSSLPattern.cpp
  \brief The self-similar square wave (paper Eq. 1) and the circular (Eq. 4) and linear landmarks.
*/
#include <visp3/ssl/vpSSLPattern.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include <visp3/core/vpException.h>

namespace {
// 2 log_p(x) is an integer exactly on a ring boundary x = p^(k/2). log() of such an x divided by
// log(p) lands a few ulps either side of the integer, which would put the boundary in the wrong
// ring (e.g. x = sqrt(0.5) giving 0.99999999999999989 instead of 1). Snapping within this many
// units of 2 log_p(x) keeps every boundary in the inner ring, as Eq. 1 says, while moving a ring
// edge by at most 1e-9 * |log p| / 2 relative, far below anything printable or visible.
const double kBoundarySnap = 1e-9;

void checkP(double p)
{
  if (!(p > 0. && p < 1.)) {
    std::ostringstream os;
    os << "vpSSLPattern: similarity ratio p must be in (0, 1), got " << p;
    throw vpException(vpException::badValue, os.str());
  }
}
} // namespace

int vpSSLPattern::squareWave(double x, double p)
{
  checkP(p);
  if (!(x > 0.)) {
    return 1;
  }
  // floor(2 (L - floor L)) = floor(2L) - 2 floor(L) = floor(2L) mod 2: one floor instead of two,
  // and only one place where rounding matters.
  double t = 2. * std::log(x) / std::log(p);
  double r = std::round(t);
  if (std::fabs(t - r) <= kBoundarySnap * std::max(1., std::fabs(t))) {
    t = r;
  }
  double k = std::floor(t);
  double m = k - 2. * std::floor(0.5 * k);
  return m != 0. ? 1 : 0;
}

int vpSSLPattern::circular(double dx, double dy, double radius, double p)
{
  if (!(radius > 0.)) {
    std::ostringstream os;
    os << "vpSSLPattern: landmark radius must be > 0, got " << radius;
    throw vpException(vpException::badValue, os.str());
  }
  double rho = std::hypot(dx, dy);
  if (!(rho <= radius)) {
    checkP(p);
    return -1;
  }
  return squareWave(rho / radius, p);
}

int vpSSLPattern::linear(double x, double length, double p)
{
  if (!(length > 0.)) {
    std::ostringstream os;
    os << "vpSSLPattern: linear landmark length must be > 0, got " << length;
    throw vpException(vpException::badValue, os.str());
  }
  if (!(x > 0. && x <= length)) {
    checkP(p);
    return -1;
  }
  return squareWave(x / length, p);
}
