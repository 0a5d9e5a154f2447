#include <visp3/ssl_bench/vpSSLCorpusView.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <visp3/core/vpException.h>
#include <visp3/core/vpImageConvert.h>
#include <visp3/ssl_bench/vpSSLCorpusRandom.h>
#include <visp3/ssl_bench/vpSSLCorpusTexture.h>

namespace {
const double kPi = 3.14159265358979323846;
const double kInf = std::numeric_limits<double>::infinity();

// ViSP's grey weights, read once from vpImageConvert::RGBToGrey itself (the conversion a ViSP user gets), so that
// the truth's contrast uses the same weights as the image.
struct GreyWeights
{
  double w[3];
  GreyWeights()
  {
    unsigned char rgb[9] = {250, 0, 0, 0, 250, 0, 0, 0, 250}, grey[3];
    vpImageConvert::RGBToGrey(rgb, grey, 3);
    for (int k = 0; k < 3; ++k)
      w[k] = grey[k] / 250.;
  }
};
const GreyWeights &greyWeights()
{
  static const GreyWeights g;
  return g;
}

// Rotation and translation of cMo, and the camera centre in the target frame.
struct Pose
{
  cv::Matx33d R;
  cv::Vec3d t, centre;
  explicit Pose(const vpHomogeneousMatrix &cMo)
  {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j)
        R(i, j) = cMo[i][j];
      t[i] = cMo[i][3];
    }
    centre = -(R.t() * t);
  }
  // Distance from the camera to plane point (X, Y, 0).
  double distance(double X, double Y) const
  {
    const cv::Vec3d P = R * cv::Vec3d(X, Y, 0.) + t;
    return std::sqrt(P.dot(P));
  }
};

// Largest singular value of the 2x2 Jacobian of the pixel -> plane map at (X, Y) = (hx, hy) / hw.
inline double footprint(const cv::Matx33d &Hi, double X, double Y, double hw)
{
  const double a = (Hi(0, 0) - X * Hi(2, 0)) / hw, b = (Hi(0, 1) - X * Hi(2, 1)) / hw;
  const double c = (Hi(1, 0) - Y * Hi(2, 0)) / hw, d = (Hi(1, 1) - Y * Hi(2, 1)) / hw;
  const double s = a * a + b * b + c * c + d * d, det = a * d - b * c;
  return std::sqrt(0.5 * (s + std::sqrt(std::max(0., s * s - 4. * det * det))));
}

// Whether a fish covers image point (x, y), and its albedo scale there (stripes).
inline bool fishAt(const vpSSLCorpusFish &f, double x, double y, double &stripe)
{
  const double ca = std::cos(f.angle), sa = std::sin(f.angle);
  const double a = (x - f.u) * ca + (y - f.v) * sa, b = -(x - f.u) * sa + (y - f.v) * ca;
  const double L = f.length, Wd = f.width;
  bool in = (a * a) / (0.25 * L * L) + (b * b) / (0.25 * Wd * Wd) <= 1.;
  if (!in && a < -0.4 * L && a > -0.85 * L)
    in = std::fabs(b) <= 0.5 * Wd * (-0.4 * L - a) / (0.45 * L);
  if (!in)
    return false;
  const double ph = std::fmod(a + 10. * L, f.stripePeriod);
  stripe = (ph < 0.5 * f.stripePeriod) ? f.stripe : 1.;
  return true;
}

// Radius of a disc around (fish.u - 0.22 L, fish.v ...) that contains the whole fish (body and tail).
inline double fishReach(const vpSSLCorpusFish &f)
{
  return 0.64 * f.length + 0.5 * f.width;
}
inline void fishMiddle(const vpSSLCorpusFish &f, double &x, double &y)
{
  x = f.u - 0.22 * f.length * std::cos(f.angle);
  y = f.v - 0.22 * f.length * std::sin(f.angle);
}

// Exclusion zone around a landmark's centre that no occluder may touch.
inline double centreZone(const vpSSLCorpusLandmarkTruth &t)
{
  return std::max(2., 0.2 * t.b);
}

