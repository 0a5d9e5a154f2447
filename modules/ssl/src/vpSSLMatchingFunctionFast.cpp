/*
  Fast matching function: the SIMD kernel of vpSSLMatchingKernel.cpp driven over spans of rows, split
  across threads, for the whole image or for regions of interest. Every pixel is computed independently with
  integer arithmetic, so the map is the same as computeReference() whatever the target or the thread count.
*/
#include <visp3/ssl/vpSSLMatchingFunction.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>

#include <visp3/core/vpException.h>

#include "vpSSLImageCheck.h"
#include "vpSSLMatchingKernel.h"
#include "vpSSLMatchingKernelThreads.h"

namespace {
namespace kernel = vpSSLMatchingKernel;

// Half-open pixel rectangle [u0, u1) x [v0, v1).
struct Box
{
  int u0, v0, u1, v1;
};

// Pixels [u0, u1) of row v.
struct Span
{
  int v, u0, u1;
};

constexpr std::align_val_t kAlign{64}; // a cache line, an AVX-512 vector

struct AlignedFree
{
  void operator()(uint8_t *p) const { ::operator delete(p, kAlign); }
};

/*
  Buffers reused from call to call (per calling thread, so that concurrent calls on one const object stay safe):
  after the first frame of a given size nothing is allocated.
*/
struct Scratch
{
  std::unique_ptr<uint8_t, AlignedFree> padded;
  std::size_t paddedCapacity = 0;
  std::vector<Box> boxes;
  std::vector<int> rowFirst;    // merged intervals of row v: intervals[rowFirst[v] .. rowFirst[v + 1])
  std::vector<Span> intervals;  // merged intervals, row by row
  std::vector<Span> rowScratch; // intervals of one row before merging
  std::vector<int> order;       // boxes by first row
  std::vector<int> active;      // boxes that cover the current row
  std::vector<int> cursor;      // next column of each interval to cut into spans
  std::vector<Span> match, copy, zero;
};

Scratch &scratch()
{
  thread_local Scratch s;
  return s;
}

uint8_t *ensurePadded(Scratch &s, std::size_t size)
{
  if (s.paddedCapacity < size) {
    // 64-byte rows for AVX-512; zeroed so that the padding the masked lanes read is initialised.
    s.padded.reset();
    s.paddedCapacity = 0;
    try {
      s.padded.reset(static_cast<uint8_t *>(::operator new(size, kAlign)));
    } catch (const std::bad_alloc &) {
      throw vpException(vpException::memoryAllocationError,
                        "vpSSLMatchingFunction: cannot allocate %zu bytes for a padded copy of the image", size);
    }
    std::memset(s.padded.get(), 0, size);
    s.paddedCapacity = size;
  }
  return s.padded.get();
}

/*
  Columns of one strip: the 2w + 1 rows a strip reads (for the vertical directions) stay within about 24 KB, i.e.
  in L1, while the strip moves down the image. A multiple of 128 keeps whole blocks of vectors inside a strip.
*/
int stripWidth(int window)
{
  return std::max(128, 24 * 1024 / (2 * window + 1) / 128 * 128);
}

// Merged union of the boxes (grown by `grow` pixels on each side, clipped to the image) for every row. The boxes
// are swept by their first row, so that each row looks only at the boxes that cover it: a full search matches up to
// a few hundred candidate tiles.
void mergeRows(Scratch &s, int W, int H, int grow)
{
  s.rowFirst.assign(static_cast<std::size_t>(H) + 1, 0);
  s.intervals.clear();
  s.order.resize(s.boxes.size());
  for (std::size_t k = 0; k < s.boxes.size(); ++k) {
    s.order[k] = static_cast<int>(k);
  }
  std::sort(s.order.begin(), s.order.end(),
            [&s](int a, int b) { return s.boxes[a].v0 < s.boxes[b].v0 || (s.boxes[a].v0 == s.boxes[b].v0 && a < b); });
  s.active.clear();
  std::size_t next = 0;
  for (int v = 0; v < H; ++v) {
    s.rowFirst[v] = static_cast<int>(s.intervals.size());
    bool changed = v == 0;
    while (next < s.order.size() && s.boxes[s.order[next]].v0 - grow <= v) {
      s.active.push_back(s.order[next++]);
      changed = true;
    }
    for (std::size_t k = 0; k < s.active.size();) {
      if (v >= s.boxes[s.active[k]].v1 + grow) {
        s.active[k] = s.active.back(); // below the box: it covers no later row
        s.active.pop_back();
        changed = true;
      } else {
        ++k;
      }
    }
    if (!changed) {
      // The same boxes as the row above: the same intervals.
      const int first = s.rowFirst[v - 1], last = s.rowFirst[v];
      for (int k = first; k < last; ++k) {
        const Span r = s.intervals[static_cast<std::size_t>(k)];
        s.intervals.push_back({v, r.u0, r.u1});
      }
      continue;
    }
    s.rowScratch.clear();
    for (const int k : s.active) {
      const Box &b = s.boxes[static_cast<std::size_t>(k)];
      s.rowScratch.push_back({v, std::max(0, b.u0 - grow), std::min(W, b.u1 + grow)});
    }
    // The union does not depend on the order of spans that start at the same column.
    if (s.rowScratch.size() > 1) {
      std::sort(s.rowScratch.begin(), s.rowScratch.end(), [](const Span &a, const Span &b) { return a.u0 < b.u0; });
    }
    for (const Span &r : s.rowScratch) {
      if (s.intervals.size() > static_cast<std::size_t>(s.rowFirst[v]) && r.u0 <= s.intervals.back().u1) {
        s.intervals.back().u1 = std::max(s.intervals.back().u1, r.u1);
      } else {
        s.intervals.push_back(r);
      }
    }
  }
  s.rowFirst[H] = static_cast<int>(s.intervals.size());
}

/*
  M inside the boxes of s.boxes (already clipped, non-empty), 0 elsewhere. The pixels each box's matching reads
  (the box grown by w, clipped) are copied into the padded image first; overlapping boxes are merged row by row
  so that every pixel is computed once.
*/
void run(const vpSSLMatchingFunction &f, const vpImage<unsigned char> &I, vpImage<int> &M, Scratch &s,
         bool clearOutside = true)
{
  const int W = static_cast<int>(I.getWidth()), H = static_cast<int>(I.getHeight());
  const int w = static_cast<int>(f.getWindow());

  kernel::Params P;
  P.stride = kernel::paddedStride(W, w);
  uint8_t *padded = ensurePadded(s, kernel::paddedSize(W, H, w)) + kernel::leftPad(w);
  P.pixels = padded;
  P.width = W;
  P.height = H;
  P.window = w;
  P.out = M.bitmap;
  const std::ptrdiff_t steps[4] = {1, -1, P.stride, -P.stride}; // vpSSLDirection order
  for (int xi = 0; xi <= w; ++xi) {
    const int a = f.offsetSqrtP(static_cast<unsigned int>(xi)), b = f.offsetP(static_cast<unsigned int>(xi));
    for (int dir = 0; dir < 4; ++dir) {
      P.offsets[dir][xi][0] = xi * steps[dir];
      P.offsets[dir][xi][1] = a * steps[dir];
      P.offsets[dir][xi][2] = b * steps[dir];
    }
  }

  // Pixels to copy: the boxes grown by the window.
  mergeRows(s, W, H, w);
  s.copy.assign(s.intervals.begin(), s.intervals.end());

  // Pixels to match, in strips of columns measured from the start of each interval (so that a region of
  // interest narrower than a strip stays one span), strip-major so that consecutive spans share their rows in
  // cache; and the rest of M, to clear.
  mergeRows(s, W, H, 0);
  s.match.clear();
  s.zero.clear();
  const int strip = stripWidth(w);
  s.cursor.resize(s.intervals.size());
  for (std::size_t k = 0; k < s.intervals.size(); ++k) {
    s.cursor[k] = s.intervals[k].u0;
  }
  for (bool more = true; more;) {
    more = false;
    for (int v = 0; v < H; ++v) {
      for (int k = s.rowFirst[v]; k < s.rowFirst[v + 1]; ++k) {
        const int a = s.cursor[k], b = std::min(s.intervals[k].u1, a + strip);
        if (a < b) {
          s.match.push_back({v, a, b});
          s.cursor[k] = b;
          more = more || b < s.intervals[k].u1;
        }
      }
    }
  }
  for (int v = 0; v < H && clearOutside; ++v) {
    int u = 0;
    for (int k = s.rowFirst[v]; k < s.rowFirst[v + 1]; ++k) {
      if (s.intervals[k].u0 > u) {
        s.zero.push_back({v, u, s.intervals[k].u0});
      }
      u = s.intervals[k].u1;
    }
    if (u < W) {
      s.zero.push_back({v, u, W});
    }
  }

  // Every pixel depends on its own neighbourhood only, so any split gives the same map. Tasks of a few rows of a
  // strip keep a thread's rows in its cache.
  long long work = 0;
  for (const Span &r : s.match) {
    work += r.u1 - r.u0;
  }
  // Below about 2^18 pixel-terms (a few microseconds) waking a worker costs more than it saves.
  const unsigned int threads =
      work * w < (1 << 18) ? 1u : (f.getNbThreads() > 0 ? f.getNbThreads() : kernel::hardwareThreads());
  const int nCopy = static_cast<int>(s.copy.size()), nMatch = static_cast<int>(s.match.size()),
            nZero = static_cast<int>(s.zero.size());
  constexpr int kCopyTask = 64, kMatchTask = 8;
  const Span *copy = s.copy.data(), *match = s.match.data(), *zero = s.zero.data();
  const unsigned char *image = I.bitmap;
  int32_t *out = M.bitmap;
  // The copy (a memcpy per row, tens of microseconds) stays on the calling thread: a job of its own would cost a
  // second wake-up of the workers.
  for (int i = 0; i < nCopy; ++i) {
    std::memcpy(padded + copy[i].v * P.stride + copy[i].u0,
                image + static_cast<std::ptrdiff_t>(copy[i].v) * W + copy[i].u0,
                static_cast<std::size_t>(copy[i].u1 - copy[i].u0));
  }
  // The cleared pixels and the matched ones are disjoint: one job does both.
  const int matchTasks = (nMatch + kMatchTask - 1) / kMatchTask, zeroTasks = (nZero + kCopyTask - 1) / kCopyTask;
  kernel::parallelFor(matchTasks + zeroTasks, threads, [&](int task) {
    if (task < matchTasks) {
      for (int i = task * kMatchTask; i < std::min(nMatch, (task + 1) * kMatchTask); ++i) {
        kernel::matchSpan(P, match[i].v, match[i].u0, match[i].u1);
      }
    } else {
      task -= matchTasks;
      for (int i = task * kCopyTask; i < std::min(nZero, (task + 1) * kCopyTask); ++i) {
        std::fill(out + static_cast<std::ptrdiff_t>(zero[i].v) * W + zero[i].u0,
                  out + static_cast<std::ptrdiff_t>(zero[i].v) * W + zero[i].u1, 0);
      }
    }
  });
}
} // namespace

