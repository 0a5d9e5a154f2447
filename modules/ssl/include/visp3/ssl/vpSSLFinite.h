/*!
  \file vpSSLFinite.h
  \brief Finite-value check of ViSP arrays, shared by the core, simulator and servo libraries.
*/
#ifndef VP_SSL_FINITE_H
#define VP_SSL_FINITE_H

#include <visp3/core/vpArray2D.h>
#include <visp3/ssl/vpSSLConfig.h>

/*!
  \class vpSSLFinite
  \ingroup group_ssl
  \brief Tells whether every element of a ViSP array (vpHomogeneousMatrix, vpMatrix, vpColVector, ...) is finite.

  Inputs that come from outside (odometry, poses, velocities) are checked with it before they are used, so that
  a NaN or an infinity is refused where it enters instead of spreading through a filter or a control law.
  Stateless: safe to call from several threads at once.
*/
class VISP_SSL_EXPORT vpSSLFinite
{
public:
  //! True when no element of \e A is NaN or infinite (true for an empty array).
  static bool isFinite(const vpArray2D<double> &A);
};

#endif
