/*
  Private interface of the ray reading of vpSSLRadiusEstimator in SIMD: the bilinear samples of a ray, the
  screening of the radius grid by the two outermost ring pairs and the reading of the radii left, implemented with
  Google Highway in vpSSLRayKernel.cpp and picked at run time for the CPU. They give the values of a plain scalar
  reference, bit for bit (the same double operations in the same order, compiled without contraction into fused
  multiply-adds): test_ring_kernels holds that reference and compares.
  Sizes: width and height in int, within the kernels' bound of vpSSLImageCheck (vpSSLRadiusEstimator::estimate()
  checks the image), every sample inside the image.
*/
#ifndef VP_SSL_RAY_KERNEL_H
#define VP_SSL_RAY_KERNEL_H

#include <cstddef>
#include <cstdint>

namespace vpSSLRayKernel {
//! Where a ray starts and how it is sampled: sample i lies at (u, v) + i step (cd, sd).
struct Ray
{
  const uint8_t *bitmap; //!< Image, rows of \e width bytes.
  int width, height;
  double u, v;   //!< Centre.
  double cd, sd; //!< Unit direction.
  double step;   //!< Distance between samples (px).
};

/*!
  out[i] = the bilinear interpolation of the image at sample i of \e ray, for i in [i0, i1), rounded to float: the
  neighbours are (floor(x), floor(y)) and the next column and row, clamped to the last ones. Every sample must lie
  inside the image (x, y >= 0).
*/
void sample(const Ray &ray, std::size_t i0, std::size_t i1, float *out);

//! A ray's profile and where its rings are too thin to be read.
struct Profile
{
  const float *p;     //!< Samples, one every \e step px from the centre.
  const double *c;    //!< c[i]: trapezoidal integral of p from 0 to sample i.
  std::size_t n;      //!< Samples (and integrals), at least 1.
  double step;        //!< Their spacing (a power of two).
  double invStep;     //!< 1 / step.
  double q;           //!< Ratio of successive ring edges, sqrt(p).
  double minWidth;    //!< Narrowest ring read (px).
  double minRadius;   //!< Smallest inner edge of a ring read (px).
  double minContrast; //!< Least contrast of the outermost ring pair.
};

/*!
  Tests of a ring reading besides the profile's (vpSSLRadiusEstimator::rayCandidates()): the
  thresholds of its ring pairs and of the ink's level.
*/
struct ScoreRules
{
  double clearWidth;          //!< Ring width (px) that any lens resolves: those pairs must all alternate.
  double minPairContrast;     //!< Least mean contrast of the pairs read.
  double outerShare;          //!< Least share of that mean the outermost pair must show.
  int minAlternations;        //!< Pairs that must alternate where at least that many are clearly resolved.
  double inkTolerance;        //!< How far the outermost black ring's level may stray from the inner ones'.
  double blurredInkTolerance; //!< The same on the dark side when fewer than two pairs are clearly resolved.
};

/*!
  Indices i in [0, n) of the radii R = radii[i] at which the ray's three outermost rings ([q R, R], [q^2 R, q R],
  [q^3 R, q^2 R]) are all readable, the outermost pair's contrast (white minus black) is at least
  profile.minContrast, and the next pair's is at least a quarter of the larger of the two: the tests that settle
  almost every radius of a cluttered image, so that score() reads the few that pass in full (test_ring_kernels
  holds a plain scalar version of both as their reference). Written to \e
  survivors in increasing order. \return their number.
*/
std::size_t screen(const Profile &profile, const double *radii, std::size_t n, uint32_t *survivors);

/*!
  Reads the ray at the radii radii[indices[k]], k in [0, n) (radii that passed screen()): every ring out to the first
  one too thin to be read, the pairs that alternate from the outermost one inwards, the ink's level, and the tests of
  the reading as a whole (vpSSLRadiusEstimator::rayCandidates(), its solid-ring test aside). The index and score (the
  sum of the alternating pairs' contrasts) of each radius that passes are written to \e passed and \e scores, in
  the order of \e indices.
  \return their number.
*/
std::size_t score(const Profile &profile, const ScoreRules &rules, const double *radii, const uint32_t *indices,
                  std::size_t n, uint32_t *passed, double *scores);
} // namespace vpSSLRayKernel

#endif