void vpSSLMatchingFunction::compute(const vpImage<unsigned char> &I, vpImage<int> &M) const
{
  vpSSLImageCheck::kernel(I, "vpSSLMatchingFunction::compute");
  M.resize(I.getHeight(), I.getWidth());
  if (I.getSize() == 0) {
    return;
  }
  Scratch &s = scratch();
  s.boxes.assign(1, {0, 0, static_cast<int>(I.getWidth()), static_cast<int>(I.getHeight())});
  run(*this, I, M, s);
}

void vpSSLMatchingFunction::compute(const vpImage<unsigned char> &I, const std::vector<vpRect> &rois,
                                    vpImage<int> &M) const
{
  computeRegions(I, rois, M, true);
}

void vpSSLMatchingFunction::computeInside(const vpImage<unsigned char> &I, const std::vector<vpRect> &rois,
                                          vpImage<int> &M) const
{
  vpSSLImageCheck::kernel(I, "vpSSLMatchingFunction::computeInside");
  vpSSLImageCheck::consistent(M, "vpSSLMatchingFunction::computeInside: map");
  if (M.getHeight() != I.getHeight() || M.getWidth() != I.getWidth()) {
    M.resize(I.getHeight(), I.getWidth());
    std::fill(M.bitmap, M.bitmap + M.getSize(), 0);
  }
  computeRegions(I, rois, M, false);
}

