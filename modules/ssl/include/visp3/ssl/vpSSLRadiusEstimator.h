/*!
  \file vpSSLRadiusEstimator.h
  \brief Apparent radius (paper Eq. 7), ellipse and sub-pixel centre of a landmark candidate.
*/
#ifndef VP_SSL_RADIUS_ESTIMATOR_H
#define VP_SSL_RADIUS_ESTIMATOR_H

#include <cstdint>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/ssl/vpSSLLandmark.h>
#include <visp3/ssl/vpSSLMatchingFunction.h>

namespace vpSSLRadiusEstimatorInternal {
struct Ellipse;
}

/*!
  \class vpSSLRadiusEstimator
  \ingroup group_ssl
  \brief Reads the ring pattern around a candidate centre: verifies it, measures the outer radius along
  eight directions, fits the outer ellipse and refines the centre.

  The paper estimates the apparent size by sweeping the window w of the matching function (Eq. 7,
  Fig. 4). On a printed sheet the white paper outside the outermost black ring continues the pattern
  by one ring, so that sweep peaks near \f$ R/\sqrt{p} \f$ rather than R (the paper notes the
  overestimate under Fig. 5). The sweep is kept (radiusEq7, sweep()) for comparison; the radius
  reported is read from the rings themselves: along each ray from the centre the profile is compared
  with the printed square wave \f$ s_p(\rho / R) \f$ for every R in the search range, ring by ring,
  and the largest R whose outermost ring is dark against the next one and whose rings alternate as
  printed wins. A ray whose rings do not alternate (clutter, occlusion) is discarded; a candidate
  with too few readable rays is rejected, which is what keeps chessboards, textures and striped fish
  out.

  The centre is refined from the midpoints of the ring edges on opposite rays; under perspective the
  rings are not concentric (their centres drift with the square of their radius), so the midpoints
  are extrapolated to radius 0, the projection of the landmark's centre.

  Threads: estimate() keeps the rays it reads in the object, so it is not const: one estimator per thread.
*/
class VISP_SSL_EXPORT vpSSLRadiusEstimator
{
public:
  vpSSLRadiusEstimator();

  //! Search range of the outer radius (px). \exception vpException unless 2 <= minRadius < maxRadius.
  void setRadiusRange(double minRadius, double maxRadius);
  //! Smallest number of the 8 rays that must show the pattern (default 6).
  void setMinDirections(unsigned int n);
  /*!
    Camera pixels per image pixel (default 1; 2 on an image upsampled twice). The thinnest ring that can
    be read is a property of the camera, so the ring-width limits are scaled by it.
  */
  void setPixelScale(double scale);
  //! Similarity ratio p of the printed landmark (default 0.5).
  void setP(double p);
  double getMinRadius() const { return m_minRadius; }               ///< Lower bound of the radius search (px).
  double getMaxRadius() const { return m_maxRadius; }               ///< Upper bound of the radius search (px).
  unsigned int getMinDirections() const { return m_minDirections; } ///< Rays needed to accept a landmark.

  /*!
    Measures the landmark whose centre is near (\e landmark.u, \e landmark.v) on the normalised image.
    Fills radius, minorRadius, theta, directionalRadius, nbDirections and refines u, v.
    \return false if the ring pattern is not there (the candidate is not a landmark).
  */
  bool estimate(const vpImage<unsigned char> &I, vpSSLLandmark &landmark);

  /*!
    Re-reads a landmark tracked from the previous frame: as estimate(), but each ray's radius is searched
    only within about 11 % of the previous ellipse (\e prior: its radius, minorRadius and theta), which
    skips the search over the whole radius range. Falls back to estimate() if \e prior has no ellipse.
    \return false if the ring pattern is not there at that size (the caller may then try estimate()).
  */
  bool estimate(const vpImage<unsigned char> &I, vpSSLLandmark &landmark, const vpSSLLandmark &prior);

