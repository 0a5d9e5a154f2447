/*
  Private interface of the SIMD twice upsampling of the small-landmark mode (vpSSLDetector), implemented with
  Google Highway in vpSSLResampleKernel.cpp and picked at run time for the CPU.
*/
#ifndef VP_SSL_RESAMPLE_KERNEL_H
#define VP_SSL_RESAMPLE_KERNEL_H

#include <cstdint>

namespace vpSSLResampleKernel {
//! Widest row upsampleRow() supports (pixels).
constexpr int kMaxWidth = 32768;
/*!
  One row of the bilinear twice upsampling with pixel centres kept (output column u samples input column
  (u + 0.5) / 2 - 0.5, edges repeated): out[u] = (wTop T[u] + (4 - wTop) B[u] + 8) >> 4 for u in [0, 2 width),
  where T and B are the rows \e top and \e bottom interpolated along the row with weights 3:1 and 1:3 (in
  quarters, edges repeated). Exact integers: the same bytes on every target.
  Sizes: 1 <= width <= 32768 (2 width indexes the output row as an int and the input limit of vpSSLInputLimits is
  16384 a side); top and bottom hold width bytes, out 2 width. The public entry points that reach it check the
  image first (vpSSLImageCheck): a 65537 px row of a wrapped vpImage would otherwise be read past its end.
*/
void upsampleRow(const uint8_t *top, const uint8_t *bottom, int wTop, int width, uint8_t *out);
} // namespace vpSSLResampleKernel

#endif
