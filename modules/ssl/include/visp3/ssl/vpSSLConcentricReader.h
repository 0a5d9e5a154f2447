/*!
  \file vpSSLConcentricReader.h
  \brief Reads a landmark from the whole of its rings: concentric-ellipse fit of the gradients, ring phase, outer ring.
*/
#ifndef VP_SSL_CONCENTRIC_READER_H
#define VP_SSL_CONCENTRIC_READER_H

#include <cstdint>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/ssl/vpSSLConfig.h>
#include <visp3/ssl/vpSSLLandmark.h>

/*!
  \class vpSSLConcentricReader
  \ingroup group_ssl
  \brief Reads a landmark from the whole of its rings rather than along a few rays.

  Under any affine view the printed rings are concentric ellipses, so every image gradient inside a landmark is
  normal to the ellipse through it. The centre and the ellipses' shape are the least-squares fit of that condition
  over the gradients of a disc that grows from the candidate while the fit explains the gradients (it stops at
  clutter, the sheet's edge or a neighbour). The radial profile averaged around those ellipses, in the log radius
  where the square wave \f$ s_p \f$ of Eq. 1 is periodic, gives the rings' phase from all the resolved rings at
  once; the outer ring is the outermost p-similar copy whose black ring stands dark against the white one inside
  it in nearly every direction, as dark as the next black ring; the scale is then read where the profile crosses
  the mid level at the two printed edges inside the outer ring (R sqrt(p) and R p), which blur does not move.
  Under perspective the outer rings' centres drift from the image of the landmark's centre: where the disc inside
  the third ring (R p^2) is 8 px or more, the centre is that of the same fit over that disc alone.

  It reads landmarks that the ray reading of vpSSLRadiusEstimator rejects: small and blurred ones, strongly
  oblique ones, and those whose rings a few rays cannot follow. vpSSLDetector asks it where the ray reading
  fails. No memory is allocated by read().
*/
class VISP_SSL_EXPORT vpSSLConcentricReader
{
public:
  //! A reader for p = 0.5 and radii of 4 to 300 px.
  vpSSLConcentricReader();

  //! Similarity ratio p of the printed landmark. \exception vpException unless in (0, 1).
  void setP(double p);
  //! Search range of the outer radius (px). \exception vpException unless 0 < minRadius < maxRadius.
  void setRadiusRange(double minRadius, double maxRadius);

  /*!
    Reads the landmark whose centre is near (\e landmark.u, \e landmark.v) on the camera's grey image: fills u, v,
    radius, minorRadius, theta, nbDirections and directionalRadius.
    \return false if no landmark is read there.
  */
  bool read(const vpImage<unsigned char> &I, vpSSLLandmark &landmark);

  /*!
    As read(), but where the landmark's outer ellipse is already known roughly (\e landmark.radius, minorRadius and
    theta, predicted from another landmark of the target): the rings are read about ellipses of that shape, from the
    centre (\e landmark.u, \e landmark.v) moved to where the disc inside the outer ring is most point-symmetric,
    instead of about the ellipses the gradients fit, which need rings well above the noise to lock; the outer ring
    read lies within a factor 0.7 of the one given, either way. Every test of read() on the rings applies.
    \return false if no landmark is read there.
    \exception vpException (dimensionError) if \e I does not hold its width x height pixels or exceeds twice the
    input limits of vpSSLInputLimits a side.
  */
  bool readAt(const vpImage<unsigned char> &I, vpSSLLandmark &landmark);

  //! Stage at which the last read() stopped: 1 the fit, 2 the phase, 3 the outer ring, 4 read.
  int getStage() const { return m_stage; }

  //! Quality of the last fit: gradient energy explained by the concentric ellipses, in [0, 1].
  double getQuality() const { return m_quality; }

  //! Correlation of the last read's ring profile with the square wave \f$ s_p \f$ (1: a sharp landmark), or with
  //! its blurred model where the blurred-ring model read it (setBlurredRingModel()).
  double getSimilarity() const { return m_similarity; }

  /*!
    Correlation with the square wave \f$ s_p \f$ of the ring profile inside \e landmark's outer ellipse (its
    centre, radius, minorRadius and theta), averaged around the ellipses of its shape, over every ring at least
    1.2 px wide: 1 for a sharp landmark, lower when blur greys the inner rings, and low or negative for concentric
    rings that do not shrink by p (a bull's-eye of equal rings, which matches the outer rings only).
  */
  double similarity(const vpImage<unsigned char> &I, const vpSSLLandmark &landmark);

