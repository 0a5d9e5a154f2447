/*
  Private interface of the SIMD matching kernel (paper Eq. 3 and 5), implemented with Google Highway in
  vpSSLMatchingKernel.cpp and picked at run time for the CPU. Sizes: width and height up to the kernels' bound
  of vpSSLImageCheck (32768 a side, 2^28 pixels: int columns and rows, ptrdiff_t strides and offsets of the
  padded copy, int32 map values), window w <= kMaxWindow (int16 sums); vpSSLMatchingFunction checks the image
  before building Params. No Highway type appears here so that the public headers stay free of it: a program
  that includes them needs no Highway headers, and the kernel's targets can change without breaking the
  library's ABI.
*/
#ifndef VP_SSL_MATCHING_KERNEL_H
#define VP_SSL_MATCHING_KERNEL_H

#include <cstddef>
#include <cstdint>
#include <cstdlib>

namespace vpSSLMatchingKernel {
//! Largest window the kernel accepts; 255 * 128 = 32640 keeps every sum inside int16.
constexpr int kMaxWindow = 128;

/*!
  One term of the Eq. 3 sum from its three pixels: |I(X + xi d) - I(X + a_xi d)| - |I(X + xi d) - I(X + b_xi d)|.
  The scalar sums (reference, single pixel, cumulative, the kernel's one-lane fallback) all add these; the
  vector kernels compute the same integers lane-wise.
*/
inline int term(int i0, int ia, int ib)
{
  return std::abs(i0 - ia) - std::abs(i0 - ib);
}

//! Directions, in the order of vpSSLDirection.
enum Direction
{
  kPlusX = 0,
  kMinusX,
  kPlusY,
  kMinusY
};

/*
  Everything one call of compute() shares between rows and threads. The kernel reads a copy of the image whose
  rows are padded on both sides, so that vector lanes outside the valid part of a row (masked out of the
  maximum, or never stored) still read allocated memory.
*/
struct Params
{
  const uint8_t *pixels; // padded copy: pixel (v, u) is pixels[v * stride + u], u from -leftPad() on
  std::ptrdiff_t stride; // bytes between rows of the padded copy
  int width;
  int height;
  int window;   // w in [2, kMaxWindow]
  int32_t *out; // the map M, row-major, width x height
  // offsets[dir][xi] = {xi, a_xi, b_xi} steps along direction dir (in bytes of the padded copy: steps 1, -1,
  // stride, -stride), with a_xi = floor(sqrt(p) xi + 1/2) and b_xi = floor(p xi + 1/2). The kernel relies on
  // that form (its plan, cached per thread, is keyed on window, stride and offsets[kPlusX] only).
  std::ptrdiff_t offsets[4][kMaxWindow + 1][3];
};

/*
  Right padding of a padded row beyond the window: two of the widest vectors Highway may use (2048-bit SVE), so
  that a whole block of pixels past the last one still reads the row. The shared horizontal rows of the kernel
  read up to 2 N + 2 w bytes past the last pixel and are only used when that fits.
*/
constexpr std::ptrdiff_t kRightPadBytes = 2 * 256;

//! Left padding (bytes) of a padded row: at least the window, rounded to 64 bytes.
std::ptrdiff_t leftPad(int window);
//! Row stride (bytes) of the padded copy for a width and a window.
std::ptrdiff_t paddedStride(int width, int window);
//! Bytes of the padded copy (to allocate once and reuse); pixel (0, 0) is at offset leftPad().
std::size_t paddedSize(int width, int height, int window);

//! Writes M(v, u) for u in [u0, u1) (Eq. 5), reading rows v - w .. v + w, columns u0 - w .. u1 + w of the copy.
void matchSpan(const Params &params, int v, int u0, int u1);

//! Name of the Highway target that matchSpan() runs on (e.g. "AVX3", "AVX2", "SSE4", "NEON", "SCALAR").
const char *targetName();
} // namespace vpSSLMatchingKernel

#endif
