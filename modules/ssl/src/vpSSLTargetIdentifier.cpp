#include <visp3/ssl/vpSSLTargetIdentifier.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include <visp3/core/vpException.h>

#include "vpSSLEllipseMap.h"

namespace {
// identify()'s buffers, reused from call to call so that it does not allocate once they have grown.
struct IdentifyScratch
{
  std::vector<vpSSLEllipseMap> maps;
  std::vector<int> hypDetection; // target-landmark labels, K per hypothesis
  std::vector<unsigned int> hypCount;
  std::vector<double> hypResidual;
  std::vector<double> hypRotation; // rotation of the target in the rectified image, in (-pi, pi]
  std::vector<char> hypBlocked;    // an unmatched landmark's place holds a detection of another size
};

// One per thread: identify() is const, and const methods of the library are safe to call concurrently.
IdentifyScratch &identifyScratch()
{
  thread_local IdentifyScratch s;
  return s;
}
} // namespace

vpSSLTargetIdentifier::vpSSLTargetIdentifier(const vpSSLTarget &target)
    : m_target(target), m_radiusTol(0.35), m_distanceTol(0.25), m_big(-1)
{
  if (m_target.size() == 0) {
    throw vpException(vpException::badValue, "vpSSLTargetIdentifier: target \"%s\" has no landmark",
                      m_target.getName().c_str());
  }
  double biggest = -1.;
  for (size_t k = 0; k < m_target.size(); ++k) {
    if (m_target.getLandmark(k).radius > biggest) {
      biggest = m_target.getLandmark(k).radius;
      m_big = static_cast<int>(k);
    }
  }
}

vpSSLTargetMatch vpSSLTargetIdentifier::identify(const std::vector<vpSSLLandmark> &landmarks) const
{
  vpSSLTargetMatch result;
  identify(landmarks, result);
  return result;
}

