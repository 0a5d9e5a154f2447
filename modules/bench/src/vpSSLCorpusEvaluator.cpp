#include <visp3/ssl_bench/vpSSLCorpusEvaluator.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

namespace {
std::string fmt(const char *f, double a)
{
  char buf[64];
  std::snprintf(buf, sizeof(buf), f, a);
  return buf;
}

double percentile(std::vector<double> v, double q)
{
  if (v.empty())
    return std::nan("");
  std::sort(v.begin(), v.end());
  const double pos = q * (v.size() - 1);
  const size_t i = static_cast<size_t>(pos);
  const double f = pos - i;
  return i + 1 < v.size() ? v[i] * (1. - f) + v[i + 1] * f : v[i];
}

// Cell "found% (n)", or "-" without views.
std::string cell(unsigned int found, unsigned int n)
{
  if (n == 0)
    return "-";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.1f %% (%u)", 100. * found / n, n);
  return buf;
}

struct Bin
{
  std::string label;
  double lo, hi;
};

const char *kNames[3] = {"B", "S1", "S2"};
} // namespace

void vpSSLCorpusEvaluator::match(const vpSSLDetector &detector, vpSSLCorpusViewResult &r)
{
  const std::vector<vpSSLLandmark> &dets = detector.getLandmarks();
  r.nbDetections = static_cast<unsigned int>(dets.size());
  r.results.assign(r.truth.size(), vpSSLCorpusLandmarkResult());
  std::vector<char> used(dets.size(), 0);
  for (size_t i = 0; i < r.truth.size(); ++i) {
    const vpSSLCorpusLandmarkTruth &t = r.truth[i];
    vpSSLCorpusLandmarkResult &res = r.results[i];
    double best = kCentreTolerance * t.a;
    int bestIndex = -1;
    for (size_t k = 0; k < dets.size(); ++k) {
      const double e = std::hypot(dets[k].u - t.u, dets[k].v - t.v);
      if (e <= kCentreTolerance * t.a)
        used[k] = 1; // near a true landmark: not a false one, even if another detection is nearer
      if (e <= best) {
        best = e;
        bestIndex = static_cast<int>(k);
      }
    }
    if (bestIndex >= 0) {
      const vpSSLLandmark &d = dets[static_cast<size_t>(bestIndex)];
      res.found = true;
      res.u = d.u;
      res.v = d.v;
      res.radius = d.radius;
      res.centreError = best;
      res.radiusError = (d.radius - t.a) / t.a;
      res.radiusOk = std::fabs(res.radiusError) <= kRadiusTolerance;
    }
    const vpSSLLandmark *m = detector.getMatchedLandmark(i);
    res.labelled = m != nullptr && std::hypot(m->u - t.u, m->v - t.v) <= kCentreTolerance * t.a;
  }
  r.falseLandmarks = 0;
  for (char u : used)
    r.falseLandmarks += u ? 0 : 1;
  r.targetFound = detector.getTargetMatch().found;
  // B is the target's largest landmark (index 0 for ssl3-a3).
  r.targetCorrect = r.targetFound && !r.results.empty() && r.results[0].labelled;
  // A label on a detection that is no landmark of that size misreads the range; two landmarks of one size swapped
  // (S1 and S2, which two landmarks alone cannot tell apart) do not, and are counted by the labelled column only.
  const vpSSLTarget &target = detector.getTarget();
  bool wrongLabel = r.truth.empty() && r.targetFound;
  for (size_t i = 0; i < r.truth.size() && i < target.size(); ++i) {
    const vpSSLLandmark *m = detector.getMatchedLandmark(i);
    if (m == nullptr || r.results[i].labelled) {
      continue;
    }
    bool sameSize = false;
    for (size_t j = 0; j < r.truth.size() && j < target.size(); ++j) {
      const vpSSLCorpusLandmarkTruth &t = r.truth[j];
      sameSize = sameSize || (j != i && target.getLandmark(j).radius == target.getLandmark(i).radius &&
                              std::hypot(m->u - t.u, m->v - t.v) <= kCentreTolerance * t.a);
    }
    wrongLabel = wrongLabel || !sameSize;
  }
  r.falseTarget = wrongLabel;
}

