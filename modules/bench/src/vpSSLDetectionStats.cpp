#include <visp3/ssl_harness/vpSSLDetectionStats.h>

#include <cmath>
#include <map>
#include <utility>

#include <visp3/ssl_harness/vpSSLBenchMath.h>

vpSSLDetectionStats::vpSSLDetectionStats()
    : bandFrames(vpSSLBenchMath::bandEdges().size() - 1, 0), bandDetected(vpSSLBenchMath::bandEdges().size() - 1, 0)
{
}

void vpSSLDetectionStats::add(const vpSSLFrameResult &f)
{
  ++nbFrames;
  time.push_back(f.timeMs);
  if (f.falseDetection)
    ++nbFalse;
  if (!f.truthKnown) {
    ++nbUnknown;
    if (f.detected)
      ++nbUnknownDetected;
    return;
  }
  if (!f.hasTarget) {
    ++nbNoTarget;
    return;
  }
  ++nbWithTarget;
  if (f.detected)
    ++nbDetected;
  if (f.detected && !f.orientationKnown)
    ++nbPositionOnly;
  const int b = vpSSLBenchMath::bandIndex(f.range);
  if (b >= 0) {
    ++bandFrames[b];
    if (f.detected)
      ++bandDetected[b];
  }
  detectedRange.push_back(f.range);
  detectedFlag.push_back(f.detected ? 1 : 0);
  centre.push_back(f.centreError);
  position.push_back(f.positionError);
  angle.push_back(f.orientationKnown ? f.angleError : vpSSLBenchMath::nan()); // vpSSLBenchMath::percentile() skips NaN
  range.push_back(f.range);
}

double vpSSLDetectionStats::rate() const
{
  if (nbWithTarget > 0)
    return static_cast<double>(nbDetected) / static_cast<double>(nbWithTarget);
  if (nbUnknown > 0)
    return static_cast<double>(nbUnknownDetected) / static_cast<double>(nbUnknown);
  return vpSSLBenchMath::nan();
}
double vpSSLDetectionStats::bandRate(size_t b) const
{
  return bandFrames[b] ? static_cast<double>(bandDetected[b]) / static_cast<double>(bandFrames[b])
                       : vpSSLBenchMath::nan();
}

double vpSSLDetectionStats::range90(double binWidth, double minRate) const
{
  // Only the bins that hold frames, in order: one far range (1e13 m) must not allocate a bin per 0.5 m.
  std::map<double, std::pair<size_t, size_t>> bins; // bin index -> (frames, detected)
  for (size_t i = 0; i < detectedRange.size(); ++i) {
    if (!std::isfinite(detectedRange[i]) || detectedRange[i] < 0.)
      continue;
    std::pair<size_t, size_t> &b = bins[std::floor(detectedRange[i] / binWidth)];
    ++b.first;
    b.second += detectedFlag[i];
  }
  double best = vpSSLBenchMath::nan();
  for (const auto &kv : bins)
    if (static_cast<double>(kv.second.second) >= minRate * static_cast<double>(kv.second.first) - 1e-12)
      best = (kv.first + 1.) * binWidth;
  return best;
}

void vpSSLDetectionStats::binnedRate(double binWidth, double maxRange, std::vector<double> &x,
                                     std::vector<double> &y) const
{
  const size_t nb = static_cast<size_t>(std::ceil(maxRange / binWidth));
  std::vector<size_t> n(nb, 0), d(nb, 0);
  for (size_t i = 0; i < detectedRange.size(); ++i) {
    if (!std::isfinite(detectedRange[i]) || detectedRange[i] < 0.)
      continue;
    const size_t k = static_cast<size_t>(std::floor(detectedRange[i] / binWidth));
    if (k < nb) {
      ++n[k];
      d[k] += detectedFlag[i];
    }
  }
  x.assign(nb, 0.);
  y.assign(nb, vpSSLBenchMath::nan());
  for (size_t k = 0; k < nb; ++k) {
    x[k] = (static_cast<double>(k) + 0.5) * binWidth;
    if (n[k])
      y[k] = static_cast<double>(d[k]) / static_cast<double>(n[k]);
  }
}

void vpSSLDetectionStats::binnedMedian(const std::vector<double> &values, double binWidth, double maxRange,
                                       std::vector<double> &x, std::vector<double> &y) const
{
  const size_t nb = static_cast<size_t>(std::ceil(maxRange / binWidth));
  std::vector<std::vector<double>> bins(nb);
  for (size_t i = 0; i < range.size(); ++i) {
    if (!std::isfinite(range[i]) || range[i] < 0. || !std::isfinite(values[i]))
      continue;
    const size_t k = static_cast<size_t>(std::floor(range[i] / binWidth));
    if (k < nb)
      bins[k].push_back(values[i]);
  }
  x.assign(nb, 0.);
  y.assign(nb, vpSSLBenchMath::nan());
  for (size_t k = 0; k < nb; ++k) {
    x[k] = (static_cast<double>(k) + 0.5) * binWidth;
    y[k] = vpSSLBenchMath::percentile(bins[k], 50.);
  }
}

void vpSSLDetectionStats::merge(const vpSSLDetectionStats &o)
{
  nbFrames += o.nbFrames;
  nbWithTarget += o.nbWithTarget;
  nbDetected += o.nbDetected;
  nbUnknown += o.nbUnknown;
  nbUnknownDetected += o.nbUnknownDetected;
  nbNoTarget += o.nbNoTarget;
  nbFalse += o.nbFalse;
  nbPositionOnly += o.nbPositionOnly;
  for (size_t b = 0; b < bandFrames.size(); ++b) {
    bandFrames[b] += o.bandFrames[b];
    bandDetected[b] += o.bandDetected[b];
  }
  auto cat = [](std::vector<double> &a, const std::vector<double> &b) { a.insert(a.end(), b.begin(), b.end()); };
  cat(range, o.range);
  cat(centre, o.centre);
  cat(position, o.position);
  cat(angle, o.angle);
  cat(time, o.time);
  cat(detectedRange, o.detectedRange);
  detectedFlag.insert(detectedFlag.end(), o.detectedFlag.begin(), o.detectedFlag.end());
}