// A background texture, 512x512 linear RGB, for the kinds drawn procedurally (photos are copied).
cv::Mat makeTexture(vpSSLCorpusViewParams::Background kind, int photo, const vpSSLCorpusPhotos &photos, uint64_t seed)
{
  vpSSLCorpusRandom rng(seed);
  const int n = 512;
  cv::Mat img(n, n, CV_32FC3);
  if (kind == vpSSLCorpusViewParams::PHOTO && photo >= 0 && static_cast<size_t>(photo) < photos.size())
    return photos.get(static_cast<size_t>(photo)).clone();
  if (kind == vpSSLCorpusViewParams::DARK_WATER) {
    img.setTo(cv::Scalar::all(0.));
    return img;
  }
  // Smooth noise: random coarse grids upsampled (cubic), mirrored so the tile repeats without seams.
  auto smooth = [&](int cells, double amp) {
    cv::Mat g(cells, cells, CV_32F), up;
    for (int i = 0; i < cells; ++i)
      for (int j = 0; j < cells; ++j)
        g.at<float>(i, j) = static_cast<float>(amp * (2. * rng.uniform() - 1.));
    cv::resize(g, up, cv::Size(n, n), 0., 0., cv::INTER_CUBIC);
    return up;
  };
  if (kind == vpSSLCorpusViewParams::STRIPES) {
    const double period = rng.uniform(8., 60.), ang = rng.uniform(0., kPi);
    const bool chess = rng.chance(0.4);
    const double dark = rng.uniform(0.02, 0.15), light = rng.uniform(0.6, 0.9);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double a = j * std::cos(ang) + i * std::sin(ang), b = -j * std::sin(ang) + i * std::cos(ang);
        bool on = std::fmod(a + 1e4 * period, period) < 0.5 * period;
        if (chess)
          on = on != (std::fmod(b + 1e4 * period, period) < 0.5 * period);
        const float v = static_cast<float>(on ? light : dark);
        img.at<cv::Vec3f>(i, j) = cv::Vec3f(v, v, v);
      }
    return img;
  }
  if (kind == vpSSLCorpusViewParams::BOARD) {
    int row = 0;
    while (row < n) {
      const int h = 30 + rng.integer(70);
      const double g = rng.uniform(0.6, 1.3);
      const cv::Vec3f base(static_cast<float>(0.45 * g), static_cast<float>(0.3 * g), static_cast<float>(0.17 * g));
      const double freq = rng.uniform(0.02, 0.08), phase = rng.uniform(0., 6.28);
      for (int i = row; i < std::min(n, row + h); ++i)
        for (int j = 0; j < n; ++j) {
          const double grain = 1. + 0.15 * std::sin(freq * j + phase + 0.3 * std::sin(0.05 * i + j * 0.01));
          const double gap = (i - row < 2 || row + h - i <= 2) ? 0.25 : 1.;
          img.at<cv::Vec3f>(i, j) = base * static_cast<float>(grain * gap);
        }
      row += h;
    }
    return img;
  }
  // Sand (also under a second sheet and under the bull's-eyes): coarse and fine variations, ripples, pebbles.
  const cv::Vec3f sand(static_cast<float>(rng.uniform(0.6, 0.85)), static_cast<float>(rng.uniform(0.55, 0.75)),
                       static_cast<float>(rng.uniform(0.38, 0.55)));
  cv::Mat coarse = smooth(6, 0.18), mid = smooth(48, 0.08);
  const bool ripples = rng.chance(0.5);
  const double rAng = rng.uniform(0., kPi), rPer = rng.uniform(20., 60.);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double v = 1. + coarse.at<float>(i, j) + mid.at<float>(i, j) + 0.06 * (rng.uniform() - 0.5);
      if (ripples)
        v += 0.12 * std::sin(2. * kPi * (j * std::cos(rAng) + i * std::sin(rAng)) / rPer + 2. * coarse.at<float>(i, j));
      img.at<cv::Vec3f>(i, j) = sand * static_cast<float>(v);
    }
  const int pebbles = rng.integer(25);
  for (int k = 0; k < pebbles; ++k) {
    const float g = static_cast<float>(rng.uniform(0.1, 0.5));
    cv::ellipse(img, cv::Point(rng.integer(n), rng.integer(n)), cv::Size(2 + rng.integer(12), 2 + rng.integer(8)),
                rng.uniform(0., 180.), 0., 360., cv::Scalar(g, g * 0.95f, g * 0.9f), -1, cv::LINE_AA);
  }
  if (kind == vpSSLCorpusViewParams::RINGS) {
    // Bull's-eyes of equal-width rings and plain discs: round, high-contrast, not self-similar.
    const int nb = 3 + rng.integer(6);
    for (int k = 0; k < nb; ++k) {
      const cv::Point c(40 + rng.integer(n - 80), 40 + rng.integer(n - 80));
      const int rings = rng.integer(7);
      const double R = rng.uniform(10., 40.);
      const float dark = static_cast<float>(rng.uniform(0.02, 0.15)), light = static_cast<float>(rng.uniform(0.6, 0.9));
      if (rings == 0) {
        cv::circle(img, c, static_cast<int>(R), cv::Scalar::all(rng.chance(0.5) ? dark : light), -1, cv::LINE_AA);
        continue;
      }
      for (int r = rings; r >= 1; --r)
        cv::circle(img, c, static_cast<int>(R * r / rings), cv::Scalar::all((r & 1) ? dark : light), -1, cv::LINE_AA);
    }
  }
  return img;
}
} // namespace

const char *vpSSLCorpusViewParams::backgroundName(Background b)
{
  switch (b) {
  case DARK_WATER:
    return "dark-water";
  case SAND:
    return "sand";
  case BOARD:
    return "board";
  case PHOTO:
    return "photo";
  case SECOND_SHEET:
    return "second-sheet";
  case STRIPES:
    return "stripes";
  case RINGS:
    return "rings";
  }
  return "?";
}

const char *vpSSLCorpusViewParams::waterName(Water w)
{
  switch (w) {
  case CLEAR:
    return "clear";
  case COASTAL:
    return "coastal";
  case TURBID:
    return "turbid";
  }
  return "?";
}

cv::Matx33d vpSSLCorpusView::homography(const vpSSLCorpusViewParams &p)
{
  const Pose pose(p.cMo);
  const cv::Matx33d K(p.camera.px, 0., p.camera.u0, 0., p.camera.py, p.camera.v0, 0., 0., 1.);
  const cv::Matx33d M(pose.R(0, 0), pose.R(0, 1), pose.t[0], pose.R(1, 0), pose.R(1, 1), pose.t[1], pose.R(2, 0),
                      pose.R(2, 1), pose.t[2]);
  return K * M;
}