void vpSSLCorpusEvaluator::matchTag(const std::vector<std::vector<vpImagePoint>> &polygons, const std::vector<int> &ids,
                                    const std::vector<vpImagePoint> &corners, int id, unsigned int width,
                                    unsigned int height, vpSSLCorpusViewResult &r)
{
  r.tagRun = true;
  r.tagWholeInFrame = !corners.empty();
  double cu = 0., cv = 0., side = 0.;
  for (size_t i = 0; i < corners.size(); ++i) {
    const vpImagePoint &c = corners[i];
    if (c.get_u() < -0.5 || c.get_v() < -0.5 || c.get_u() > width - 0.5 || c.get_v() > height - 0.5)
      r.tagWholeInFrame = false;
    const vpImagePoint &n = corners[(i + 1) % corners.size()];
    side += vpImagePoint::distance(c, n) / corners.size();
  }
  // The tag's centre is where its diagonals cross (the projection of the square's centre).
  if (corners.size() == 4) {
    const double x1 = corners[0].get_u(), y1 = corners[0].get_v(), x2 = corners[2].get_u(), y2 = corners[2].get_v();
    const double x3 = corners[1].get_u(), y3 = corners[1].get_v(), x4 = corners[3].get_u(), y4 = corners[3].get_v();
    const double den = (x1 - x2) * (y3 - y4) - (y1 - y2) * (x3 - x4);
    const double a = x1 * y2 - y1 * x2, b = x3 * y4 - y3 * x4;
    cu = (a * (x3 - x4) - (x1 - x2) * b) / den;
    cv = (a * (y3 - y4) - (y1 - y2) * b) / den;
  }
  r.tagFound = false;
  r.tagFalse = 0;
  for (size_t i = 0; i < ids.size(); ++i) {
    double u = 0., v = 0.;
    for (const vpImagePoint &q : polygons[i]) {
      u += q.get_u() / polygons[i].size();
      v += q.get_v() / polygons[i].size();
    }
    if (ids[i] == id && !r.tagFound && std::hypot(u - cu, v - cv) <= kCentreTolerance * 0.5 * side)
      r.tagFound = true;
    else
      ++r.tagFalse;
  }
}

double vpSSLCorpusEvaluator::recall(const std::string &name, unsigned int &n) const
{
  unsigned int found = 0;
  n = 0;
  for (const vpSSLCorpusViewResult &r : m_results)
    for (size_t i = 0; i < r.truth.size(); ++i)
      if (r.truth[i].name == name && r.truth[i].eligible()) {
        ++n;
        found += r.results[i].found ? 1 : 0;
      }
  return n ? static_cast<double>(found) / n : 0.;
}

unsigned int vpSSLCorpusEvaluator::falseTargetsOnNegatives(unsigned int &n) const
{
  unsigned int f = 0;
  n = 0;
  for (const vpSSLCorpusViewResult &r : m_results)
    if (!r.params.hasTarget) {
      ++n;
      f += r.falseTarget ? 1 : 0;
    }
  return f;
}

unsigned int vpSSLCorpusEvaluator::falseTargetsOnPositives() const
{
  unsigned int f = 0;
  for (const vpSSLCorpusViewResult &r : m_results)
    if (r.params.hasTarget)
      f += r.falseTarget ? 1 : 0;
  return f;
}

