#include "vpSSLTargetPrediction.h"

#include <cmath>

double vpSSLTargetPrediction::rotationTo(const vpSSLLandmark &detection, size_t l) const
{
  // The detection's offset rectified (in metres of the target, up to the scale) against the printed offset.
  const vpSSLTargetLandmark &k = m_target.getLandmark(m_k), &m = m_target.getLandmark(l);
  const double du = detection.u - m_anchor.u, dv = detection.v - m_anchor.v;
  const double wx = m_map.inv[0][0] * du + m_map.inv[0][1] * dv, wy = m_map.inv[1][0] * du + m_map.inv[1][1] * dv;
  return std::atan2(wy, wx) - std::atan2(m.y - k.y, m.x - k.x);
}

double vpSSLTargetPrediction::distanceRatio(const vpSSLLandmark &detection, size_t l) const
{
  const vpSSLTargetLandmark &k = m_target.getLandmark(m_k), &m = m_target.getLandmark(l);
  const double du = detection.u - m_anchor.u, dv = detection.v - m_anchor.v;
  const double wx = m_map.inv[0][0] * du + m_map.inv[0][1] * dv, wy = m_map.inv[1][0] * du + m_map.inv[1][1] * dv;
  return std::hypot(wx, wy) * k.radius / std::hypot(m.x - k.x, m.y - k.y);
}

vpSSLLandmark vpSSLTargetPrediction::predict(size_t j, double phi) const
{
  const vpSSLTargetLandmark &k = m_target.getLandmark(m_k), &m = m_target.getLandmark(j);
  // The printed offset in units of the anchor's radius, turned by phi, then through the ellipse's map.
  const double ox = (m.x - k.x) / k.radius, oy = (m.y - k.y) / k.radius;
  const double c = std::cos(phi), s = std::sin(phi);
  const double rx = c * ox - s * oy, ry = s * ox + c * oy;
  vpSSLLandmark p;
  p.u = m_anchor.u + m_map.m[0][0] * rx + m_map.m[0][1] * ry;
  p.v = m_anchor.v + m_map.m[1][0] * rx + m_map.m[1][1] * ry;
  const double ratio = m.radius / k.radius;
  p.radius = ratio * m_anchor.radius;
  p.minorRadius = ratio * (m_anchor.minorRadius > 0. ? m_anchor.minorRadius : m_anchor.radius);
  p.theta = m_anchor.theta;
  return p;
}

double vpSSLTargetPrediction::reach(size_t j) const
{
  const vpSSLTargetLandmark &k = m_target.getLandmark(m_k), &m = m_target.getLandmark(j);
  return std::hypot(m.x - k.x, m.y - k.y) / k.radius * m_anchor.radius;
}