std::vector<vpSSLCorpusLandmarkTruth> vpSSLCorpusView::geometry(const vpSSLTarget &target,
                                                                const vpSSLCorpusViewParams &p)
{
  std::vector<vpSSLCorpusLandmarkTruth> out;
  const Pose pose(p.cMo);
  const cv::Matx33d H = homography(p), Hi = H.inv();
  const double W = p.camera.width, Hh = p.camera.height;
  for (const vpSSLTargetLandmark &l : target.getLandmarks()) {
    vpSSLCorpusLandmarkTruth t;
    t.name = l.name;
    const cv::Vec3d c = H * cv::Vec3d(l.x, l.y, 1.);
    t.u = c[0] / c[2];
    t.v = c[1] / c[2];
    // The circle's image conic Hi^T C Hi (a point conic maps by the inverse homography).
    const double X = l.x, Y = l.y, R = l.radius;
    const cv::Matx33d C(1., 0., -X, 0., 1., -Y, -X, -Y, X * X + Y * Y - R * R);
    cv::Matx33d Q = Hi.t() * C * Hi;
    if (Q(0, 0) + Q(1, 1) < 0.)
      Q = Q * -1.;
    const double A = Q(0, 0), B = Q(0, 1), Cc = Q(1, 1), D = Q(0, 2), E = Q(1, 2), F = Q(2, 2);
    const double det = A * Cc - B * B;
    // The circle is wholly in front of the camera when its lowest depth is positive (depth is affine on the plane).
    const double zMin = pose.R(2, 0) * X + pose.R(2, 1) * Y + pose.t[2] - R * std::hypot(pose.R(2, 0), pose.R(2, 1));
    t.isEllipse = det > 0. && zMin > 0.;
    if (t.isEllipse) {
      t.ellipseU = (-D * Cc + B * E) / det;
      t.ellipseV = (-A * E + B * D) / det;
      const double F0 = F + D * t.ellipseU + E * t.ellipseV;
      const double mean = 0.5 * (A + Cc), diff = std::sqrt(0.25 * (A - Cc) * (A - Cc) + B * B);
      const double lMax = mean + diff, lMin = mean - diff;
      t.a = std::sqrt(-F0 / lMin);
      t.b = std::sqrt(-F0 / lMax);
      // 0.5 atan2(2B, A - C) is the eigenvector of the larger eigenvalue (the minor axis); the major one is normal.
      double th = 0.5 * std::atan2(2. * B, A - Cc) + 0.5 * kPi;
      if (th > 0.5 * kPi)
        th -= kPi;
      t.theta = th;
      const double hu = std::sqrt(t.a * t.a * std::cos(th) * std::cos(th) + t.b * t.b * std::sin(th) * std::sin(th));
      const double hv = std::sqrt(t.a * t.a * std::sin(th) * std::sin(th) + t.b * t.b * std::cos(th) * std::cos(th));
      t.wholeInFrame = t.ellipseU - hu >= -0.5 && t.ellipseU + hu <= W - 0.5 && t.ellipseV - hv >= -0.5 &&
                       t.ellipseV + hv <= Hh - 0.5;
    }
    t.centreInFrame = c[2] > 0. && t.u >= -0.5 && t.u < W - 0.5 && t.v >= -0.5 && t.v < Hh - 0.5;
    const cv::Vec3d ray = cv::Vec3d(l.x, l.y, 0.) - pose.centre;
    t.range = std::sqrt(ray.dot(ray));
    t.viewAngle = std::acos(std::min(1., std::fabs(ray[2]) / t.range)) * 180. / kPi;
    t.rangeOverVisibility = t.range / p.visibility;
    t.blurSigma = std::sqrt(p.gaussSigma * p.gaussSigma + p.motionLength * p.motionLength / 12.);
    // The kept sheet: the crop inside the target's sheet rectangle (what render() keeps for an SSL sheet).
    const double sl = target.getSheetCenterX() - 0.5 * target.getSheetWidth();
    const double st = target.getSheetCenterY() - 0.5 * target.getSheetHeight();
    const double left = std::max(p.cropLeft, sl), right = std::min(p.cropRight, sl + target.getSheetWidth());
    const double top = std::max(p.cropTop, st), bottom = std::min(p.cropBottom, st + target.getSheetHeight());
    t.sheetMargin = (std::min(std::min(l.x - left, right - l.x), std::min(l.y - top, bottom - l.y)) - R) / R;
    out.push_back(t);
  }
  return out;
}