  /*!
    Whether the candidate of the last estimate() (from scratch) passed the point-symmetry test that opens the ring
    reading, whatever came after, and the centre that test settled on: a point-symmetric candidate whose rays do
    not read is worth another reader's look (vpSSLConcentricReader), most clutter is not.
  */
  bool getLastSymmetric(double &u, double &v) const
  {
    u = m_symmetricU;
    v = m_symmetricV;
    return m_symmetric;
  }

  /*!
    Eq. 7 sweep: \e S[w] is the +x matching sum with window w at pixel (u, v), for w up to
    \e maxWindow (or the image border).
    \return the w maximising S (the paper's apparent size), 0 if the sweep is empty.
  */
  static unsigned int sweep(const vpImage<unsigned char> &I, const vpSSLMatchingFunction &match, int u, int v,
                            unsigned int maxWindow, std::vector<int> &S);

private:
  bool readRays(const vpImage<unsigned char> &I, double u, double v, double maxRadius);
  bool symmetricCentre(const vpImage<unsigned char> &I, double &u, double &v);
  bool finish(const vpImage<unsigned char> &I, double u, double v, double R[8], bool ok[8], vpSSLLandmark &landmark);
  struct Candidate
  {
    double radius;
    double score;
  };
  void rayCandidates(int d, double ref, std::vector<Candidate> &candidates);
  void ray(int d, double upTo);
  bool symmetryCentre(const vpImage<unsigned char> &I, double &u, double &v, double &asymmetry);
  bool selectRadii(const double *ref, double R[8], bool ok[8], double &scale);
  bool refineCentre(const vpImage<unsigned char> &I, double u0, double v0, double scale, double &u, double &v,
                    double R[8], bool ok[8]);
  bool solidRings(int d, double radius);
  bool ringEdge(int d, double expected, double halfWidth, double &position);
  bool ringsAllAround(const vpImage<unsigned char> &I, double u, double v,
                      const vpSSLRadiusEstimatorInternal::Ellipse &e) const;

  double m_minRadius;
  double m_maxRadius;
  unsigned int m_minDirections;
  double m_p;
  double m_q; // sqrt(p), the ratio of successive ring edges
  double m_step;
  double m_pixelScale;
  bool m_symmetric = false; // the last estimate()'s candidate passed the symmetry test, centred at:
  double m_symmetricU = 0., m_symmetricV = 0.;
  // Per-ray profiles and their prefix sums, reused between candidates.
  std::vector<float> m_profile[8];
  std::vector<double> m_prefix[8];
  std::vector<double> m_mean3[8];              // means of three neighbouring samples (solidRings()), read as needed
  std::vector<double> m_grid, m_scores;        // radius search scratch
  std::vector<uint32_t> m_survivors, m_passed; // radii of the grid that pass the SIMD screen, and all its tests
  std::vector<double> m_passedScores;          // the scores of the latter
  std::vector<Candidate> m_candidates[8];
  std::vector<double> m_valid; // selectRadii() scratch
  // Centre of the rays (readRays()); each ray is read on first use (ray()).
  const vpImage<unsigned char> *m_rayImage = nullptr;
  double m_rayU = 0., m_rayV = 0., m_rayMaxRadius = 0.;
  bool m_rayRead[8] = {false, false, false, false, false, false, false, false};
  size_t m_raySamples[8] = {0, 0, 0, 0, 0, 0, 0, 0}; // length of each whole ray, in samples
  // Radius grid of the whole search range, built once (rayCandidates()).
  std::vector<double> m_fullGrid;
  bool m_levelZeroOnly = false;  // tracked re-reading: only the previous level is searched
  bool m_keepCandidates = false; // selectRadii() takes the rays' candidates of the previous call as they are
  double m_fullGridMin = 0., m_fullGridMax = 0.;
  // Row extents of the half disc compared with its half-turn (symmetryCentre()), for this radius; the copies of
  // the search window's neighbourhood that the comparison reads.
  std::vector<int> m_symmetryOffsets;
  int m_symmetryRadius = -1;
  std::vector<int16_t> m_symmetryPatch;
};

#endif
