/*
  Private interface of the SIMD arithmetic of vpSSLWaterModel's sensor noise, implemented with Google Highway in
  vpSSLNoiseKernel.cpp and picked at run time for the CPU. Every lane performs the IEEE operations of the scalar
  expressions below, in the same order and without fused multiply-adds, so the results are the scalar ones bit for
  bit (test_sim_exact compares them).
*/
#ifndef VP_SSL_NOISE_KERNEL_H
#define VP_SSL_NOISE_KERNEL_H

#include <cstddef>

namespace vpSSLNoiseKernel {
/*!
  The factors of Marsaglia's polar method: fac[i] = std::sqrt(-2. * logRsq[i] / rsq[i]), for the n accepted pairs'
  squared radii \e rsq and their logarithms \e logRsq (libm's, computed by the caller).
*/
void polarFactors(const double *rsq, const double *logRsq, size_t n, double *fac);

/*!
  The noisy 8-bit colour of nb pixels: channel c of pixel k is
  vpSSLQuantise::quantise(255. * (y + std::sqrt(std::max(0., a * y + b)) * deviates[3 * k + c])) with
  y = gain * radiance_c[k], written to rgba[4 * k + c], and 255 to rgba[4 * k + 3] (vpRGBa's layout).
*/
void exposeQuantise(const float *red, const float *green, const float *blue, const double *deviates, size_t nb,
                    double gain, double a, double b, unsigned char *rgba);
} // namespace vpSSLNoiseKernel

#endif
