// The core library's small shared helpers: vpSSLFinite (every input check of the core, simulator and servo
// libraries calls it) and vpSSLPointTransform (every landmark projection of the tracker, pose and servo).
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include <visp3/core/vpColVector.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpPoint.h>
#include <visp3/ssl/vpSSLFinite.h>
#include <visp3/ssl/vpSSLPointTransform.h>

TEST(CoreUtils, FiniteRefusesAnyNanOrInfinityAnywhere)
{
  const vpHomogeneousMatrix M(0.1, -0.2, 1.5, 0.3, 0.2, -0.1);
  EXPECT_TRUE(vpSSLFinite::isFinite(M));
  for (unsigned int i = 0; i < 4; ++i) {
    for (unsigned int j = 0; j < 4; ++j) {
      for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                         -std::numeric_limits<double>::infinity()}) {
        vpHomogeneousMatrix B = M;
        B[i][j] = bad;
        EXPECT_FALSE(vpSSLFinite::isFinite(B)) << i << " " << j << " " << bad;
      }
    }
  }
  vpColVector v(6, 1.);
  EXPECT_TRUE(vpSSLFinite::isFinite(v));
  v[5] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(vpSSLFinite::isFinite(v));
  EXPECT_TRUE(vpSSLFinite::isFinite(vpColVector()));
}

TEST(CoreUtils, PointTransformMatchesViSPChangeFrame)
{
  const vpHomogeneousMatrix cMo(0.1, -0.2, 1.5, 0.3, 0.2, -0.1);
  const double points[3][3] = {{0., 0., 0.}, {0.12, -0.07, 0.}, {-0.3, 0.25, 0.05}};
  for (const double *p : points) {
    double c[3];
    vpSSLPointTransform::apply(cMo, p[0], p[1], p[2], c);
    vpPoint P(p[0], p[1], p[2]);
    P.changeFrame(cMo);
    EXPECT_NEAR(c[0], P.get_X(), 1e-12);
    EXPECT_NEAR(c[1], P.get_Y(), 1e-12);
    EXPECT_NEAR(c[2], P.get_Z(), 1e-12);
  }
}
