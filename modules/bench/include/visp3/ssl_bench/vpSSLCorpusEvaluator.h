/*!
  \file vpSSLCorpusEvaluator.h
  \brief Matching of detections to a corpus view's truth, and the recall tables.
*/
#ifndef VP_SSL_CORPUS_EVALUATOR_H
#define VP_SSL_CORPUS_EVALUATOR_H

#include <ostream>
#include <string>
#include <vector>

#include <visp3/ssl/vpSSLDetector.h>
#include <visp3/ssl_bench/vpSSLCorpusView.h>

/*!
  \struct vpSSLCorpusLandmarkResult
  \ingroup group_ssl_bench
  \brief What the detector made of one true landmark.
*/
struct vpSSLCorpusLandmarkResult
{
  bool found = false;      ///< A detected centre lies within 15 % of the true radius of the true centre.
  double u = 0.;           ///< That detection's centre (px).
  double v = 0.;           ///< That detection's centre (px).
  double radius = 0.;      ///< Its major semi-axis (px).
  double centreError = 0.; ///< Distance to the true centre (px).
  double radiusError = 0.; ///< (radius - true a) / true a.
  bool radiusOk = false;   ///< found and |radiusError| <= 10 %.
  bool labelled = false;   ///< The target identification gave this landmark's label to that detection.
};

/*!
  \struct vpSSLCorpusViewResult
  \ingroup group_ssl_bench
  \brief One view's truth, description and detection results.
*/
struct vpSSLCorpusViewResult
{
  unsigned int index = 0;                         ///< View index (within positives or negatives).
  vpSSLCorpusViewParams params;                   ///< How the view was made.
  std::vector<vpSSLCorpusLandmarkTruth> truth;    ///< Landmarks' truth (empty for a negative).
  std::vector<vpSSLCorpusLandmarkResult> results; ///< Per landmark, in truth order.
  unsigned int nbDetections = 0;                  ///< Landmarks the detector reported.
  unsigned int falseLandmarks = 0; ///< Detections within 15 % of no true landmark's radius of its centre.
  bool targetFound = false;        ///< getTargetMatch().found.
  bool targetCorrect = false;      ///< Found, and its B within 15 % of B's radius of the true B.
  bool falseTarget = false;        ///< Found on a negative, or a label on a detection that is no landmark of that size.
  double detectMs = 0.;            ///< Detector time (ms).
  bool tagRun = false;             ///< The AprilTag baseline ran on this view's tag rendering.
  bool tagWholeInFrame = false;    ///< The tag's four corners are in the image.
  bool tagFound = false;           ///< The tag's id found within 15 % of its apparent half side of its centre.
  unsigned int tagFalse = 0;       ///< Other tag detections (other ids, or the id elsewhere).
  double tagMs = 0.;               ///< AprilTag detector time (ms).
};

/*!
  \class vpSSLCorpusEvaluator
  \ingroup group_ssl_bench
  \brief Matches detections to the truth and prints the recall tables (Markdown) and the per-landmark CSV.

  A true landmark is found when a detected landmark's centre lies within 15 % of its true radius (the outer
  ellipse's major semi-axis) of its true centre (the projection of the circle's centre); a detection that is
  found near no true landmark is a false landmark (an inner ring of B read as a landmark included). Eligible
  (the headline): the whole outer disc in the image, radius >= 8 px, centre not occluded, ring contrast at least
  3 times the noise sigma.
*/
class vpSSLCorpusEvaluator
{
public:
  //! Fraction of the true radius within which a detected centre finds a landmark.
  static constexpr double kCentreTolerance = 0.15;
  //! Relative radius error of a detection read with the right size.
  static constexpr double kRadiusTolerance = 0.10;

  /*!
    Matches the last detection of \e detector with \e result.truth and fills the rest of \e result (the
    detector's target must be the corpus's: its landmark order is the truth's).
  */
  static void match(const vpSSLDetector &detector, vpSSLCorpusViewResult &result);

  /*!
    Matches an AprilTag detection: \e polygons and \e ids of the tags found, \e corners the true corners (px) of
    tag \e id. Fills the tag fields of \e result.
  */
  static void matchTag(const std::vector<std::vector<vpImagePoint>> &polygons, const std::vector<int> &ids,
                       const std::vector<vpImagePoint> &corners, int id, unsigned int width, unsigned int height,
                       vpSSLCorpusViewResult &result);

  //! Adds a view's result to the tables.
  void add(const vpSSLCorpusViewResult &result) { m_results.push_back(result); }
  //! The results added, in order.
  const std::vector<vpSSLCorpusViewResult> &getResults() const { return m_results; }

  /*!
    Recall over the eligible views of landmark \e name (B, S1, S2): found / eligible, and the count of eligible
    views in \e n. 0 when there is none.
  */
  double recall(const std::string &name, unsigned int &n) const;
  //! False targets over the negative views (and their count in \e n).
  unsigned int falseTargetsOnNegatives(unsigned int &n) const;
  //! False targets over the positive views: found with B away from the true B.
  unsigned int falseTargetsOnPositives() const;

  //! Writes every table (Markdown) to \e os.
  void printTables(std::ostream &os) const;
  //! Writes one CSV row per view x landmark (negatives: one row with landmark "-").
  void writeCsv(std::ostream &os) const;

private:
  std::vector<vpSSLCorpusViewResult> m_results;
};

#endif
