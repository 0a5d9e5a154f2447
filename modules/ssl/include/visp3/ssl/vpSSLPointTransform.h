/*!
  \file vpSSLPointTransform.h
  \brief A 3-D point changed of frame without a temporary: the one copy the core, simulator and servo use.
*/
#ifndef VP_SSL_POINT_TRANSFORM_H
#define VP_SSL_POINT_TRANSFORM_H

#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/ssl/vpSSLConfig.h>

/*!
  \class vpSSLPointTransform
  \ingroup group_ssl
  \brief Coordinates of a point in frame a from its coordinates in frame b and the pose aMb.

  The same as vpPoint::changeFrame() or aMb * vpColVector, without allocating: the tracker and the servo law
  project the target's landmarks at every frame. Stateless: safe to call from several threads at once.

  \code
  double c[3];
  vpSSLPointTransform::apply(cMo, l.x, l.y, l.z, c); // landmark l in the camera frame
  const double x = c[0] / c[2], y = c[1] / c[2];    // its normalised image coordinates
  \endcode
*/
class VISP_SSL_EXPORT vpSSLPointTransform
{
public:
  //! \e out = aMb (x, y, z, 1)^T, the first three coordinates.
  static void apply(const vpHomogeneousMatrix &aMb, double x, double y, double z, double out[3])
  {
    for (unsigned int i = 0; i < 3; ++i) {
      out[i] = aMb[i][0] * x + aMb[i][1] * y + aMb[i][2] * z + aMb[i][3];
    }
  }
};

#endif
