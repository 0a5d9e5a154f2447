/*
  The matching function alone (paper Eq. 3 and 5, no peak finding): the plain reference against the SIMD kernel,
  full frames at 640x480 and 1920x1080 on one thread and on all of them, three 100x100 regions of interest at
  640x480, and the 640x480 frame on every SIMD target compiled in. The frames hold rings in the ratio p, like a
  rendered landmark; the kernel does the same work whatever the pixels.

    ./bench-matching --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

  Figures and their reading: doc/kernel.md.
*/
#include <cmath>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <hwy/targets.h>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRect.h>
#include <visp3/core/vpUniRand.h>
#include <visp3/ssl/vpSSLMatchingFunction.h>

namespace {
const unsigned int kWindow = 40; // the paper's window
const double kP = 0.5;

// Rings of radii in ratio p around a point off the centre, with noise.
vpImage<unsigned char> ringFrame(unsigned int width, unsigned int height)
{
  vpImage<unsigned char> I(height, width);
  vpUniRand rng(42);
  const double cu = 0.4 * width, cv = 0.55 * height, r0 = 0.3 * height;
  for (unsigned int v = 0; v < height; ++v) {
    for (unsigned int u = 0; u < width; ++u) {
      const double r = std::hypot(u - cu, v - cv) + 0.5;
      const int ring = static_cast<int>(std::floor(std::log(r / r0) / std::log(kP)));
      I[v][u] = static_cast<unsigned char>((ring % 2 == 0 ? 210 : 40) + rng.uniform(-15, 16));
    }
  }
  return I;
}

// Throughput counters: pixels per second and "pixel-terms" (pixel x valid direction x xi) per nanosecond.
void setCounters(benchmark::State &state, unsigned int width, unsigned int height, long long pixels)
{
  const long long w = kWindow;
  long long terms = 0;
  for (long long v = 0; v < height; ++v) {
    terms += (v + w < height) + (v >= w);
  }
  terms = terms * width + 2LL * height * std::max(0LL, static_cast<long long>(width) - w);
  terms = terms * w * pixels / (static_cast<long long>(width) * height);
  state.counters["px/s"] =
      benchmark::Counter(static_cast<double>(pixels), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["terms/ns"] =
      benchmark::Counter(static_cast<double>(terms) * 1e-9, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_Reference(benchmark::State &state)
{
  const unsigned int width = static_cast<unsigned int>(state.range(0)),
                     height = static_cast<unsigned int>(state.range(1));
  const vpImage<unsigned char> I = ringFrame(width, height);
  const vpSSLMatchingFunction f(kWindow, kP);
  vpImage<int> M;
  for (auto _ : state) {
    f.computeReference(I, M);
    benchmark::DoNotOptimize(M.bitmap);
  }
  setCounters(state, width, height, static_cast<long long>(width) * height);
}

// range(2): thread count, 0 = all cores.
void BM_Fast(benchmark::State &state)
{
  const unsigned int width = static_cast<unsigned int>(state.range(0)),
                     height = static_cast<unsigned int>(state.range(1));
  const vpImage<unsigned char> I = ringFrame(width, height);
  vpSSLMatchingFunction f(kWindow, kP);
  f.setNbThreads(static_cast<unsigned int>(state.range(2)));
  vpImage<int> M;
  for (auto _ : state) {
    f.compute(I, M);
    benchmark::DoNotOptimize(M.bitmap);
  }
  setCounters(state, width, height, static_cast<long long>(width) * height);
}

// Three 100x100 regions around predicted landmarks, the rest of the 640x480 map cleared.
void BM_FastRoi(benchmark::State &state)
{
  const vpImage<unsigned char> I = ringFrame(640, 480);
  vpSSLMatchingFunction f(kWindow, kP);
  f.setNbThreads(static_cast<unsigned int>(state.range(0)));
  const std::vector<vpRect> rois = {vpRect(70, 60, 100, 100), vpRect(290, 190, 100, 100), vpRect(480, 330, 100, 100)};
  vpImage<int> M;
  for (auto _ : state) {
    f.compute(I, rois, M);
    benchmark::DoNotOptimize(M.bitmap);
  }
  setCounters(state, 640, 480, 3 * 100 * 100);
}

// One thread on the target range(0) indexes in hwy::SupportedAndGeneratedTargets().
void BM_FastTarget(benchmark::State &state)
{
  const std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
  const size_t k = static_cast<size_t>(state.range(0));
  if (k >= targets.size()) {
    state.SkipWithError("target not available on this CPU");
    return;
  }
  hwy::SetSupportedTargetsForTest(targets[k]);
  state.SetLabel(vpSSLMatchingFunction::getSimdTarget());
  const vpImage<unsigned char> I = ringFrame(640, 480);
  vpSSLMatchingFunction f(kWindow, kP);
  f.setNbThreads(1);
  vpImage<int> M;
  for (auto _ : state) {
    f.compute(I, M);
    benchmark::DoNotOptimize(M.bitmap);
  }
  hwy::SetSupportedTargetsForTest(0);
  setCounters(state, 640, 480, 640LL * 480);
}
} // namespace

BENCHMARK(BM_Reference)->Args({640, 480})->Args({1920, 1080})->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Fast)
    ->ArgsProduct({{640}, {480}, {1, 0}})
    ->ArgsProduct({{1920}, {1080}, {1, 0}})
    ->ArgNames({"width", "height", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_FastRoi)->Arg(1)->Arg(0)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_FastTarget)->DenseRange(0, 4)->ArgName("target")->Unit(benchmark::kMillisecond);

int main(int argc, char **argv)
{
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) {
    return 1;
  }
  benchmark::AddCustomContext("simd_target", vpSSLMatchingFunction::getSimdTarget());
  benchmark::AddCustomContext("window", std::to_string(kWindow));
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
