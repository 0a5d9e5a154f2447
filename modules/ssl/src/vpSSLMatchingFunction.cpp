#include <visp3/ssl/vpSSLMatchingFunction.h>

#include <cmath>
#include <cstdlib>

#include <visp3/core/vpException.h>

#include "vpSSLImageCheck.h"
#include "vpSSLMatchingKernel.h"

namespace {
const int kDu[4] = {1, -1, 0, 0};
const int kDv[4] = {0, 0, 1, -1};
} // namespace

vpSSLMatchingFunction::vpSSLMatchingFunction(unsigned int window, double p) : m_window(40), m_p(0.5), m_nbThreads(0)
{
  setWindow(window);
  setP(p);
}

void vpSSLMatchingFunction::setWindow(unsigned int window)
{
  // 128 keeps 255 * w inside int16, which the SIMD kernel accumulates in.
  if (window < 2 || window > 128) {
    throw vpException(vpException::badValue, "vpSSLMatchingFunction: window %u not in [2, 128]", window);
  }
  m_window = window;
}

void vpSSLMatchingFunction::setP(double p)
{
  if (!(p > 0. && p < 1.)) {
    throw vpException(vpException::badValue, "vpSSLMatchingFunction: p = %g not in (0, 1)", p);
  }
  m_p = p;
}

int vpSSLMatchingFunction::offsetSqrtP(unsigned int xi) const
{
  return static_cast<int>(std::floor(std::sqrt(m_p) * xi + 0.5));
}

int vpSSLMatchingFunction::offsetP(unsigned int xi) const
{
  return static_cast<int>(std::floor(m_p * xi + 0.5));
}

bool vpSSLMatchingFunction::evaluate(const vpImage<unsigned char> &I, int u, int v, vpSSLDirection d,
                                     unsigned int window, int &value) const
{
  vpSSLImageCheck::kernel(I, "vpSSLMatchingFunction::evaluate");
  const int du = kDu[d], dv = kDv[d];
  const int W = static_cast<int>(I.getWidth()), H = static_cast<int>(I.getHeight());
  const int ue = u + du * static_cast<int>(window), ve = v + dv * static_cast<int>(window);
  if (u < 0 || v < 0 || u >= W || v >= H || ue < 0 || ve < 0 || ue >= W || ve >= H) {
    return false;
  }
  int sum = 0;
  for (unsigned int xi = 1; xi <= window; ++xi) {
    const int a = offsetSqrtP(xi), b = offsetP(xi);
    const int i0 = I[v + dv * static_cast<int>(xi)][u + du * static_cast<int>(xi)];
    const int ia = I[v + dv * a][u + du * a];
    const int ib = I[v + dv * b][u + du * b];
    sum += vpSSLMatchingKernel::term(i0, ia, ib);
  }
  value = sum;
  return true;
}

void vpSSLMatchingFunction::cumulative(const vpImage<unsigned char> &I, int u, int v, vpSSLDirection d,
                                       unsigned int maxWindow, std::vector<int> &S) const
{
  vpSSLImageCheck::kernel(I, "vpSSLMatchingFunction::cumulative");
  const int du = kDu[d], dv = kDv[d];
  const int W = static_cast<int>(I.getWidth()), H = static_cast<int>(I.getHeight());
  S.assign(1, 0);
  if (u < 0 || v < 0 || u >= W || v >= H) {
    return;
  }
  int sum = 0;
  // offsetSqrtP() and offsetP() with the square root taken once (the same arithmetic): the Eq. 7 sweep of
  // every landmark runs hundreds of terms.
  const double q = std::sqrt(m_p);
  for (unsigned int xi = 1; xi <= maxWindow; ++xi) {
    const int ue = u + du * static_cast<int>(xi), ve = v + dv * static_cast<int>(xi);
    if (ue < 0 || ve < 0 || ue >= W || ve >= H) {
      break;
    }
    const int a = static_cast<int>(std::floor(q * xi + 0.5)), b = static_cast<int>(std::floor(m_p * xi + 0.5));
    const int i0 = I[ve][ue];
    const int ia = I[v + dv * a][u + du * a];
    const int ib = I[v + dv * b][u + du * b];
    sum += vpSSLMatchingKernel::term(i0, ia, ib);
    S.push_back(sum);
  }
}

void vpSSLMatchingFunction::computeReference(const vpImage<unsigned char> &I, vpImage<int> &M) const
{
  vpSSLImageCheck::kernel(I, "vpSSLMatchingFunction::computeReference");
  const int W = static_cast<int>(I.getWidth()), H = static_cast<int>(I.getHeight());
  M.resize(I.getHeight(), I.getWidth(), 0);
  for (int v = 0; v < H; ++v) {
    for (int u = 0; u < W; ++u) {
      bool any = false;
      int best = 0;
      for (int d = 0; d < 4; ++d) {
        int value;
        if (evaluate(I, u, v, static_cast<vpSSLDirection>(d), m_window, value)) {
          best = any ? std::max(best, value) : value;
          any = true;
        }
      }
      M[v][u] = any ? best : 0;
    }
  }
}
