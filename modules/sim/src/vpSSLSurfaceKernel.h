/*
  Private interface of the SIMD shading of vpSSLRenderer's open-water rays that meet the water surface and, after
  it, nothing (vpSSLRenderer::renderCore()), implemented with Google Highway in vpSSLSurfaceKernel.cpp and
  picked at run time for the CPU. Every lane performs the scalar IEEE operations in the same order, without fused
  multiply-adds, so that the values are the scalar ones bit for bit (test_sim_exact compares them).
*/
#ifndef VP_SSL_SURFACE_KERNEL_H
#define VP_SSL_SURFACE_KERNEL_H

#include <cstddef>

namespace vpSSLSurfaceKernel {
//! The constants of a frame's surface rays.
struct Surface
{
  double sn[3];       //!< Unit normal of the surface, towards the air.
  double num;         //!< sd - sn . o from the camera centre o (> 0: the camera is below the surface).
  double maxRange2;   //!< Squared maximum range of the rays (m^2, may be infinite).
  double waterIndex;  //!< Refractive index of the water.
  double parallelEps; //!< Rays with sn . d at or below this do not meet the surface.
};

/*!
  For each of the \e count rays of directions (dx[k], dy[k], dz[k]) from the camera centre: \e fresnel[k] = -1 when
  the ray does not meet the surface within the maximum range, else the unpolarised Fresnel reflectance of the
  water-to-air interface at its incidence, and \e tw[k] the ray parameter of the surface (shade()'s num / dn, a path
  length in units of |d|; meaningful where fresnel[k] >= 0).
*/
void surfaceRays(const Surface &surface, const double *dx, const double *dy, const double *dz, size_t count,
                 double *fresnel, double *tw);

//! The same for one ray, scalar: the reference of the vectors and their tail.
double surfaceRay(const Surface &surface, double dx, double dy, double dz, double &tw);
} // namespace vpSSLSurfaceKernel

#endif