void vpSSLTargetIdentifier::identify(const std::vector<vpSSLLandmark> &landmarks, vpSSLTargetMatch &result) const
{
  const size_t K = m_target.size(), N = landmarks.size();
  result.found = false;
  result.nbMatched = 0;
  result.residual = 0.;
  result.detection.assign(K, -1);
  if (N == 0) {
    return;
  }
  IdentifyScratch &scratch = identifyScratch();
  std::vector<vpSSLEllipseMap> &maps = scratch.maps;
  maps.resize(N);
  for (size_t i = 0; i < N; ++i) {
    maps[i] = vpSSLEllipseMap(landmarks[i]);
  }
  const std::vector<vpSSLTargetLandmark> &model = m_target.getLandmarks();

  std::vector<int> &hypDetection = scratch.hypDetection; // K labels per hypothesis
  std::vector<unsigned int> &hypCount = scratch.hypCount;
  std::vector<double> &hypResidual = scratch.hypResidual;
  std::vector<double> &hypRotation = scratch.hypRotation;
  std::vector<char> &hypBlocked = scratch.hypBlocked;
  hypDetection.clear();
  hypCount.clear();
  hypResidual.clear();
  hypRotation.clear();
  hypBlocked.clear();
  for (size_t i = 0; i < N; ++i) {
    for (size_t k = 0; k < K; ++k) {
      for (size_t j = 0; j < N; ++j) {
        if (j == i) {
          continue;
        }
        for (size_t l = 0; l < K; ++l) {
          if (l == k) {
            continue;
          }
          // The anchor i is the larger of the two in the model, so its ellipse rectifies best.
          if (model[k].radius < model[l].radius) {
            continue;
          }
          const double ratio = (landmarks[j].radius / landmarks[i].radius) / (model[l].radius / model[k].radius);
          if (ratio < 1. - m_radiusTol || ratio > 1. / (1. - m_radiusTol)) {
            continue;
          }
          // Offset of j from i, rectified and in metres of the model.
          const double du = landmarks[j].u - landmarks[i].u, dv = landmarks[j].v - landmarks[i].v;
          const double wx = model[k].radius * (maps[i].inv[0][0] * du + maps[i].inv[0][1] * dv);
          const double wy = model[k].radius * (maps[i].inv[1][0] * du + maps[i].inv[1][1] * dv);
          const double mx = model[l].x - model[k].x, my = model[l].y - model[k].y;
          const double dw = std::hypot(wx, wy), dm = std::hypot(mx, my);
          if (dm <= 0. || std::fabs(dw / dm - 1.) > m_distanceTol) {
            continue;
          }
          // Rotation and scale taking model offsets to rectified image offsets.
          const double phi = std::atan2(wy, wx) - std::atan2(my, mx);
          const double scale = dw / dm / model[k].radius; // rectified radii per metre
          const double cphi = std::cos(phi) * scale, sphi = std::sin(phi) * scale;
          const size_t base = hypDetection.size();
          hypDetection.resize(base + K, -1);
          int *detection = &hypDetection[base];
          detection[k] = static_cast<int>(i);
          detection[l] = static_cast<int>(j);
          unsigned int nbMatched = 2;
          bool blocked = false;
          double residual = std::fabs(dw / dm - 1.);
          for (size_t m = 0; m < K; ++m) {
            if (m == k || m == l) {
              continue;
            }
            const double ox = model[m].x - model[k].x, oy = model[m].y - model[k].y;
            const double rx = cphi * ox - sphi * oy, ry = sphi * ox + cphi * oy;
            const double pu = landmarks[i].u + maps[i].m[0][0] * rx + maps[i].m[0][1] * ry;
            const double pv = landmarks[i].v + maps[i].m[1][0] * rx + maps[i].m[1][1] * ry;
            const double reach = std::hypot(pu - landmarks[i].u, pv - landmarks[i].v);
            const double expectedRadius = landmarks[i].radius * model[m].radius / model[k].radius;
            int bestJ = -1;
            double bestE = m_distanceTol;
            bool otherSize = false;
            for (size_t jj = 0; jj < N; ++jj) {
              if (jj == i || jj == j) {
                continue;
              }
              const double e = std::hypot(landmarks[jj].u - pu, landmarks[jj].v - pv) / std::max(reach, 1.);
              const double rr = landmarks[jj].radius / expectedRadius;
              if (rr < 1. - m_radiusTol || rr > 1. / (1. - m_radiusTol)) {
                otherSize = otherSize || e < m_distanceTol;
                continue;
              }
              if (e < bestE) {
                bestE = e;
                bestJ = static_cast<int>(jj);
              }
            }
            if (bestJ >= 0) {
              detection[m] = bestJ;
              ++nbMatched;
              residual += bestE;
            } else {
              blocked = blocked || otherSize;
            }
          }
          hypCount.push_back(nbMatched);
          hypResidual.push_back(residual / (nbMatched - 1));
          hypRotation.push_back(std::remainder(phi, 2. * M_PI));
          hypBlocked.push_back(blocked ? 1 : 0);
        }
      }
    }
  }

  const size_t H = hypCount.size();
  unsigned int bestCount = 0;
  for (size_t h = 0; h < H; ++h) {
    bestCount = std::max(bestCount, hypCount[h]);
  }
  if (bestCount >= 2) {
    // Keep only the labels that every equally complete hypothesis agrees on: two landmarks of a symmetric
    // target cannot be told apart (paper Sec. 3.2, case 2).
    size_t best = H;
    for (size_t h = 0; h < H; ++h) {
      if (hypCount[h] == bestCount && (best == H || hypResidual[h] < hypResidual[best])) {
        best = h;
      }
    }
    const double residual = hypResidual[best];
    std::vector<int> &agreed = result.detection;
    std::copy(hypDetection.begin() + best * K, hypDetection.begin() + (best + 1) * K, agreed.begin());
    for (size_t h = 0; h < H; ++h) {
      if (hypCount[h] != bestCount || hypResidual[h] > residual + 0.1) {
        continue;
      }
      for (size_t k = 0; k < K; ++k) {
        if (agreed[k] != hypDetection[h * K + k]) {
          agreed[k] = -1;
        }
      }
    }
    unsigned int n = 0;
    for (size_t k = 0; k < K; ++k) {
      n += agreed[k] >= 0 ? 1 : 0;
    }
    if (agreed[m_big] >= 0 && n > 0) {
      result.found = true;
      result.nbMatched = n;
      result.residual = residual;
      return;
    }
    // No equally complete hypothesis puts the big landmark among the detections: they are smaller landmarks of
    // the target, and taking the biggest of them for the big one (case 1) would misread the range by the ratio of
    // their radii. When their labels are ambiguous (two landmarks of equal size, S1 and S2 of ssl3-a3, swap under a
    // half turn), the target is taken the right way up: the hypothesis with the least rotation in the image. A
    // detection of another size where a hypothesis puts a landmark it did not match (the big one read at one of
    // its inner copies, or three equal circles) leaves the reading to case 1.
    bool bigSeen = false;
    size_t upright = best;
    for (size_t h = 0; h < H; ++h) {
      if (hypCount[h] != bestCount) {
        continue;
      }
      // Any equally complete reading with the big landmark, however good its fit, leaves the doubt.
      bigSeen = bigSeen || hypDetection[h * K + m_big] >= 0 || hypBlocked[h] != 0;
      if (hypResidual[h] <= residual + 0.1 && std::fabs(hypRotation[h]) < std::fabs(hypRotation[upright])) {
        upright = h;
      }
    }
    // A detection bigger than every one the hypothesis labels may be the big landmark that the geometry missed
    // (its ellipse or a neighbour's read at another size): case 1 takes it for the big one.
    double labelledMax = 0., seenMax = 0.;
    for (size_t k = 0; k < K; ++k) {
      const int d = hypDetection[upright * K + k];
      labelledMax = d >= 0 ? std::max(labelledMax, landmarks[static_cast<size_t>(d)].radius) : labelledMax;
    }
    for (const vpSSLLandmark &l : landmarks) {
      seenMax = std::max(seenMax, l.radius);
    }
    if (!bigSeen && seenMax <= labelledMax) {
      std::copy(hypDetection.begin() + upright * K, hypDetection.begin() + (upright + 1) * K, agreed.begin());
      result.found = true;
      result.nbMatched = bestCount;
      result.residual = hypResidual[upright];
      return;
    }
    std::fill(agreed.begin(), agreed.end(), -1);
  }
  // Case 1 (and case 2 when the labels stay ambiguous): the biggest landmark seen stands for the big one.
  size_t biggest = 0;
  for (size_t i = 1; i < N; ++i) {
    if (landmarks[i].radius > landmarks[biggest].radius) {
      biggest = i;
    }
  }
  result.found = true;
  result.nbMatched = 1;
  result.detection[m_big] = static_cast<int>(biggest);
}
