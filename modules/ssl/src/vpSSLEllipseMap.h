/*
  Private to the library: the affine map of the unit circle onto a landmark's outer ellipse, which rectifies the
  target plane around that landmark (vpSSLTargetIdentifier, vpSSLTargetPrediction).
*/
#ifndef VP_SSL_ELLIPSE_MAP_H
#define VP_SSL_ELLIPSE_MAP_H

#include <cmath>

#include <visp3/ssl/vpSSLLandmark.h>

/*
  The symmetric map m taking the unit circle onto the ellipse of semi-axes radius and minorRadius at theta, and its
  inverse. Undoing it rectifies the target plane locally, up to a rotation and a scale, without changing its
  orientation (its determinant is > 0).
*/
struct vpSSLEllipseMap
{
  double m[2][2];
  double inv[2][2];

  explicit vpSSLEllipseMap(const vpSSLLandmark &l)
  {
    const double a = l.radius, b = l.minorRadius > 0. ? l.minorRadius : l.radius;
    const double c = std::cos(l.theta), s = std::sin(l.theta);
    m[0][0] = a * c * c + b * s * s;
    m[0][1] = (a - b) * c * s;
    m[1][0] = m[0][1];
    m[1][1] = a * s * s + b * c * c;
    const double ia = 1. / a, ib = 1. / b;
    inv[0][0] = ia * c * c + ib * s * s;
    inv[0][1] = (ia - ib) * c * s;
    inv[1][0] = inv[0][1];
    inv[1][1] = ia * s * s + ib * c * c;
  }
  vpSSLEllipseMap() : m{{1., 0.}, {0., 1.}}, inv{{1., 0.}, {0., 1.}} {}
};

#endif
