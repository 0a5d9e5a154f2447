/*!
  \file vpSSLMatchingFunction.h
  \brief The four-direction self-similarity matching function (paper Eq. 2-5).
*/
#ifndef VP_SSL_MATCHING_FUNCTION_H
#define VP_SSL_MATCHING_FUNCTION_H

#include <string>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRect.h>
#include <visp3/ssl/vpSSLConfig.h>

/*!
  Scan directions of the matching function, in the paper's notation (Sec. 2.1).
*/
enum vpSSLDirection
{
  vpSSL_PLUS_X = 0, ///< \f$ m_{+x} \f$: towards increasing u.
  vpSSL_MINUS_X,    ///< \f$ m_{-x} \f$: towards decreasing u.
  vpSSL_PLUS_Y,     ///< \f$ m_{+y} \f$: towards increasing v (down the image).
  vpSSL_MINUS_Y     ///< \f$ m_{-y} \f$: towards decreasing v.
};

/*!
  \class vpSSLMatchingFunction
  \ingroup group_ssl
  \brief Discrete matching function of Eq. 3 in four directions and their maximum (Eq. 5).

  For a pixel X, a unit direction d and a window w, with the rounded sample offsets
  \f$ a_\xi = \lfloor \sqrt{p}\,\xi + 1/2 \rfloor \f$ and \f$ b_\xi = \lfloor p\,\xi + 1/2 \rfloor \f$:
  \f[ m_d(X) = \sum_{\xi=1}^{w} |I(X+\xi d) - I(X+a_\xi d)| - |I(X+\xi d) - I(X+b_\xi d)| \f]
  i.e. \f$ w \f$ times the paper's normalised integral, kept in integers so that every
  implementation (reference, SIMD, threaded, ROI) gives exactly the same map. A direction is valid
  at X when \f$ X + w d \f$ is inside the image; \f$ M(X) \f$ is the maximum over the valid
  directions, and 0 where none is. A perfect response is \f$ 255 w \f$.

  computeReference() is the plain implementation that defines the map; compute() is the fast one
  (SIMD with runtime dispatch, threads, regions of interest) and must give the same map.

  Threads: the const methods (compute(), computeReference(), evaluate(), cumulative()) are safe to call from
  several threads on one object (the buffers compute() reuses are per thread); the setters are not.

  \code
  vpSSLMatchingFunction match(40, 0.5);
  vpImage<int> M;
  match.compute(I, M);      // M(v, u) / (255 * 40) is the score in [-1, 1]
  \endcode
*/
class VISP_SSL_EXPORT vpSSLMatchingFunction
{
public:
  /*!
    \param window : window length w in pixels (paper: 40), in [2, 128].
    \param p : similarity ratio of the printed square wave, in (0, 1).
    \exception vpException on a window or p out of range.
  */
  explicit vpSSLMatchingFunction(unsigned int window = 40, double p = 0.5);

  //! Sets the window length w. \exception vpException if not in [2, 128].
  void setWindow(unsigned int window);
  //! Sets p. \exception vpException if not in (0, 1).
  void setP(double p);
  //! Window length w.
  unsigned int getWindow() const { return m_window; }
  //! Similarity ratio p.
  double getP() const { return m_p; }
  //! Largest possible value of the map, 255 w: divide by it to get a score in [-1, 1].
  int getMaxValue() const { return 255 * static_cast<int>(m_window); }

  /*!
    Reference implementation of M (Eq. 5) over the whole image: plain loops, no SIMD, no threads.
    \param I : grey image (any size; pixels with no valid direction get 0).
    \param M : resized to the image size.
  */
  void computeReference(const vpImage<unsigned char> &I, vpImage<int> &M) const;

  /*!
    Fast M (Eq. 5) over the whole image; the same values as computeReference().
  */
  void compute(const vpImage<unsigned char> &I, vpImage<int> &M) const;

  /*!
    Fast M inside the given rectangles only (clipped to the image); the other pixels of M are set to 0.
    M is resized to the image size.
  */
  void compute(const vpImage<unsigned char> &I, const std::vector<vpRect> &rois, vpImage<int> &M) const;

  /*!
    Matching function in one direction at one pixel for any window length (Eq. 3, unnormalised sum),
    used by the apparent-radius sweep (Eq. 7).
    \return false (and leaves \e value untouched) when the window leaves the image.
  */
  bool evaluate(const vpImage<unsigned char> &I, int u, int v, vpSSLDirection d, unsigned int window, int &value) const;

  /*!
    Cumulative matching function along one direction: \e S[k] is the Eq. 3 sum over
    \f$ \xi = 1 \dots k \f$ (S[0] = 0), for k up to \e maxWindow or the image border, whichever comes
    first. One call gives the whole Eq. 7 sweep.
  */
  void cumulative(const vpImage<unsigned char> &I, int u, int v, vpSSLDirection d, unsigned int maxWindow,
                  std::vector<int> &S) const;

  //! Number of worker threads of compute() (0: all cores, the default). Results do not depend on it.
  void setNbThreads(unsigned int n) { m_nbThreads = n; }
  //! Worker thread setting (0: all cores).
  unsigned int getNbThreads() const { return m_nbThreads; }

  //! Name of the SIMD target compute() runs on this CPU ("AVX3", "AVX2", "SSE4", "NEON", "EMU128", ...).
  static std::string getSimdTarget();

  //! Offset \f$ a_\xi = \lfloor \sqrt{p}\,\xi + 1/2 \rfloor \f$ for \f$ \xi \ge 0 \f$.
  int offsetSqrtP(unsigned int xi) const;
  //! Offset \f$ b_\xi = \lfloor p\,\xi + 1/2 \rfloor \f$ for \f$ \xi \ge 0 \f$.
  int offsetP(unsigned int xi) const;

private:
  // The detection pipeline behind vpSSLDetector (modules/ssl/src/vpSSLDetectionPipeline.h) is the one caller of
  // computeInside(): the map it leaves outside the rectangles is only right for a caller that clears it itself.
  friend class vpSSLDetectionPipeline;

  // As compute(I, rois, M), but only the pixels inside the rectangles are written: the others keep their values
  // (if M has not the image's size, it is resized and set to 0 first). For a caller that keeps M zero outside its
  // regions itself, by clearing only the regions it wrote last (vpSSLDetector's tracking frames), rather than the
  // whole map at every call.
  void computeInside(const vpImage<unsigned char> &I, const std::vector<vpRect> &rois, vpImage<int> &M) const;

  void computeRegions(const vpImage<unsigned char> &I, const std::vector<vpRect> &rois, vpImage<int> &M,
                      bool clearOutside) const;

  unsigned int m_window;
  double m_p;
  unsigned int m_nbThreads;
};

#endif