  /*!
    Whether the profile of the last similarity() is better explained by rings of one width than by \f$ s_p \f$
    (their best square wave in linear radius correlates with it by 0.15 more), while the rings in [0.2 R, 0.5 R)
    keep 0.9 of the contrast of those in [0.5 R, R): a bull's-eye of equal rings whose blur leaves the outer rings
    close to \f$ s_p \f$. Blur greys a landmark's inner rings, which are narrower, but not a bull's-eye's. false
    before any similarity(), after a read() and when similarity() read no profile.
  */
  bool isEqualRings() const;

  /*!
    Whether read() falls back on a model of the blurred rings where its outer-ring tests find no ring (off by
    default). Those tests compare mean levels with a floor of 4 grey levels and ask each direction for the outer
    pair's contrast: a landmark of 10-20 px whose rings, blurred by 1-2.5 px and seen through water, keep only a few
    grey levels of contrast, fails them although its profile is plain. The model is the profile of \f$ s_p \f$
    blurred by a Gaussian of 0.4 to 4 px, its outer edge at each p-similar copy the rings' phase allows (outermost
    first, within a tenth of a period): a copy is read when, over its radii from twice the blur (1.5 px at least) to
    1.1 R, it correlates with the profile by 0.945 or more, by 0.1 more than a blurred solid disc of about that
    radius (blur that has greyed every ring leaves a disc, which anything dark and round matches), with 0.3 or more
    in three quarters of the directions seen (six of eight at least), a radius of 8 px or more and the model's
    variance twice the noise of the profile's mean (the spread of the directions). doc/detector.md gives what it adds
    on the independent corpus.
  */
  void setBlurredRingModel(bool enable) { m_blurredRingModel = enable; }
  //! Whether read() falls back on the blurred-ring model (setBlurredRingModel()).
  bool getBlurredRingModel() const { return m_blurredRingModel; }

private:
  struct Fit
  {
    double u = 0., v = 0.;
    double q[3] = {1., 0., 1.}; // (x - c)^T [q0 q1; q1 q2] (x - c), determinant 1
    double quality = 0.;
  };
  bool fit(const vpImage<unsigned char> &I, double radius, int iterations, double gridSide, bool smooth, Fit &f) const;
  bool grow(const vpImage<unsigned char> &I, double u, double v, bool smooth, Fit &best, double &bestRadius) const;
  // Stages 2-5 of read() on the ellipses of \e best, locked on a disc of \e bestRadius (rho units).
  bool readRings(const vpImage<unsigned char> &I, Fit best, double bestRadius, vpSSLLandmark &landmark);
  bool readProfile(const vpImage<unsigned char> &I, const Fit &f, double tauLow, double tauHigh);
  double band(double tau0, double tau1, int sector) const;
  void allAround(double *level) const;
  double profileSimilarity(const double *level, double tauA, double tR) const;
  bool equalRings(const double *level, double tauA, double tR) const;
  double blurredOuter(const double *level, double phase, double tauHigh, const Fit &f, double &correlation) const;
  double modelCorrelation(const double *level, int sector, double R, double sigma, bool rings, double pxPerRho,
                          double &amplitude) const;

  double m_p;
  double m_logStep; // log(1 / p): one period of the rings in log radius
  double m_minRadius, m_maxRadius;
  // readAt()'s symmetry centring: the half disc's rows and the kernel's scratch, kept between calls.
  int m_symmetryRadius = 0;
  // The outer radii (rho units) that the outer ring may take: any for read(), about the one given for readAt().
  double m_outerLow = 0., m_outerHigh = 0.;
  std::vector<int> m_symmetrySpans;
  std::vector<int16_t> m_symmetryBuffer;
  int m_stage;
  double m_quality;
  double m_similarity;
  // The span in periods of the last similarity()'s profile (isEqualRings()); m_profileTauR 0 when there is none.
  double m_profileTauA, m_profileTauR;
  bool m_blurredRingModel;

  // Radial profile: bins of kBinsPerPeriod per period of log radius from m_tau0, per sector of directions.
  static constexpr int kSectors = 8;
  static constexpr int kMaxBins = 512;
  double m_tau0;
  int m_nbBins;
  float m_sum[kMaxBins][kSectors];
  unsigned short m_count[kMaxBins][kSectors];
  double m_rho[kMaxBins]; // each bin's radius, the same on every ray
};

#endif
