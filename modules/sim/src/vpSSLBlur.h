/*
  Private forward-scatter blur of vpSSLWaterModel: a separable Gaussian blur of a float plane added to an image, on
  the box where the plane is not zero (a landmark sheet, a patch of surface) rather than on the whole frame.
*/
#ifndef VP_SSL_BLUR_H
#define VP_SSL_BLUR_H

#include <algorithm>
#include <cmath>
#include <vector>

namespace vpSSLBlur {
// Adds to out (w x h) the separable Gaussian blur of the plane (w x h), borders replicated: each output pixel is
// sum_i k_i plane[clamp(.)] over the taps i ascending, summed from 0 in float, across then down. Only the box of the
// pixels that are not zero, widened by the blur's radius, is blurred and added: elsewhere every tap is +-0, the blur
// +0, and out + 0 is out (out is never -0: the backscatter it starts from is a product of non-negative factors).
// tmp is the caller's scratch, reused from one call to the next.
inline void addBlurred(const std::vector<float> &plane, unsigned int w, unsigned int h, double sigma,
                       std::vector<float> &tmp, float *out)
{
  const int W = static_cast<int>(w), H = static_cast<int>(h);
  int bx0 = W, bx1 = 0, by0 = H, by1 = 0;
  for (int y = 0; y < H; ++y) {
    const float *row = &plane[static_cast<size_t>(y) * w];
    int x0 = 0;
    while (x0 < W && row[x0] == 0.f) {
      ++x0;
    }
    if (x0 == W) {
      continue;
    }
    int x1 = W;
    while (row[x1 - 1] == 0.f) {
      --x1;
    }
    bx0 = std::min(bx0, x0);
    bx1 = std::max(bx1, x1);
    by0 = std::min(by0, y);
    by1 = y + 1;
  }
  if (bx0 >= bx1) {
    return;
  }
  if (sigma <= 0.) {
    for (int y = by0; y < by1; ++y) {
      for (int x = bx0; x < bx1; ++x) {
        out[static_cast<size_t>(y) * w + x] += plane[static_cast<size_t>(y) * w + x];
      }
    }
    return;
  }
  const int r = static_cast<int>(std::ceil(3. * sigma));
  std::vector<float> k(2 * r + 1);
  double sum = 0.;
  for (int i = -r; i <= r; ++i) {
    k[i + r] = static_cast<float>(std::exp(-0.5 * i * i / (sigma * sigma)));
    sum += k[i + r];
  }
  for (float &x : k) {
    x = static_cast<float>(x / sum);
  }
  // Across, on the box's rows, for its columns widened by r: the taps are the outer loop and the pixels the inner
  // one (so that the pixels vectorise), the border clamp left to the columns within r of the image's ends.
  const int ex0 = std::max(bx0 - r, 0), ex1 = std::min(bx1 + r, W), ew = ex1 - ex0;
  const int in0 = std::min(std::max(ex0, r), ex1), in1 = std::max(in0, std::min(ex1, W - r));
  tmp.resize(static_cast<size_t>(by1 - by0) * ew);
#pragma omp parallel for schedule(static)
  for (int y = by0; y < by1; ++y) {
    const float *row = &plane[static_cast<size_t>(y) * w];
    float *t = &tmp[static_cast<size_t>(y - by0) * ew] - ex0;
    std::fill(t + ex0, t + ex1, 0.f);
    for (int i = -r; i <= r; ++i) {
      const float ki = k[i + r];
      for (int x = ex0; x < in0; ++x) {
        t[x] += ki * row[std::min(std::max(x + i, 0), W - 1)];
      }
      for (int x = in0; x < in1; ++x) {
        t[x] += ki * row[x + i];
      }
      for (int x = in1; x < ex1; ++x) {
        t[x] += ki * row[std::min(std::max(x + i, 0), W - 1)];
      }
    }
  }
  // Down, on the box's rows widened by r: the rows outside the box blur to +0 across and are left out.
  const int ey0 = std::max(by0 - r, 0), ey1 = std::min(by1 + r, H);
#pragma omp parallel
  {
    // One row's sums, per thread.
    std::vector<float> a(ew);
#pragma omp for schedule(static)
    for (int y = ey0; y < ey1; ++y) {
      std::fill(a.begin(), a.end(), 0.f);
      for (int i = -r; i <= r; ++i) {
        const int yy = std::min(std::max(y + i, 0), H - 1);
        if (yy < by0 || yy >= by1) {
          continue;
        }
        const float ki = k[i + r];
        const float *src = &tmp[static_cast<size_t>(yy - by0) * ew];
        for (int x = 0; x < ew; ++x) {
          a[x] += ki * src[x];
        }
      }
      float *dst = out + static_cast<size_t>(y) * w + ex0;
      for (int x = 0; x < ew; ++x) {
        dst[x] += a[x];
      }
    }
  }
}

} // namespace vpSSLBlur

#endif