vpSSLCorpusViewParams vpSSLCorpusView::draw(const vpSSLTarget &target, const vpSSLCorpusPhotos &photos, uint64_t seed,
                                            uint64_t index, bool hasTarget)
{
  vpSSLCorpusRandom rng(vpSSLCorpusRandom::mix(vpSSLCorpusRandom::mix(seed, hasTarget ? 1 : 2), index));
  vpSSLCorpusViewParams p;
  p.seed = rng.next();
  p.hasTarget = hasTarget;

  // Camera: three intrinsic sets, the principal point off the pixel grid and off the image centre.
  const double k = rng.uniform();
  vpSSLCorpusCamera &cam = p.camera;
  if (k < 0.6) {
    cam.name = "vga";
    cam.width = 640;
    cam.height = 480;
    cam.px = rng.uniform(550., 900.);
  } else if (k < 0.8) {
    cam.name = "svga";
    cam.width = 800;
    cam.height = 600;
    cam.px = rng.uniform(700., 1100.);
  } else {
    cam.name = "wide";
    cam.width = 640;
    cam.height = 480;
    cam.px = rng.uniform(330., 450.);
  }
  cam.py = cam.px * rng.uniform(0.995, 1.005);
  cam.u0 = 0.5 * (cam.width - 1) + rng.uniform(-0.03, 0.03) * cam.width;
  cam.v0 = 0.5 * (cam.height - 1) + rng.uniform(-0.03, 0.03) * cam.height;
  p.supersampling = 3;

  // Water: visibility V sets the green attenuation (contrast exp(-c V) = 2 %), red is absorbed faster, blue about
  // as fast; the veiling light is blue-green, greener and brighter as the water gets turbid.
  p.water = static_cast<vpSSLCorpusViewParams::Water>(rng.integer(3));
  static const double kBack[3][3] = {{0.03, 0.20, 0.30}, {0.06, 0.26, 0.22}, {0.16, 0.30, 0.22}};
  if (p.water == vpSSLCorpusViewParams::CLEAR)
    p.visibility = rng.uniform(8., 15.);
  else if (p.water == vpSSLCorpusViewParams::COASTAL)
    p.visibility = rng.uniform(3., 6.);
  else
    p.visibility = rng.uniform(1., 3.);
  const double cG = std::log(50.) / p.visibility;
  p.attenuation[0] = cG * rng.uniform(1.5, 2.5);
  p.attenuation[1] = cG;
  p.attenuation[2] = cG * rng.uniform(0.9, 1.3);
  const double bScale = rng.uniform(0.6, 1.4);
  for (int c = 0; c < 3; ++c)
    p.backscatter[c] = kBack[p.water][c] * bScale * rng.uniform(0.9, 1.1);

  // Pose: the line of sight to an aim point on the sheet is 0-75 deg off the normal, the range log-uniform from
  // 0.3 m to past the visibility (or to where B is 5 px), the aim point anywhere in the image, any roll.
  const double angle = rng.uniform(0., 75.) * kPi / 180.;
  const double azimuth = rng.uniform(0., 2. * kPi);
  const double rMax = std::max(0.45, std::min(1.2 * p.visibility, cam.px * target.getMaxRadius() / 5.));
  const double range = rng.logUniform(0.3, rMax);
  const cv::Vec3d aim(rng.uniform(-0.2, 0.1), rng.uniform(-0.12, 0.12), 0.);
  const double margin = rng.chance(0.1) ? -0.1 : 0.05;
  const double uAim = rng.uniform(margin, 1. - margin) * cam.width,
               vAim = rng.uniform(margin, 1. - margin) * cam.height;
  const double roll = rng.uniform(0., 2. * kPi);
  const cv::Vec3d dir(std::sin(angle) * std::cos(azimuth), std::sin(angle) * std::sin(azimuth), -std::cos(angle));
  const cv::Vec3d centre = aim + range * dir;
  // wRc = R1 Q: Q turns the aim pixel's ray onto the optical axis, R1 turns the optical axis onto -dir (the aim
  // point) with the roll about it.
  cv::Vec3d rc((uAim - cam.u0) / cam.px, (vAim - cam.v0) / cam.py, 1.);
  rc /= std::sqrt(rc.dot(rc));
  const cv::Vec3d z(0., 0., 1.);
  cv::Vec3d axis = rc.cross(z);
  const double s = std::sqrt(axis.dot(axis)), cth = rc.dot(z);
  cv::Matx33d Q = cv::Matx33d::eye();
  if (s > 1e-12) {
    axis /= s;
    const cv::Matx33d Kx(0., -axis[2], axis[1], axis[2], 0., -axis[0], -axis[1], axis[0], 0.);
    Q = cv::Matx33d::eye() + s * Kx + (1. - cth) * Kx * Kx;
  }
  const cv::Vec3d zw = -dir;
  cv::Vec3d ref = std::fabs(zw[0]) < 0.9 ? cv::Vec3d(1., 0., 0.) : cv::Vec3d(0., 1., 0.);
  cv::Vec3d xw = ref - ref.dot(zw) * zw;
  xw /= std::sqrt(xw.dot(xw));
  cv::Vec3d yw = zw.cross(xw);
  const cv::Vec3d xr = std::cos(roll) * xw + std::sin(roll) * yw, yr = zw.cross(xr);
  const cv::Matx33d R1(xr[0], yr[0], zw[0], xr[1], yr[1], zw[1], xr[2], yr[2], zw[2]);
  const cv::Matx33d wRc = R1 * Q, cRw = wRc.t();
  const cv::Vec3d tc = -(cRw * centre);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      p.cMo[i][j] = cRw(i, j);
    p.cMo[i][3] = tc[i];
  }

  // Sheet crop: the full sheet, or a sheet cut close to the landmarks (0.1-0.5 R of white past the outermost
  // ring) on some sides.
  const double sl = target.getSheetCenterX() - 0.5 * target.getSheetWidth();
  const double st = target.getSheetCenterY() - 0.5 * target.getSheetHeight();
  p.cropLeft = sl;
  p.cropTop = st;
  p.cropRight = sl + target.getSheetWidth();
  p.cropBottom = st + target.getSheetHeight();
  if (rng.chance(0.4)) {
    double ext[4] = {1e9, 1e9, -1e9, -1e9}, rad[4] = {0., 0., 0., 0.};
    for (const vpSSLTargetLandmark &l : target.getLandmarks()) {
      if (l.x - l.radius < ext[0]) {
        ext[0] = l.x - l.radius;
        rad[0] = l.radius;
      }
      if (l.y - l.radius < ext[1]) {
        ext[1] = l.y - l.radius;
        rad[1] = l.radius;
      }
      if (l.x + l.radius > ext[2]) {
        ext[2] = l.x + l.radius;
        rad[2] = l.radius;
      }
      if (l.y + l.radius > ext[3]) {
        ext[3] = l.y + l.radius;
        rad[3] = l.radius;
      }
    }
    double *side[4] = {&p.cropLeft, &p.cropTop, &p.cropRight, &p.cropBottom};
    for (int i = 0; i < 4; ++i) {
      if (!rng.chance(0.6))
        continue;
      const double m = rng.uniform(0.1, 0.5) * rad[i];
      const double cut = i < 2 ? ext[i] - m : ext[i] + m;
      *side[i] = i < 2 ? std::max(*side[i], cut) : std::min(*side[i], cut);
    }
  }
  p.paper = rng.uniform(0.55, 0.95);
  p.ink = p.paper * rng.uniform(0.03, 0.45);

  // Surroundings.
  const bool havePhotos = photos.size() > 0;
  const double b = rng.uniform();
  using P = vpSSLCorpusViewParams;
  if (hasTarget)
    p.background = b < 0.2    ? P::DARK_WATER
                   : b < 0.45 ? P::SAND
                   : b < 0.6  ? P::BOARD
                   : b < 0.85 ? P::PHOTO
                              : P::SECOND_SHEET;
  else
    p.background = b < 0.1    ? P::DARK_WATER
                   : b < 0.25 ? P::SAND
                   : b < 0.35 ? P::BOARD
                   : b < 0.6  ? P::PHOTO
                   : b < 0.7  ? P::SECOND_SHEET
                   : b < 0.85 ? P::STRIPES
                              : P::RINGS;
  if (p.background == P::PHOTO) {
    if (havePhotos)
      p.photo = rng.integer(static_cast<int>(photos.size()));
    else
      p.background = P::SAND;
  }
  p.textureMetres = rng.uniform(1., 4.);
  p.textureX = rng.uniform(-5., 5.);
  p.textureY = rng.uniform(-5., 5.);
  p.backgroundGain = rng.uniform(0.5, 1.2);
  const bool a4 = rng.chance(0.5);
  p.sheet2[0] = rng.uniform(-0.3, 0.2);
  p.sheet2[1] = rng.uniform(-0.25, 0.25);
  p.sheet2[2] = a4 ? 0.297 : 0.42;
  p.sheet2[3] = a4 ? 0.21 : 0.297;
  p.sheet2[4] = rng.uniform(0., kPi);
  p.sheet2Albedo = rng.uniform(0.5, 0.95);

  // Light and camera.
  p.ambient = rng.uniform(0.15, 1.);
  p.spot = rng.chance(0.5) ? rng.uniform(0.5, 2.) : 0.;
  p.spotWidth = rng.uniform(15., 40.) * kPi / 180.;
  p.spotX = rng.uniform(-0.2, 0.2);
  p.spotY = rng.uniform(-0.2, 0.2);
  p.vignetting = rng.uniform(0., 0.5);
  const double defocus = 2.5 * std::pow(rng.uniform(), 2.);
  const double scatter = rng.uniform(0., 1.5) * range / p.visibility;
  p.gaussSigma = std::min(4., std::hypot(defocus, scatter));
  if (rng.chance(0.3)) {
    p.motionLength = rng.uniform(1., 8.);
    p.motionAngle = rng.uniform(0., kPi);
  }
  p.exposure = rng.uniform(0.5, 0.95);
  p.noiseGain = rng.logUniform(1. / 3000., 1. / 150.);
  p.readNoise = rng.logUniform(0.002, 0.02);
  p.gamma = rng.chance(0.3) ? 1. : rng.uniform(1.8, 2.4);
  p.jpegQuality = rng.chance(0.6) ? 30 + rng.integer(66) : 0;

  // Occluders, never over a landmark's centre (the exclusion zone is centreZone()).
  std::vector<vpSSLCorpusLandmarkTruth> truth;
  if (hasTarget)
    truth = geometry(target, p);
  const vpSSLCorpusLandmarkTruth *bt = truth.empty() ? nullptr : &truth[0];
  auto clear = [&](double x, double y, double reach) {
    for (const vpSSLCorpusLandmarkTruth &t : truth)
      if (std::hypot(x - t.u, y - t.v) < reach + centreZone(t))
        return false;
    return true;
  };
  const int nbFish = rng.chance(hasTarget ? 0.35 : 0.5) ? 1 + rng.integer(hasTarget ? 4 : 8) : 0;
  for (int i = 0; i < nbFish; ++i) {
    for (int attempt = 0; attempt < 20; ++attempt) {
      vpSSLCorpusFish f;
      f.length = rng.logUniform(15., 120.);
      f.width = f.length * rng.uniform(0.25, 0.45);
      f.angle = rng.uniform(0., 2. * kPi);
      if (bt && bt->centreInFrame && rng.chance(0.5)) {
        const double r = rng.uniform(0.3, 1.5) * std::max(bt->a, 10.), ang = rng.uniform(0., 2. * kPi);
        f.u = bt->u + r * std::cos(ang);
        f.v = bt->v + r * std::sin(ang);
      } else {
        f.u = rng.uniform(0., cam.width);
        f.v = rng.uniform(0., cam.height);
      }
      f.stripePeriod = f.length * rng.uniform(0.15, 0.4);
      const double g = rng.uniform(0.2, 0.8);
      f.body[0] = g * rng.uniform(0.7, 1.1);
      f.body[1] = g * rng.uniform(0.8, 1.1);
      f.body[2] = g * rng.uniform(0.7, 1.0);
      f.stripe = rng.uniform(0.1, 0.6);
      f.distance = rng.uniform(0.2, std::max(0.25, 0.95 * range));
      double mx, my;
      fishMiddle(f, mx, my);
      if (clear(mx, my, fishReach(f))) {
        p.fish.push_back(f);
        break;
      }
    }
  }
  if (havePhotos && rng.chance(0.15)) {
    for (int attempt = 0; attempt < 30; ++attempt) {
      vpSSLCorpusPatch q;
      q.photo = rng.integer(static_cast<int>(photos.size()));
      double cu = rng.uniform(0., cam.width), cv = rng.uniform(0., cam.height), size = rng.uniform(20., 200.);
      if (!truth.empty()) {
        const vpSSLCorpusLandmarkTruth &t = truth[static_cast<size_t>(rng.integer(static_cast<int>(truth.size())))];
        const double r = rng.uniform(0.6, 1.3) * std::max(t.a, 5.), ang = rng.uniform(0., 2. * kPi);
        size = rng.uniform(0.3, 1.2) * std::max(t.a, 10.);
        cu = t.u + r * std::cos(ang);
        cv = t.v + r * std::sin(ang);
      }
      const double aspect = rng.uniform(0.5, 2.);
      q.u0 = cu - 0.5 * size * aspect;
      q.u1 = cu + 0.5 * size * aspect;
      q.v0 = cv - 0.5 * size / aspect;
      q.v1 = cv + 0.5 * size / aspect;
      q.cropX = rng.uniform();
      q.cropY = rng.uniform();
      q.distance = rng.uniform(0.2, std::max(0.25, 0.95 * range));
      bool ok = true;
      for (const vpSSLCorpusLandmarkTruth &t : truth) {
        const double z = centreZone(t);
        if (t.u > q.u0 - z && t.u < q.u1 + z && t.v > q.v0 - z && t.v < q.v1 + z)
          ok = false;
      }
      if (ok) {
        p.patch = q;
        break;
      }
    }
  }
  return p;
}