void vpSSLCorpusEvaluator::printTables(std::ostream &os) const
{
  unsigned int nPos = 0, nNeg = 0;
  for (const vpSSLCorpusViewResult &r : m_results)
    (r.params.hasTarget ? nPos : nNeg)++;
  const bool tags =
      std::any_of(m_results.begin(), m_results.end(), [](const vpSSLCorpusViewResult &r) { return r.tagRun; });

  // Headline.
  os << "### Eligible landmarks (whole in frame, radius >= 8 px, centre not occluded, contrast >= 3 noise sigma)\n\n";
  os << "| landmark | eligible | found | found, radius within 10 % | labelled by the target match | centre error "
        "median / p90 (px) | radius error median / p90 |\n|---|---|---|---|---|---|---|\n";
  for (const char *name : kNames) {
    unsigned int n = 0, found = 0, rok = 0, lab = 0;
    std::vector<double> ce, re;
    for (const vpSSLCorpusViewResult &r : m_results)
      for (size_t i = 0; i < r.truth.size(); ++i)
        if (r.truth[i].name == name && r.truth[i].eligible()) {
          ++n;
          const vpSSLCorpusLandmarkResult &x = r.results[i];
          found += x.found;
          rok += x.radiusOk;
          lab += x.labelled;
          if (x.found) {
            ce.push_back(x.centreError);
            re.push_back(std::fabs(x.radiusError));
          }
        }
    os << "| " << name << " | " << n << " | " << cell(found, n) << " | " << cell(rok, n) << " | " << cell(lab, n)
       << " | " << fmt("%.2f", percentile(ce, 0.5)) << " / " << fmt("%.2f", percentile(ce, 0.9)) << " | "
       << fmt("%.1f %%", 100. * percentile(re, 0.5)) << " / " << fmt("%.1f %%", 100. * percentile(re, 0.9)) << " |\n";
  }
  unsigned int nAll = 0, tAll = 0, nB = 0, tB = 0;
  for (const vpSSLCorpusViewResult &r : m_results) {
    if (!r.params.hasTarget || r.truth.size() < 3)
      continue;
    if (r.truth[0].eligible()) {
      ++nB;
      tB += r.targetCorrect;
    }
    if (r.truth[0].eligible() && r.truth[1].eligible() && r.truth[2].eligible()) {
      ++nAll;
      tAll += r.targetCorrect;
    }
  }
  os << "\nTarget identified with the right B: " << cell(tB, nB) << " of the views where B is eligible, "
     << cell(tAll, nAll) << " of the views where B, S1 and S2 all are.\n\n";

  unsigned int falsePos = 0, falseNeg = 0, ftNeg = 0, ftPos = 0;
  double ms = 0.;
  for (const vpSSLCorpusViewResult &r : m_results) {
    (r.params.hasTarget ? falsePos : falseNeg) += r.falseLandmarks;
    if (r.falseTarget)
      (r.params.hasTarget ? ftPos : ftNeg)++;
    ms += r.detectMs;
  }
  os << "False landmarks per image: " << fmt("%.3f", nPos ? static_cast<double>(falsePos) / nPos : 0.) << " on the "
     << nPos << " target views, " << fmt("%.3f", nNeg ? static_cast<double>(falseNeg) / nNeg : 0.) << " on the " << nNeg
     << " negatives. False targets: " << ftNeg << " of " << nNeg << " negatives, " << ftPos << " of " << nPos
     << " target views (a landmark labelled as one of another size, or on no landmark). Detector time: "
     << fmt("%.2f", m_results.empty() ? 0. : ms / m_results.size()) << " ms per image (one thread).\n\n";

  // Tables by one variable; the other headline conditions hold (whole in frame, centre not occluded, radius >= 8
  // px unless binned by radius, contrast >= 3 sigma unless binned by contrast).
  struct Table
  {
    std::string title;
    std::vector<Bin> bins;
    std::function<double(const vpSSLCorpusViewResult &, const vpSSLCorpusLandmarkTruth &)> value;
    bool radius, contrast;
    // Only landmarks seen at most this far off their normal (deg).
    double maxViewAngle = 1e300;
  };
  const double inf = 1e300;
  // Ring widths are proportional to the minor semi-axis: this ratio says how many blur sigmas the rings span across
  // their narrowest direction, which decides whether they survive the blur. A view without blur falls in the top bin.
  const Table minorOverBlur = {"minor semi-axis / blur sigma",
                               {{"0-4", 0, 4}, {"4-8", 4, 8}, {"8-16", 8, 16}, {"16-32", 16, 32}, {"32+", 32, inf}},
                               [](const vpSSLCorpusViewResult &, const vpSSLCorpusLandmarkTruth &t) {
                                 return t.b / std::max(t.blurSigma, 1e-6);
                               },
                               false,
                               false};
  // The same within 60 degrees of the normal, where an oblique view's foreshortening does not add to the blur's toll.
  Table minorOverBlurNear = minorOverBlur;
  minorOverBlurNear.title += ", view angle <= 60 deg";
  minorOverBlurNear.maxViewAngle = 60.;
  std::vector<Table> tables = {
      {"view angle (deg)",
       {{"0-20", 0, 20}, {"20-40", 20, 40}, {"40-55", 40, 55}, {"55-60", 55, 60}, {"60-70", 60, 70}, {"70+", 70, inf}},
       [](const vpSSLCorpusViewResult &, const vpSSLCorpusLandmarkTruth &t) { return t.viewAngle; },
       false,
       false},
      {"radius (px)",
       {{"4-8", 4, 8},
        {"8-12", 8, 12},
        {"12-16", 12, 16},
        {"16-26", 16, 26},
        {"26-50", 26, 50},
        {"50-100", 50, 100},
        {"100+", 100, inf}},
       [](const vpSSLCorpusViewResult &, const vpSSLCorpusLandmarkTruth &t) { return t.a; },
       true,
       false},
      {"range / visibility",
       {{"0-0.25", 0, 0.25}, {"0.25-0.5", 0.25, 0.5}, {"0.5-0.75", 0.5, 0.75}, {"0.75+", 0.75, inf}},
       [](const vpSSLCorpusViewResult &, const vpSSLCorpusLandmarkTruth &t) { return t.rangeOverVisibility; },
       false,
       false},
      {"blur sigma (px, Gaussian and motion)",
       {{"0-0.5", 0, 0.5}, {"0.5-1", 0.5, 1}, {"1-1.5", 1, 1.5}, {"1.5-2", 1.5, 2}, {"2-3", 2, 3}, {"3+", 3, inf}},
       [](const vpSSLCorpusViewResult &, const vpSSLCorpusLandmarkTruth &t) { return t.blurSigma; },
       false,
       false},
      minorOverBlur,
      minorOverBlurNear,
      {"contrast / noise sigma",
       {{"0-3", 0, 3}, {"3-5", 3, 5}, {"5-10", 5, 10}, {"10-20", 10, 20}, {"20-50", 20, 50}, {"50+", 50, inf}},
       [](const vpSSLCorpusViewResult &, const vpSSLCorpusLandmarkTruth &t) { return t.contrastOverNoise; },
       false,
       true},
      {"water",
       {{"clear", 0, 0.5}, {"coastal", 0.5, 1.5}, {"turbid", 1.5, 2.5}},
       [](const vpSSLCorpusViewResult &r, const vpSSLCorpusLandmarkTruth &) { return double(r.params.water); },
       false,
       false},
      {"surroundings",
       {{"dark-water", -0.5, 0.5},
        {"sand", 0.5, 1.5},
        {"board", 1.5, 2.5},
        {"photo", 2.5, 3.5},
        {"second-sheet", 3.5, 4.5}},
       [](const vpSSLCorpusViewResult &r, const vpSSLCorpusLandmarkTruth &) { return double(r.params.background); },
       false,
       false},
      {"white margin beyond the outer ring (radii)",
       {{"0-0.25", -1, 0.25}, {"0.25-0.5", 0.25, 0.5}, {"0.5-1", 0.5, 1}, {"1+", 1, inf}},
       [](const vpSSLCorpusViewResult &, const vpSSLCorpusLandmarkTruth &t) { return t.sheetMargin; },
       false,
       false},
      {"occluded fraction of the outer disc",
       {{"0", -1, 1e-9}, {"0-0.1", 1e-9, 0.1}, {"0.1-0.25", 0.1, 0.25}, {"0.25+", 0.25, inf}},
       [](const vpSSLCorpusViewResult &, const vpSSLCorpusLandmarkTruth &t) { return t.occludedFraction; },
       false,
       false},
      {"JPEG quality",
       {{"none", -1, 0.5}, {"30-50", 0.5, 50}, {"50-75", 50, 75}, {"75-95", 75, inf}},
       [](const vpSSLCorpusViewResult &r, const vpSSLCorpusLandmarkTruth &) { return double(r.params.jpegQuality); },
       false,
       false}};
  for (const Table &tb : tables) {
    os << "#### Recall by " << tb.title << "\n\n| " << tb.title << " | B | S1 | S2 |";
    if (tags)
      os << " target (right B) | AprilTag |";
    os << "\n|---|---|---|---|" << (tags ? "---|---|" : "") << "\n";
    for (const Bin &b : tb.bins) {
      os << "| " << b.label << " |";
      for (const char *name : kNames) {
        unsigned int n = 0, f = 0;
        for (const vpSSLCorpusViewResult &r : m_results)
          for (size_t i = 0; i < r.truth.size(); ++i) {
            const vpSSLCorpusLandmarkTruth &t = r.truth[i];
            if (t.name != name || !t.wholeInFrame || t.centreOccluded || (!tb.radius && t.a < 8.) ||
                (!tb.contrast && t.contrastOverNoise < 3.) || t.viewAngle > tb.maxViewAngle)
              continue;
            const double x = tb.value(r, t);
            if (x < b.lo || x >= b.hi)
              continue;
            ++n;
            f += r.results[i].found;
          }
        os << " " << cell(f, n) << " |";
      }
      if (tags) {
        // Equal terms: the views where B passes this table's conditions and the tag is wholly in the image; the
        // bins are B's.
        unsigned int n = 0, ft = 0, fa = 0;
        for (const vpSSLCorpusViewResult &r : m_results) {
          if (r.truth.empty() || !r.tagRun || !r.tagWholeInFrame)
            continue;
          const vpSSLCorpusLandmarkTruth &t = r.truth[0];
          if (!t.wholeInFrame || t.centreOccluded || (!tb.radius && t.a < 8.) ||
              (!tb.contrast && t.contrastOverNoise < 3.) || t.viewAngle > tb.maxViewAngle)
            continue;
          const double x = tb.value(r, t);
          if (x < b.lo || x >= b.hi)
            continue;
          ++n;
          ft += r.targetCorrect;
          fa += r.tagFound;
        }
        os << " " << cell(ft, n) << " | " << cell(fa, n) << " |";
      }
      os << "\n";
    }
    os << "\n";
  }
  if (tags) {
    unsigned int n = 0, ft = 0, fa = 0, negTags = 0, nNegTag = 0;
    double ms = 0.;
    for (const vpSSLCorpusViewResult &r : m_results) {
      if (!r.tagRun)
        continue;
      ms += r.tagMs;
      if (!r.params.hasTarget) {
        ++nNegTag;
        negTags += r.tagFalse + (r.tagFound ? 1 : 0);
        continue;
      }
      if (!r.truth.empty() && r.truth[0].eligible() && r.tagWholeInFrame) {
        ++n;
        ft += r.targetCorrect;
        fa += r.tagFound;
      }
    }
    os << "AprilTag baseline (same poses, water and camera, tag rendering): B eligible and tag whole in frame: SSL "
          "target "
       << cell(ft, n) << ", AprilTag " << cell(fa, n) << "; tags detected on " << nNegTag << " negatives: " << negTags
       << "; AprilTag time " << fmt("%.2f", ms / std::max<size_t>(1, m_results.size())) << " ms per image.\n\n";
  }
}

