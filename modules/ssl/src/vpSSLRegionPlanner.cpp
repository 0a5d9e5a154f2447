#include "vpSSLRegionPlanner.h"

#include <cmath>

#include <visp3/core/vpImagePoint.h>

namespace {
double centreU(const vpRect &r)
{
  return r.getLeft() + 0.5 * r.getWidth();
}
double centreV(const vpRect &r)
{
  return r.getTop() + 0.5 * r.getHeight();
}
} // namespace

void vpSSLRegionPlanner::startFrame()
{
  m_filled.assign(m_rois.size(), 0);
  m_pending.clear();
  m_pendingIndex.clear();
  m_map.clear();
}

const vpSSLLandmark *vpSSLRegionPlanner::previousNear(double u, double v) const
{
  // Within half its smaller semi-axis: the same landmark, not a neighbour (landmarks do not overlap).
  const vpSSLLandmark *nearest = nullptr;
  double nearestDistance = 0.;
  for (const vpSSLLandmark &k : m_previous) {
    const double d = std::hypot(k.u - u, k.v - v);
    if (d < 0.5 * k.minorRadius && (nearest == nullptr || d < nearestDistance)) {
      nearest = &k;
      nearestDistance = d;
    }
  }
  return nearest;
}

void vpSSLRegionPlanner::fillNearest(double u, double v)
{
  size_t filled = m_rois.size();
  double nearestDistance = 0.;
  for (size_t k = 0; k < m_rois.size(); ++k) {
    const vpRect &r = m_rois[k];
    const double d = std::hypot(centreU(r) - u, centreV(r) - v);
    if (r.isInside(vpImagePoint(v, u)) && (filled == m_rois.size() || d < nearestDistance)) {
      filled = k;
      nearestDistance = d;
    }
  }
  if (filled < m_rois.size()) {
    m_filled[filled] = 1;
  }
}

bool vpSSLRegionPlanner::isOpen(double u, double v) const
{
  for (size_t k = 0; k < m_rois.size(); ++k) {
    if (!m_filled[k] && m_rois[k].isInside(vpImagePoint(v, u))) {
      return true;
    }
  }
  return false;
}

void vpSSLRegionPlanner::defer(size_t k)
{
  m_pending.push_back(m_rois[k]);
  m_pendingIndex.push_back(k);
}

void vpSSLRegionPlanner::splitByResolution(double minRadius)
{
  m_coarse.clear();
  m_coarseIndex.clear();
  m_fine.clear();
  for (size_t k = 0; k < m_pending.size(); ++k) {
    if (largeLandmarkIn(m_pending[k], minRadius)) {
      m_coarse.push_back(m_pending[k]);
      m_coarseIndex.push_back(m_pendingIndex[k]);
    } else {
      m_fine.push_back(m_pending[k]);
    }
  }
}

void vpSSLRegionPlanner::refineUnfilledCoarse()
{
  for (size_t k = 0; k < m_coarse.size(); ++k) {
    if (!m_filled[m_coarseIndex[k]]) {
      m_fine.push_back(m_coarse[k]);
    }
  }
}

bool vpSSLRegionPlanner::largeLandmarkIn(const vpRect &r, double minRadius) const
{
  // The landmark of the previous frame inside the region and nearest its centre: the one the region predicts. One
  // that shrank below minRadius since, or that the decimated pass misses, is matched again at full resolution.
  const double cu = centreU(r), cv = centreV(r);
  const vpSSLLandmark *nearest = nullptr;
  double nearestDistance = 0.;
  for (const vpSSLLandmark &k : m_previous) {
    const double d = std::hypot(k.u - cu, k.v - cv);
    if (r.isInside(vpImagePoint(k.v, k.u)) && (nearest == nullptr || d < nearestDistance)) {
      nearest = &k;
      nearestDistance = d;
    }
  }
  return nearest != nullptr && nearest->minorRadius >= minRadius;
}
