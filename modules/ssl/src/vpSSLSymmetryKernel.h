/*
  Private interface of the symmetry centring of a candidate (vpSSLRadiusEstimator): the half-pixel centre about
  which a disc best matches its half-turn. The sums of squared differences of the whole search window are
  computed with Google Highway in vpSSLSymmetryKernel.cpp, picked at run time for the CPU. Sizes: radius <= 144
  (32-bit sums, see centre()), the image within the kernels' bound of vpSSLImageCheck (vpSSLRadiusEstimator checks
  it).
*/
#ifndef VP_SSL_SYMMETRY_KERNEL_H
#define VP_SSL_SYMMETRY_KERNEL_H

#include <cstddef>
#include <cstdint>
#include <vector>

#include <visp3/core/vpImage.h>

namespace vpSSLSymmetryKernel {
//! Half pixels searched either way of the starting centre: a window of (2 kReach + 1)^2 half-pixel centres.
const int kReach = 6;
//! Largest disc radius centre() reads (px): half the disc times 255^2 stays below 2^31.
const int kMaxRadius = 144;

/*!
  Row extents of the half disc of \e radius that pairs every pixel of the disc with its half-turn once (dy > 0,
  or dy = 0 and dx > 0): row dy spans dx in [spans[dy], spans[radius + 1 + dy]]. spans[radius + 1 + |dy|] is
  also the half width of row dy of the whole disc.
*/
void halfDisc(int radius, std::vector<int> &spans);

/*!
  Moves (\e u, \e v) to the half-pixel centre, within kReach half pixels, that minimises the sum of squared
  differences between the disc of \e radius about it and its half-turn (the first in row-major order on ties),
  refined by a parabola through its neighbours. \e asymmetry is that sum relative to the disc's variance, 0 if
  the variance is below \e flatVariance.
  \e spans comes from halfDisc(radius); \e buffer is scratch, kept between calls (no allocation once grown). The
  sums are 32-bit: \e radius up to 144 (half the disc times 255^2 below 2^31).
  \return false (\e u, \e v unchanged, \e asymmetry 0) if the window comes too close to the border, \e radius is
  not in [1, kMaxRadius] or the centre is not finite.
*/
bool centre(const vpImage<unsigned char> &I, int radius, const std::vector<int> &spans, double flatVariance,
            std::vector<int16_t> &buffer, double &u, double &v, double &asymmetry);
} // namespace vpSSLSymmetryKernel

#endif
