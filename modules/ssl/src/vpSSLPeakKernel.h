/*
  Private interface of the SIMD local-maximum test of vpSSLPeakDetector, implemented with Google Highway in
  vpSSLPeakKernel.cpp and picked at run time for the CPU.
*/
#ifndef VP_SSL_PEAK_KERNEL_H
#define VP_SSL_PEAK_KERNEL_H

#include <cstddef>

namespace vpSSLPeakKernel {
/*!
  Columns u in [u0, u1] of \e row at which row[u] >= threshold and row[u] is a maximum of its 3x3 neighbourhood,
  strictly against the later neighbours (row[u + 1] and the row below) and loosely against the earlier ones: one
  pixel per plateau. \e above and \e below are the neighbouring rows, nullptr where the row is the map's first or
  last. Every column read, u0 - 1 to u1 + 1, must exist. Written to \e columns in increasing order.
  Sizes: columns in int, the map within the kernels' bound of vpSSLImageCheck (vpSSLPeakDetector::detect()
  checks it); \e columns holds u1 - u0 + 1 ints.
  \return their number.
*/
int localMaxima(const int *above, const int *row, const int *below, int u0, int u1, int threshold, int *columns);
} // namespace vpSSLPeakKernel

#endif
