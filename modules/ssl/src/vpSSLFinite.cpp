/*!
  \file vpSSLFinite.cpp
  \brief Finite-value check of ViSP arrays.
*/
#include <visp3/ssl/vpSSLFinite.h>

#include <algorithm>
#include <cmath>

bool vpSSLFinite::isFinite(const vpArray2D<double> &A)
{
  return std::all_of(A.data, A.data + A.size(), [](double v) { return std::isfinite(v); });
}
