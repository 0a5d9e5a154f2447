/*
  Views of the independent corpus (visp_ssl_bench) that the corpus tests set up by hand: a clean view, the sheet on
  dark water without water, light or sensor effects (each test adds what it tests), poses that put a landmark's
  centre on the optical axis, and a landmark on a true outer ellipse. Header only: the corpus tests link visp_ssl_bench,
  not the tests' common library.
*/
#ifndef SSL_TEST_CORPUS_VIEW_H
#define SSL_TEST_CORPUS_VIEW_H

#include <cmath>

#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/ssl/vpSSLLandmark.h>
#include <visp3/ssl_bench/vpSSLCorpusView.h>

// A clean view: no water loss or veiling light, uniform light, no blur, noise, gamma or JPEG, the sheet on dark
// water, fine supersampling; the pose is set by the caller.
inline vpSSLCorpusViewParams cleanView()
{
  vpSSLCorpusViewParams p;
  p.camera.px = p.camera.py = 800.;
  p.camera.u0 = 319.3; // off the pixel grid
  p.camera.v0 = 241.7;
  p.paper = 0.9;
  p.ink = 0.05;
  p.background = vpSSLCorpusViewParams::DARK_WATER;
  for (int c = 0; c < 3; ++c) {
    p.attenuation[c] = 0.;
    p.backscatter[c] = 0.;
  }
  p.ambient = 1.;
  p.spot = 0.;
  p.vignetting = 0.;
  p.gaussSigma = 0.;
  p.motionLength = 0.;
  p.exposure = 0.9;
  p.noiseGain = 0.;
  p.readNoise = 0.;
  p.gamma = 1.;
  p.jpegQuality = 0;
  p.supersampling = 6;
  p.cropLeft = -1.;
  p.cropTop = -1.;
  p.cropRight = 1.;
  p.cropBottom = 1.;
  return p;
}

// Pose: rotation about the target's X axis by \e tilt, then B's centre at depth \e depth on the optical axis.
inline vpHomogeneousMatrix tiltedOnAxis(double tilt, double depth, double bx)
{
  vpHomogeneousMatrix M;
  const double c = std::cos(tilt), s = std::sin(tilt);
  M[0][0] = 1.;
  M[0][1] = 0.;
  M[0][2] = 0.;
  M[1][0] = 0.;
  M[1][1] = c;
  M[1][2] = -s;
  M[2][0] = 0.;
  M[2][1] = s;
  M[2][2] = c;
  M[0][3] = -bx; // R (bx, 0, 0) = (bx, 0, 0)
  M[1][3] = 0.;
  M[2][3] = depth;
  return M;
}

// Pose: rotation about the target's X axis by \e tilt, then the point (\e x, \e y) of the target plane at depth
// \e depth on the optical axis.
inline vpHomogeneousMatrix tiltedOnAxis(double tilt, double depth, double x, double y)
{
  vpHomogeneousMatrix M = tiltedOnAxis(tilt, depth, x);
  // R (x, y, 0) = (x, c y, s y)
  M[1][3] = -std::cos(tilt) * y;
  M[2][3] = depth - std::sin(tilt) * y;
  return M;
}
// A landmark on a true landmark's outer ellipse.
inline vpSSLLandmark trueEllipse(const vpSSLCorpusLandmarkTruth &t)
{
  vpSSLLandmark l;
  l.u = t.u;
  l.v = t.v;
  l.radius = t.a;
  l.minorRadius = t.b;
  l.theta = t.theta;
  return l;
}

#endif
