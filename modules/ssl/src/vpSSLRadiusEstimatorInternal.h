/*
  Shared by vpSSLRadiusEstimator.cpp (ray reading, radius search) and vpSSLRadiusEstimatorGeometry.cpp
  (symmetry centring, ring edges, centre refinement, ellipse fit). Not installed.
*/
#ifndef VP_SSL_RADIUS_ESTIMATOR_INTERNAL_H
#define VP_SSL_RADIUS_ESTIMATOR_INTERNAL_H

#include <cmath>

namespace vpSSLRadiusEstimatorInternal {
// Directions of the eight rays.
const double kCos[8] = {1., M_SQRT1_2, 0., -M_SQRT1_2, -1., -M_SQRT1_2, 0., M_SQRT1_2};
const double kSin[8] = {0., M_SQRT1_2, 1., M_SQRT1_2, 0., -M_SQRT1_2, -1., -M_SQRT1_2};
// Smallest mean contrast (grey levels of the normalised image) between adjacent rings of a readable ray.
const double kMinPairContrast = 6.;

struct Ellipse
{
  double major = 0., minor = 0., theta = 0.;
  double a = 0., b = 0., c = 0.; // a x^2 + 2 b x y + c y^2 = 1
  //! Distance from the centre to the ellipse along the unit direction (x, y).
  double radiusAlong(double x, double y) const { return 1. / std::sqrt(a * x * x + 2. * b * x * y + c * y * y); }
  double worstResidual = 0.;
  int worstRay = -1;
};
// Least-squares ellipse centred at the origin, A x^2 + B x y + C y^2 = 1, through the points R[d] (cos, sin).
bool fitEllipse(const double R[8], const bool ok[8], Ellipse &e);
} // namespace vpSSLRadiusEstimatorInternal

#endif