void vpSSLMatchingFunction::computeRegions(const vpImage<unsigned char> &I, const std::vector<vpRect> &rois,
                                           vpImage<int> &M, bool clearOutside) const
{
  vpSSLImageCheck::kernel(I, "vpSSLMatchingFunction::compute");
  M.resize(I.getHeight(), I.getWidth());
  if (I.getSize() == 0) {
    return;
  }
  const double W = I.getWidth(), H = I.getHeight();
  Scratch &s = scratch();
  s.boxes.clear();
  for (std::size_t k = 0; k < rois.size(); ++k) {
    const vpRect &r = rois[k];
    if (!std::isfinite(r.getLeft()) || !std::isfinite(r.getTop()) || !std::isfinite(r.getWidth()) ||
        !std::isfinite(r.getHeight())) {
      throw vpException(vpException::badValue,
                        "vpSSLMatchingFunction::compute: region of interest %zu has a non-finite coordinate", k);
    }
    // vpRect spans the pixels left .. getRight() inclusive; clip in double before converting to int.
    const double u0 = std::ceil(std::max(0., r.getLeft())), v0 = std::ceil(std::max(0., r.getTop()));
    const double u1 = std::floor(std::min(W - 1., r.getRight())), v1 = std::floor(std::min(H - 1., r.getBottom()));
    if (u0 <= u1 && v0 <= v1) {
      s.boxes.push_back(
          {static_cast<int>(u0), static_cast<int>(v0), static_cast<int>(u1) + 1, static_cast<int>(v1) + 1});
    }
  }
  run(*this, I, M, s, clearOutside);
}

std::string vpSSLMatchingFunction::getSimdTarget()
{
  return vpSSLMatchingKernel::targetName();
}
