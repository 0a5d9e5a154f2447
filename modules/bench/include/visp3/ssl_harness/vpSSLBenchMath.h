/*!
  \file vpSSLBenchMath.h
  \brief The arithmetic of the detection benchmarks: pose errors, range bands, percentiles, table numbers.
*/
#ifndef VP_SSL_BENCH_MATH_H
#define VP_SSL_BENCH_MATH_H

#include <cstddef>
#include <string>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>

/*!
  \defgroup group_ssl_harness Benchmark and closed-loop harness
  Library visp_ssl_harness, headers <tt>\<visp3/ssl_harness/...\></tt>, built with the tutorials, tests or
  benchmarks and not installed (in the project: <tt>target_link_libraries(app visp_ssl_harness)</tt>): the code the
  comparison tutorials and their tests share: the AprilTag baseline, the statistics of a detection benchmark, and
  the simulated closed loop of the servo tutorials.
*/

/*!
  \class vpSSLBenchMath
  \ingroup group_ssl_harness
  \brief The arithmetic of the detection benchmarks (tutorial-ssl-vs-apriltag, tutorial-ssl-servo-monte-carlo).
*/
class vpSSLBenchMath
{
public:
  //! NaN: a quantity that was not measured.
  static double nan();

  //! Position error |t_est - t_true| (m).
  static double positionError(const vpHomogeneousMatrix &est, const vpHomogeneousMatrix &truth);

  //! Angle of the rotation between the two orientations (degrees), in [0, 180].
  static double angleError(const vpHomogeneousMatrix &est, const vpHomogeneousMatrix &truth);

  //! \e x with \e digits decimals for the Markdown tables, "-" when it was not measured (NaN).
  static std::string fmt(double x, int digits);

  //! \e x with \e digits decimals for a CSV cell, "" when it was not measured (NaN).
  static std::string csvNumber(double x, int digits);

  //! The range bands of the report (m): [0,1), [1,2), [2,4), [4,8), [8,12].
  static const std::vector<double> &bandEdges();

  //! Band label "0-1", ... "8-12".
  static std::string bandLabel(size_t b);

  //! Index of the band holding \e range, or -1 outside [0, 12] or when not finite; 12 m belongs to the last band.
  static int bandIndex(double range);

  /*!
    Percentile \e p in [0, 100] of \e v with linear interpolation between order statistics (NaN values are
    ignored); NaN when no value is left.
  */
  static double percentile(std::vector<double> v, double p);
};

#endif