vpSSLCorpusView::vpSSLCorpusView(const vpSSLTarget &target) : m_target(target) {}

void vpSSLCorpusView::render(const vpSSLCorpusViewParams &p, const vpSSLCorpusSheet *sheet,
                             const vpSSLCorpusPhotos &photos)
{
  const int W = static_cast<int>(p.camera.width), Hh = static_cast<int>(p.camera.height);
  if (W <= 0 || Hh <= 0 || p.supersampling < 1)
    throw vpException(vpException::badValue, "vpSSLCorpusView: empty image or supersampling below 1");
  const Pose pose(p.cMo);
  const cv::Matx33d H = homography(p), Hi = H.inv();
  const bool withSheet = sheet != nullptr && p.hasTarget;
  m_truth = p.hasTarget ? geometry(m_target, p) : std::vector<vpSSLCorpusLandmarkTruth>();

  // Sheet rectangle kept: the crop, inside the sheet; an AprilTag keeps its one-cell white border.
  double crop[4] = {p.cropLeft, p.cropTop, p.cropRight, p.cropBottom};
  if (withSheet) {
    if (sheet->getContent() == vpSSLCorpusSheet::APRILTAG) {
      const double half = 0.5 * sheet->getTagSize() * 10. / 8.;
      crop[0] = std::min(crop[0], sheet->getTagX() - half);
      crop[1] = std::min(crop[1], sheet->getTagY() - half);
      crop[2] = std::max(crop[2], sheet->getTagX() + half);
      crop[3] = std::max(crop[3], sheet->getTagY() + half);
    }
    crop[0] = std::max(crop[0], sheet->getLeft());
    crop[1] = std::max(crop[1], sheet->getTop());
    crop[2] = std::min(crop[2], sheet->getLeft() + sheet->getWidth());
    crop[3] = std::min(crop[3], sheet->getTop() + sheet->getHeight());
  }
  const bool withSecond = p.background == vpSSLCorpusViewParams::SECOND_SHEET;
  const double c2 = std::cos(p.sheet2[4]), s2 = std::sin(p.sheet2[4]);

  // Image bounding box of a plane rectangle (whole image if a corner is behind the camera).
  auto bbox = [&](const cv::Vec2d *corners, cv::Rect &r) {
    double u0 = 1e9, v0 = 1e9, u1 = -1e9, v1 = -1e9;
    for (int i = 0; i < 4; ++i) {
      const cv::Vec3d q = H * cv::Vec3d(corners[i][0], corners[i][1], 1.);
      if (q[2] <= 1e-9) {
        r = cv::Rect(0, 0, W, Hh);
        return;
      }
      u0 = std::min(u0, q[0] / q[2]);
      v0 = std::min(v0, q[1] / q[2]);
      u1 = std::max(u1, q[0] / q[2]);
      v1 = std::max(v1, q[1] / q[2]);
    }
    const int iu0 = std::max(0, static_cast<int>(std::floor(u0)) - 1);
    const int iv0 = std::max(0, static_cast<int>(std::floor(v0)) - 1);
    const int iu1 = std::min(W - 1, static_cast<int>(std::ceil(u1)) + 1);
    const int iv1 = std::min(Hh - 1, static_cast<int>(std::ceil(v1)) + 1);
    r = (iu1 >= iu0 && iv1 >= iv0) ? cv::Rect(iu0, iv0, iu1 - iu0 + 1, iv1 - iv0 + 1) : cv::Rect();
  };
  cv::Rect box;
  if (withSheet) {
    const cv::Vec2d k[4] = {{crop[0], crop[1]}, {crop[2], crop[1]}, {crop[2], crop[3]}, {crop[0], crop[3]}};
    bbox(k, box);
  }
  if (withSecond) {
    cv::Vec2d k[4];
    const double hx = 0.5 * p.sheet2[2], hy = 0.5 * p.sheet2[3];
    const double sx[4] = {-hx, hx, hx, -hx}, sy[4] = {-hy, -hy, hy, hy};
    for (int i = 0; i < 4; ++i)
      k[i] = cv::Vec2d(p.sheet2[0] + c2 * sx[i] - s2 * sy[i], p.sheet2[1] + s2 * sx[i] + c2 * sy[i]);
    cv::Rect b2;
    bbox(k, b2);
    box = box.area() > 0 ? (box | b2) : b2;
  }

  // Sheet layers at output resolution, each the average of s x s samples: paper coverage of the target sheet,
  // the target sheet's mask, the second sheet's mask.
  cv::Mat A(Hh, W, CV_32F, cv::Scalar(0.f)), M1(Hh, W, CV_32F, cv::Scalar(0.f)), M2(Hh, W, CV_32F, cv::Scalar(0.f));
  const int s = p.supersampling;
  const double inv = 1. / (s * s);
  for (int v = box.y; v < box.y + box.height; ++v) {
    float *pa = A.ptr<float>(v), *p1 = M1.ptr<float>(v), *p2 = M2.ptr<float>(v);
    for (int u = box.x; u < box.x + box.width; ++u) {
      double sa = 0., s1 = 0., s2c = 0.;
      // The pyramid level follows the sample footprint, which varies little within a pixel: read at its centre.
      double level = 0.;
      if (withSheet) {
        const double hw = Hi(2, 0) * u + Hi(2, 1) * v + Hi(2, 2);
        if (hw > 0.) {
          const double X = (Hi(0, 0) * u + Hi(0, 1) * v + Hi(0, 2)) / hw;
          const double Y = (Hi(1, 0) * u + Hi(1, 1) * v + Hi(1, 2)) / hw;
          level = sheet->getTexture().level(footprint(Hi, X, Y, hw) / s);
        }
      }
      for (int i = 0; i < s; ++i) {
        const double vs = v - 0.5 + (i + 0.5) / s;
        for (int j = 0; j < s; ++j) {
          const double us = u - 0.5 + (j + 0.5) / s;
          const double hw = Hi(2, 0) * us + Hi(2, 1) * vs + Hi(2, 2);
          if (hw <= 0.)
            continue; // the plane is behind the camera there
          const double X = (Hi(0, 0) * us + Hi(0, 1) * vs + Hi(0, 2)) / hw;
          const double Y = (Hi(1, 0) * us + Hi(1, 1) * vs + Hi(1, 2)) / hw;
          if (withSheet && X >= crop[0] && X < crop[2] && Y >= crop[1] && Y < crop[3]) {
            float val;
            sheet->getTexture().sampleLevel(X, Y, level, &val);
            sa += val;
            s1 += 1.;
          } else if (withSecond) {
            const double dx = X - p.sheet2[0], dy = Y - p.sheet2[1];
            if (std::fabs(c2 * dx + s2 * dy) < 0.5 * p.sheet2[2] && std::fabs(-s2 * dx + c2 * dy) < 0.5 * p.sheet2[3])
              s2c += 1.;
          }
        }
      }
      pa[u] = static_cast<float>(sa * inv);
      p1[u] = static_cast<float>(s1 * inv);
      p2[u] = static_cast<float>(s2c * inv);
    }
  }

  // Surroundings, light and water, per output pixel.
  const bool planeBackground = p.background != vpSSLCorpusViewParams::DARK_WATER;
  vpSSLCorpusTexture bgTex;
  if (planeBackground) {
    cv::Mat tex = makeTexture(p.background, p.photo, photos, vpSSLCorpusRandom::mix(p.seed, 7));
    bgTex.set(tex, p.textureX, p.textureY, tex.cols / p.textureMetres, vpSSLCorpusTexture::MIRROR, 0.f);
  }
  const double spotN = std::sqrt(p.spotX * p.spotX + p.spotY * p.spotY + 1.);
  auto light = [&](double u, double v, double d) {
    if (p.spot <= 0.)
      return p.ambient;
    const double x = (u - p.camera.u0) / p.camera.px, y = (v - p.camera.v0) / p.camera.py;
    const double cosA = (x * p.spotX + y * p.spotY + 1.) / (std::sqrt(x * x + y * y + 1.) * spotN);
    const double ang = std::acos(std::min(1., cosA));
    return p.ambient + p.spot * std::exp(-(ang / p.spotWidth) * (ang / p.spotWidth)) * std::min(1., 1. / (d * d)) *
                           std::exp(-p.attenuation[1] * d);
  };
  cv::Mat lin(Hh, W, CV_32FC3);
  for (int v = 0; v < Hh; ++v) {
    const float *pa = A.ptr<float>(v), *p1 = M1.ptr<float>(v), *p2 = M2.ptr<float>(v);
    cv::Vec3f *out = lin.ptr<cv::Vec3f>(v);
    for (int u = 0; u < W; ++u) {
      const double hw = Hi(2, 0) * u + Hi(2, 1) * v + Hi(2, 2);
      double dPlane = kInf, X = 0., Y = 0.;
      if (hw > 0.) {
        X = (Hi(0, 0) * u + Hi(0, 1) * v + Hi(0, 2)) / hw;
        Y = (Hi(1, 0) * u + Hi(1, 1) * v + Hi(1, 2)) / hw;
        dPlane = pose.distance(X, Y);
      }
      float bg[3] = {0.f, 0.f, 0.f};
      double dBg = kInf;
      if (planeBackground && hw > 0.) {
        bgTex.sample(X, Y, footprint(Hi, X, Y, hw), bg);
        dBg = dPlane;
      }
      const double cover = std::min(1., static_cast<double>(p1[u] + p2[u]));
      // The background is either on the sheet's plane (same distance and light) or at infinity.
      const double Es = std::isfinite(dPlane) ? light(u, v, dPlane) : 0.;
      const double Eb = Es;
      const double Js = pa[u] * (p.paper - p.ink) + p1[u] * p.ink + p2[u] * p.sheet2Albedo; // coverage-weighted
      for (int c = 0; c < 3; ++c) {
        const double Ts = std::isfinite(dPlane) ? std::exp(-p.attenuation[c] * dPlane) : 0.;
        const double Tb = std::isfinite(dBg) ? Ts : 0.;
        const double sheetPart = Es * Js * Ts + cover * p.backscatter[c] * (1. - Ts);
        const double bgPart = (1. - cover) * (Eb * bg[c] * p.backgroundGain * Tb + p.backscatter[c] * (1. - Tb));
        out[u][c] = static_cast<float>(sheetPart + bgPart);
      }
    }
  }

  // Occluders in the water in front of the sheet: coverage O for the truth, colour with their own water.
  cv::Mat O(Hh, W, CV_32F, cv::Scalar(0.f));
  for (const vpSSLCorpusFish &f : p.fish) {
    double mx, my;
    fishMiddle(f, mx, my);
    const double reach = fishReach(f);
    const int u0 = std::max(0, static_cast<int>(mx - reach) - 1),
              u1 = std::min(W - 1, static_cast<int>(mx + reach) + 1);
    const int v0 = std::max(0, static_cast<int>(my - reach) - 1),
              v1 = std::min(Hh - 1, static_cast<int>(my + reach) + 1);
    for (int v = v0; v <= v1; ++v)
      for (int u = u0; u <= u1; ++u) {
        double cov = 0., alb = 0.;
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j) {
            double st;
            if (fishAt(f, u - 0.5 + (j + 0.5) / 4., v - 0.5 + (i + 0.5) / 4., st)) {
              cov += 1. / 16.;
              alb += st / 16.;
            }
          }
        if (cov <= 0.)
          continue;
        const double E = light(u, v, f.distance);
        cv::Vec3f &o = lin.at<cv::Vec3f>(v, u);
        for (int c = 0; c < 3; ++c) {
          const double T = std::exp(-p.attenuation[c] * f.distance);
          o[c] = static_cast<float>((1. - cov) * o[c] + E * alb * f.body[c] * T + cov * p.backscatter[c] * (1. - T));
        }
        O.at<float>(v, u) = std::min(1.f, O.at<float>(v, u) + static_cast<float>(cov));
      }
  }
  if (p.patch.photo >= 0 && static_cast<size_t>(p.patch.photo) < photos.size()) {
    const vpSSLCorpusPatch &q = p.patch;
    const cv::Mat &img = photos.get(static_cast<size_t>(q.photo));
    const int u0 = std::max(0, static_cast<int>(std::floor(q.u0 + 0.5))),
              u1 = std::min(W - 1, static_cast<int>(std::ceil(q.u1 - 0.5)));
    const int v0 = std::max(0, static_cast<int>(std::floor(q.v0 + 0.5))),
              v1 = std::min(Hh - 1, static_cast<int>(std::ceil(q.v1 - 0.5)));
    const double ox = q.cropX * std::max(0., img.cols - (q.u1 - q.u0) - 1.);
    const double oy = q.cropY * std::max(0., img.rows - (q.v1 - q.v0) - 1.);
    for (int v = v0; v <= v1; ++v)
      for (int u = u0; u <= u1; ++u) {
        // Exact area of the pixel square inside the rectangle.
        const double cu = std::max(0., std::min(u + 0.5, q.u1) - std::max(u - 0.5, q.u0));
        const double cv = std::max(0., std::min(v + 0.5, q.v1) - std::max(v - 0.5, q.v0));
        const double cov = cu * cv;
        if (cov <= 0.)
          continue;
        const int px = std::min(img.cols - 1, std::max(0, static_cast<int>(ox + u - q.u0)));
        const int py = std::min(img.rows - 1, std::max(0, static_cast<int>(oy + v - q.v0)));
        const cv::Vec3f &J = img.at<cv::Vec3f>(py, px);
        const double E = light(u, v, q.distance);
        cv::Vec3f &o = lin.at<cv::Vec3f>(v, u);
        for (int c = 0; c < 3; ++c) {
          const double T = std::exp(-p.attenuation[c] * q.distance);
          o[c] = static_cast<float>((1. - cov) * o[c] + cov * (E * J[c] * T + p.backscatter[c] * (1. - T)));
        }
        O.at<float>(v, u) = std::min(1.f, O.at<float>(v, u) + static_cast<float>(cov));
      }
  }

  // Vignetting, then the optics' blur.
  const double rc2 = std::max(p.camera.u0 * p.camera.u0, (W - p.camera.u0) * (W - p.camera.u0)) +
                     std::max(p.camera.v0 * p.camera.v0, (Hh - p.camera.v0) * (Hh - p.camera.v0));
  auto vignette = [&](double u, double v) {
    return 1. - p.vignetting * ((u - p.camera.u0) * (u - p.camera.u0) + (v - p.camera.v0) * (v - p.camera.v0)) / rc2;
  };
  for (int v = 0; v < Hh; ++v) {
    cv::Vec3f *o = lin.ptr<cv::Vec3f>(v);
    for (int u = 0; u < W; ++u)
      o[u] *= static_cast<float>(vignette(u, v));
  }
  if (p.gaussSigma > 0.05)
    cv::GaussianBlur(lin, lin, cv::Size(0, 0), p.gaussSigma, p.gaussSigma, cv::BORDER_REFLECT);
  if (p.motionLength > 0.5) {
    // A segment of the given length, splatted bilinearly at 256 points: the average of the image along the motion.
    const int half = static_cast<int>(std::ceil(0.5 * p.motionLength)) + 1;
    cv::Mat kernel(2 * half + 1, 2 * half + 1, CV_32F, cv::Scalar(0.f));
    for (int i = 0; i < 256; ++i) {
      const double t = ((i + 0.5) / 256. - 0.5) * p.motionLength;
      const double x = half + t * std::cos(p.motionAngle), y = half + t * std::sin(p.motionAngle);
      const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
      const float ax = static_cast<float>(x - x0), ay = static_cast<float>(y - y0);
      kernel.at<float>(y0, x0) += (1 - ax) * (1 - ay);
      kernel.at<float>(y0, x0 + 1) += ax * (1 - ay);
      kernel.at<float>(y0 + 1, x0) += (1 - ax) * ay;
      kernel.at<float>(y0 + 1, x0 + 1) += ax * ay;
    }
    kernel /= cv::sum(kernel)[0];
    cv::filter2D(lin, lin, -1, kernel, cv::Point(-1, -1), 0., cv::BORDER_REFLECT);
  }

  // Exposure: the 99th percentile of ViSP's luminance goes to p.exposure.
  const double *w = greyWeights().w;
  std::vector<float> lum(static_cast<size_t>(W) * Hh);
  for (int v = 0; v < Hh; ++v) {
    const cv::Vec3f *o = lin.ptr<cv::Vec3f>(v);
    for (int u = 0; u < W; ++u)
      lum[static_cast<size_t>(v) * W + u] = static_cast<float>(w[0] * o[u][0] + w[1] * o[u][1] + w[2] * o[u][2]);
  }
  const size_t k99 = lum.size() * 99 / 100;
  std::nth_element(lum.begin(), lum.begin() + static_cast<long>(k99), lum.end());
  m_exposureScale = p.exposure / std::max(1e-6, static_cast<double>(lum[k99]));
  lin *= m_exposureScale;

  // Sensor: Poisson-Gaussian noise (Gaussian with variance a x + b^2), gamma, 8 bits.
  cv::Mat noise(Hh, W, CV_32FC3);
  cv::RNG cvRng(vpSSLCorpusRandom::mix(p.seed, 11));
  cvRng.fill(noise, cv::RNG::NORMAL, 0., 1.);
  m_colour.create(Hh, W, CV_8UC3);
  const double invGamma = 1. / p.gamma;
  // Gamma through a table of 2^16 + 1 linear levels (an error below 1e-5 before the 8-bit rounding).
  std::vector<unsigned char> gammaLut(65537);
  for (size_t i = 0; i < gammaLut.size(); ++i)
    gammaLut[i] = static_cast<unsigned char>(std::lround(255. * std::pow(i / 65536., invGamma)));
  for (int v = 0; v < Hh; ++v) {
    const cv::Vec3f *o = lin.ptr<cv::Vec3f>(v), *n = noise.ptr<cv::Vec3f>(v);
    cv::Vec3b *out = m_colour.ptr<cv::Vec3b>(v);
    for (int u = 0; u < W; ++u)
      for (int c = 0; c < 3; ++c) {
        const double x = o[u][c];
        double y = x + std::sqrt(p.noiseGain * std::max(0., x) + p.readNoise * p.readNoise) * n[u][c];
        y = std::min(1., std::max(0., y));
        out[u][c] = gammaLut[static_cast<size_t>(y * 65536. + 0.5)];
      }
  }
  if (p.jpegQuality > 0) {
    cv::Mat bgr;
    cv::cvtColor(m_colour, bgr, cv::COLOR_RGB2BGR);
    std::vector<unsigned char> buf;
    cv::imencode(".jpg", bgr, buf, {cv::IMWRITE_JPEG_QUALITY, p.jpegQuality});
    bgr = cv::imdecode(buf, cv::IMREAD_COLOR);
    cv::cvtColor(bgr, m_colour, cv::COLOR_BGR2RGB);
  }
  m_grey.resize(static_cast<unsigned int>(Hh), static_cast<unsigned int>(W));
  vpImageConvert::RGBToGrey(m_colour.data, m_grey.bitmap, static_cast<unsigned int>(W * Hh));

  // Photometric truth per landmark: paper and ink through the same light, water, vignetting, exposure and gamma at
  // the landmark's centre; the noise sigma propagated through the gamma at both levels.
  for (vpSSLCorpusLandmarkTruth &t : m_truth) {
    const double uc = std::min(W - 1., std::max(0., t.u)), vc = std::min(Hh - 1., std::max(0., t.v));
    const double E = light(uc, vc, t.range), vig = vignette(uc, vc);
    double grey[2] = {0., 0.}, var[2] = {0., 0.};
    for (int k = 0; k < 2; ++k) {
      const double albedo = k == 0 ? p.paper : p.ink;
      for (int c = 0; c < 3; ++c) {
        const double T = std::exp(-p.attenuation[c] * t.range);
        const double x = (E * albedo * T + p.backscatter[c] * (1. - T)) * vig * m_exposureScale;
        const double xc = std::min(1., x);
        grey[k] += w[c] * 255. * std::pow(xc, invGamma);
        const double slope = x >= 1. ? 0. : 255. * invGamma * std::pow(std::max(x, 1e-6), invGamma - 1.);
        const double sigma = std::sqrt(p.noiseGain * x + p.readNoise * p.readNoise);
        var[k] += (w[c] * slope * sigma) * (w[c] * slope * sigma);
      }
    }
    t.contrast = std::fabs(grey[0] - grey[1]);
    t.noiseSigma = std::sqrt(0.5 * (var[0] + var[1]) + 1. / 12.);
    t.contrastOverNoise = t.contrast / t.noiseSigma;
    // Occlusion of the outer disc (pixel centres inside the true ellipse, in the frame).
    if (t.isEllipse) {
      const double ct = std::cos(t.theta), st = std::sin(t.theta);
      const int u0 = std::max(0, static_cast<int>(std::floor(t.ellipseU - t.a)));
      const int u1 = std::min(W - 1, static_cast<int>(std::ceil(t.ellipseU + t.a)));
      const int v0 = std::max(0, static_cast<int>(std::floor(t.ellipseV - t.a)));
      const int v1 = std::min(Hh - 1, static_cast<int>(std::ceil(t.ellipseV + t.a)));
      double sum = 0.;
      long n = 0;
      for (int v = v0; v <= v1; ++v)
        for (int u = u0; u <= u1; ++u) {
          const double du = u - t.ellipseU, dv = v - t.ellipseV;
          const double x = du * ct + dv * st, y = -du * st + dv * ct;
          if (x * x / (t.a * t.a) + y * y / (t.b * t.b) <= 1.) {
            sum += O.at<float>(v, u);
            ++n;
          }
        }
      t.occludedFraction = n > 0 ? sum / n : 0.;
    }
    if (t.centreInFrame) {
      const int iu = static_cast<int>(std::lround(t.u)), iv = static_cast<int>(std::lround(t.v));
      t.centreOccluded = O.at<float>(std::min(Hh - 1, std::max(0, iv)), std::min(W - 1, std::max(0, iu))) > 0.f;
    }
  }
}