void vpSSLCorpusEvaluator::writeCsv(std::ostream &os) const
{
  os << "kind,view,camera,width,height,px,water,visibility_m,background,jpeg_quality,gauss_sigma_px,motion_px,"
        "landmark,true_u,true_v,ellipse_u,ellipse_v,a_px,b_px,theta_rad,whole_in_frame,centre_in_frame,view_angle_deg,"
        "range_m,range_over_visibility,blur_sigma_px,contrast_grey,noise_sigma_grey,contrast_over_noise,"
        "sheet_margin_r,occluded_fraction,centre_occluded,eligible,found,det_u,det_v,det_radius_px,centre_error_px,"
        "radius_rel_error,"
        "radius_ok,labelled,target_found,target_correct,false_target,false_landmarks,nb_detections,detect_ms,"
        "tag_run,tag_whole_in_frame,tag_found,tag_false\n";
  for (const vpSSLCorpusViewResult &r : m_results) {
    const vpSSLCorpusViewParams &p = r.params;
    char head[512];
    std::snprintf(head, sizeof(head), "%s,%u,%s,%u,%u,%.2f,%s,%.3f,%s,%d,%.3f,%.3f,",
                  p.hasTarget ? "target" : "negative", r.index, p.camera.name.c_str(), p.camera.width, p.camera.height,
                  p.camera.px, vpSSLCorpusViewParams::waterName(p.water), p.visibility,
                  vpSSLCorpusViewParams::backgroundName(p.background), p.jpegQuality, p.gaussSigma, p.motionLength);
    char tail[256];
    std::snprintf(tail, sizeof(tail), "%d,%d,%d,%u,%u,%.3f,%d,%d,%d,%u\n", r.targetFound, r.targetCorrect,
                  r.falseTarget, r.falseLandmarks, r.nbDetections, r.detectMs, r.tagRun, r.tagWholeInFrame, r.tagFound,
                  r.tagFalse);
    if (r.truth.empty()) {
      os << head << "-";
      for (int k = 0; k < 29; ++k)
        os << ",";
      os << tail;
      continue;
    }
    for (size_t i = 0; i < r.truth.size(); ++i) {
      const vpSSLCorpusLandmarkTruth &t = r.truth[i];
      const vpSSLCorpusLandmarkResult &x = r.results[i];
      char row[1024];
      std::snprintf(row, sizeof(row),
                    "%s,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.5f,%d,%d,%.2f,%.4f,%.4f,%.3f,%.3f,%.3f,%.3f,%.3f,%.4f,%d,%d,%d,"
                    "%.4f,%.4f,%.4f,%.4f,%.5f,%d,%d,",
                    t.name.c_str(), t.u, t.v, t.ellipseU, t.ellipseV, t.a, t.b, t.theta, t.wholeInFrame,
                    t.centreInFrame, t.viewAngle, t.range, t.rangeOverVisibility, t.blurSigma, t.contrast, t.noiseSigma,
                    t.contrastOverNoise, t.sheetMargin, t.occludedFraction, t.centreOccluded, t.eligible(), x.found,
                    x.u, x.v, x.radius, x.centreError, x.radiusError, x.radiusOk, x.labelled);
      os << head << row << tail;
    }
  }
}
