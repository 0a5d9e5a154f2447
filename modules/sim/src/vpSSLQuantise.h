/*
  Private 8-bit quantisation of the simulator's images (vpSSLRenderer's grey image, vpSSLWaterModel's colour one).

  quantise(v) is the grey level static_cast<unsigned char>(clamp(std::round(v), 0, 255)). std::round is a libm call
  on the x86-64 baseline (roundsd needs SSE4.1), once per pixel and channel; in [0, 255) the rounding is done here by
  truncation instead: for 0 <= v < 255, i = (int)v is floor(v), v - i is exact (i and v are within the same or a
  smaller binade) and rounding half away from zero is i + 1 exactly when v - i >= 0.5. Outside that range the clamp
  decides alone: v >= 255 rounds to 255 or more, v < 0 to 0 or less (-0 included), both of which the clamp maps to the
  same byte. NaN, for which the cast of std::round's result is undefined, is 0 (black, the byte x86-64's conversion
  gave).
*/
#ifndef VP_SSL_QUANTISE_H
#define VP_SSL_QUANTISE_H

namespace vpSSLQuantise {
//! static_cast<unsigned char>(clamp(std::round(v), 0, 255)), without the libm call; 0 for NaN.
inline unsigned char quantise(double v)
{
  if (v >= 0.) {
    if (v < 255.) {
      const int i = static_cast<int>(v);
      return static_cast<unsigned char>(v - i >= 0.5 ? i + 1 : i);
    }
    return 255;
  }
  // v < 0, and NaN.
  return 0;
}
} // namespace vpSSLQuantise

#endif
