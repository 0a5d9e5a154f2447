/*!
  \file vpSSLTarget.cpp
  \brief Target model: the built-in ssl3-a3 target and the target file reader and writer.
*/
#include <visp3/ssl/vpSSLTarget.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <utility>

#include <visp3/core/vpException.h>

namespace {
// Tolerance (m) for "fits on the sheet" and "does not overlap": far below a printer's resolution,
// large enough that the values of a file written by save() never fail on rounding.
const double kGeometryTol = 1e-9;

std::string quote(const std::string &s)
{
  return "\"" + s + "\"";
}

// Shortest decimal text that reads back to the same double (std::to_chars without a precision), so
// that save() followed by load() gives back the identical target and the file stays readable
// ("0.1", not "0.10000000000000001").
std::string formatNumber(double v)
{
  char buf[64];
  std::to_chars_result r = std::to_chars(buf, buf + sizeof(buf), v);
  return std::string(buf, r.ptr);
}

// A name is one blank-free word without '#', so that the file format can store it.
bool isValidName(const std::string &name)
{
  if (name.empty()) {
    return false;
  }
  for (char c : name) {
    if (std::isspace(static_cast<unsigned char>(c)) || c == '#') {
      return false;
    }
  }
  return true;
}

// Problem with adding `lm` to `existing`, as (field, message); `other` receives the index of the
// conflicting landmark, or -1. An empty field means no problem.
std::pair<std::string, std::string> landmarkProblem(const vpSSLTargetLandmark &lm,
                                                    const std::vector<vpSSLTargetLandmark> &existing, int &other)
{
  other = -1;
  std::ostringstream os;
  if (!isValidName(lm.name)) {
    return {"name", "must be one word without blanks or '#', got " + quote(lm.name)};
  }
  const double c = vpSSLTarget::maxCoordinate();
  if (!std::isfinite(lm.x) || !std::isfinite(lm.y) || !std::isfinite(lm.z)) {
    return {"centre", "must be finite"};
  }
  if (std::fabs(lm.x) > c || std::fabs(lm.y) > c || std::fabs(lm.z) > c) {
    os << "each coordinate must be within +-" << c << " m, got (" << lm.x << ", " << lm.y << ", " << lm.z << ")";
    return {"centre", os.str()};
  }
  if (!(lm.radius > 0.) || !std::isfinite(lm.radius)) {
    os << "must be > 0, got " << lm.radius;
    return {"radius", os.str()};
  }
  if (lm.radius < vpSSLTarget::minRadius() || lm.radius > vpSSLTarget::maxRadius()) {
    os << "must be in [" << vpSSLTarget::minRadius() << ", " << vpSSLTarget::maxRadius() << "] m, got "
       << formatNumber(lm.radius);
    return {"radius", os.str()};
  }
  if (!(lm.p >= vpSSLTarget::minP() && lm.p <= vpSSLTarget::maxP())) {
    os << "must be in [" << vpSSLTarget::minP() << ", " << vpSSLTarget::maxP() << "], got " << formatNumber(lm.p);
    return {"p", os.str()};
  }
  if (existing.size() >= vpSSLTarget::maxLandmarks()) {
    os << "more than " << vpSSLTarget::maxLandmarks() << " landmarks in one target";
    return {"landmark", os.str()};
  }
  for (size_t i = 0; i < existing.size(); ++i) {
    const vpSSLTargetLandmark &o = existing[i];
    // The detector matches one square wave: every landmark of a target shares its p.
    if (lm.p != o.p) {
      other = static_cast<int>(i);
      os << lm.p << " differs from " << o.p << " of " << quote(o.name) << " (the landmarks of a target share one p)";
      return {"p", os.str()};
    }
    if (o.name == lm.name) {
      other = static_cast<int>(i);
      return {"name", "duplicate landmark name " + quote(lm.name)};
    }
    // Discs are printed in planes parallel to the sheet: overlap is judged as seen along Z.
    double d = std::hypot(lm.x - o.x, lm.y - o.y);
    if (d < lm.radius + o.radius - kGeometryTol) {
      other = static_cast<int>(i);
      os << quote(lm.name) << " overlaps " << quote(o.name) << ": centre distance " << d << " m < sum of radii "
         << lm.radius + o.radius << " m";
      return {"landmark", os.str()};
    }
  }
  return {"", ""};
}

std::string sheetProblem(double width, double height, double cx, double cy)
{
  std::ostringstream os;
  const double side = vpSSLTarget::maxSheetSide(), c = vpSSLTarget::maxCoordinate();
  if (!(width > 0.) || !std::isfinite(width)) {
    os << "width: must be > 0, got " << width;
  } else if (!(height > 0.) || !std::isfinite(height)) {
    os << "height: must be > 0, got " << height;
  } else if (width > side) {
    os << "width: must be at most " << side << " m, got " << width;
  } else if (height > side) {
    os << "height: must be at most " << side << " m, got " << height;
  } else if (!std::isfinite(cx) || !std::isfinite(cy)) {
    os << "center: must be finite";
  } else if (std::fabs(cx) > c || std::fabs(cy) > c) {
    os << "center: each coordinate must be within +-" << c << " m";
  }
  return os.str();
}

// Empty when the landmark disc lies on the sheet rectangle.
std::string fitProblem(const vpSSLTargetLandmark &lm, const vpSSLTarget &t)
{
  double x0 = t.getSheetCenterX() - 0.5 * t.getSheetWidth(), x1 = t.getSheetCenterX() + 0.5 * t.getSheetWidth();
  double y0 = t.getSheetCenterY() - 0.5 * t.getSheetHeight(), y1 = t.getSheetCenterY() + 0.5 * t.getSheetHeight();
  if (lm.x - lm.radius < x0 - kGeometryTol || lm.x + lm.radius > x1 + kGeometryTol ||
      lm.y - lm.radius < y0 - kGeometryTol || lm.y + lm.radius > y1 + kGeometryTol) {
    std::ostringstream os;
    os << quote(lm.name) << " does not fit on the sheet: disc x in [" << lm.x - lm.radius << ", " << lm.x + lm.radius
       << "], y in [" << lm.y - lm.radius << ", " << lm.y + lm.radius << "], sheet x in [" << x0 << ", " << x1
       << "], y in [" << y0 << ", " << y1 << "]";
    return os.str();
  }
  return "";
}

// Reads the target file line by line; every error names file, line and field.
class TargetFileParser
{
public:
  explicit TargetFileParser(const std::string &filename) : m_file(filename) {}

  vpSSLTarget parse()
  {
    std::error_code ec;
    if (std::filesystem::is_directory(m_file, ec)) {
      throw vpException(vpException::ioError, m_file + ": cannot open (is a directory)");
    }
    std::ifstream in(m_file);
    if (!in) {
      throw vpException(vpException::ioError, m_file + ": cannot open");
    }
    std::string text;
    while (std::getline(in, text)) {
      ++m_line;
      std::vector<std::string> f = split(text);
      if (f.empty()) {
        continue;
      }
      if (f[0] == "name") {
        parseName(f);
      } else if (f[0] == "sheet") {
        parseSheet(f);
      } else if (f[0] == "landmark") {
        parseLandmark(f);
      } else {
        fail("", "unknown keyword " + quote(f[0]) + " (expected name, sheet or landmark)");
      }
    }
    if (in.bad()) {
      throw vpException(vpException::ioError, m_file + ": read error after line " + std::to_string(m_line));
    }
    return finish();
  }

private:
  std::string m_file;
  int m_line = 0;
  vpSSLTarget m_target;
  int m_nameLine = 0, m_sheetLine = 0;
  double m_sheet[4] = {0., 0., 0., 0.};
  std::vector<int> m_landmarkLines;

  [[noreturn]] void fail(const std::string &field, const std::string &problem, int line = -1) const
  {
    std::ostringstream os;
    os << m_file;
    if (line != 0) {
      os << ":" << (line < 0 ? m_line : line);
    }
    os << ": ";
    if (!field.empty()) {
      os << field << ": ";
    }
    os << problem;
    throw vpException(vpException::badValue, os.str());
  }

  static std::vector<std::string> split(const std::string &text)
  {
    std::istringstream is(text.substr(0, text.find('#')));
    std::vector<std::string> f;
    std::string tok;
    while (is >> tok) {
      f.push_back(tok);
    }
    return f;
  }

  void checkCount(const std::vector<std::string> &f, size_t lo, size_t hi) const
  {
    if (f.size() < lo || f.size() > hi) {
      std::ostringstream os;
      os << "expected " << lo;
      if (hi != lo) {
        os << " or " << hi;
      }
      os << " fields, got " << f.size();
      fail(f[0], os.str());
    }
  }

  // from_chars, unlike strtod and streams, ignores the C locale (no decimal comma surprises).
  double number(const std::string &tok, const std::string &field) const
  {
    const char *b = tok.data(), *e = tok.data() + tok.size();
    if (b != e && *b == '+') {
      ++b;
      // from_chars takes a '-' of its own: "+-0.1" would read as -0.1.
      if (b != e && (*b == '-' || *b == '+')) {
        fail(field, "not a number: " + quote(tok));
      }
    }
    double v = 0.;
    std::from_chars_result r = std::from_chars(b, e, v);
    if (r.ec == std::errc::result_out_of_range) {
      fail(field, "out of range: " + quote(tok));
    }
    if (r.ec != std::errc() || r.ptr != e || b == e) {
      fail(field, "not a number: " + quote(tok));
    }
    if (!std::isfinite(v)) {
      fail(field, "not a finite number: " + quote(tok));
    }
    return v;
  }

  void parseName(const std::vector<std::string> &f)
  {
    checkCount(f, 2, 2);
    if (m_nameLine != 0) {
      fail("name", "given twice (first on line " + std::to_string(m_nameLine) + ")");
    }
    m_nameLine = m_line;
    m_target.setName(f[1]);
  }

  void parseSheet(const std::vector<std::string> &f)
  {
    checkCount(f, 5, 5);
    if (m_sheetLine != 0) {
      fail("sheet", "given twice (first on line " + std::to_string(m_sheetLine) + ")");
    }
    const char *fields[4] = {"width", "height", "center_x", "center_y"};
    for (int i = 0; i < 4; ++i) {
      m_sheet[i] = number(f[i + 1], fields[i]);
    }
    if (!(m_sheet[0] > 0.)) {
      fail("width", "must be > 0, got " + f[1]);
    }
    if (!(m_sheet[1] > 0.)) {
      fail("height", "must be > 0, got " + f[2]);
    }
    const std::string pb = sheetProblem(m_sheet[0], m_sheet[1], m_sheet[2], m_sheet[3]);
    if (!pb.empty()) {
      const size_t colon = pb.find(": ");
      fail(pb.substr(0, colon), pb.substr(colon + 2));
    }
    m_sheetLine = m_line;
  }

  void parseLandmark(const std::vector<std::string> &f)
  {
    checkCount(f, 6, 7);
    vpSSLTargetLandmark lm;
    lm.name = f[1];
    lm.x = number(f[2], "x");
    lm.y = number(f[3], "y");
    lm.z = number(f[4], "z");
    lm.radius = number(f[5], "radius");
    if (f.size() == 7) {
      lm.p = number(f[6], "p");
    }
    int other = -1;
    std::pair<std::string, std::string> pb = landmarkProblem(lm, m_target.getLandmarks(), other);
    if (!pb.first.empty()) {
      std::string where = other >= 0 ? " (line " + std::to_string(m_landmarkLines[other]) + ")" : "";
      fail(pb.first, pb.second + where);
    }
    m_target.addLandmark(lm);
    m_landmarkLines.push_back(m_line);
  }

  vpSSLTarget finish()
  {
    if (m_nameLine == 0) {
      fail("name", "missing (add a line \"name NAME\")", 0);
    }
    if (m_target.size() == 0) {
      fail("landmark", "none (add at least one line \"landmark NAME X Y Z RADIUS [P]\")", 0);
    }
    if (m_sheetLine != 0) {
      m_target.setSheet(m_sheet[0], m_sheet[1], m_sheet[2], m_sheet[3]);
    } else {
      // The automatic sheet (the landmarks' bounding box plus a margin) meets the limits of a written one, so that
      // what save() writes loads back.
      const std::string pb = sheetProblem(m_target.getSheetWidth(), m_target.getSheetHeight(),
                                          m_target.getSheetCenterX(), m_target.getSheetCenterY());
      if (!pb.empty()) {
        fail("sheet", "the automatic sheet around the landmarks: " + pb, 0);
      }
    }
    for (size_t i = 0; i < m_target.size(); ++i) {
      std::string pb = fitProblem(m_target.getLandmark(i), m_target);
      if (!pb.empty()) {
        fail("landmark", pb, m_landmarkLines[i]);
      }
    }
    return m_target;
  }
};
} // namespace

vpSSLTarget::vpSSLTarget()
    : m_name(), m_landmarks(), m_sheetWidth(0.), m_sheetHeight(0.), m_sheetCenterX(0.), m_sheetCenterY(0.),
      m_sheetSet(false)
{
}

vpSSLTarget vpSSLTarget::ssl3a3()
{
  // Values of the table in doc/target-ssl3-a3.md, not computed from the triangle: the printed sheet,
  // recorded sequences and evaluation sets must agree on these exact numbers.
  vpSSLTarget t;
  t.setName("ssl3-a3");
  vpSSLTargetLandmark b, s1, s2;
  b.name = "B";
  b.x = -0.103923;
  b.radius = 0.100;
  s1.name = "S1";
  s1.x = 0.051962;
  s1.y = -0.090;
  s1.radius = 0.050;
  s2.name = "S2";
  s2.x = 0.051962;
  s2.y = 0.090;
  s2.radius = 0.050;
  t.addLandmark(b);
  t.addLandmark(s1);
  t.addLandmark(s2);
  t.setSheet(0.420, 0.297, -0.051, 0.0);
  return t;
}

vpSSLTarget vpSSLTarget::fromName(const std::string &nameOrPath)
{
  if (nameOrPath == "ssl3-a3") {
    return ssl3a3();
  }
  std::error_code ec;
  if (!std::filesystem::exists(nameOrPath, ec)) {
    throw vpException(vpException::ioError,
                      nameOrPath + ": cannot open (not a file, nor a built-in target name: ssl3-a3)");
  }
  return load(nameOrPath);
}

vpSSLTarget vpSSLTarget::load(const std::string &filename)
{
  TargetFileParser parser(filename);
  return parser.parse();
}

void vpSSLTarget::save(const std::string &filename) const
{
  // Refuse to write a file that load() would reject.
  if (!isValidName(m_name)) {
    throw vpException(vpException::badValue,
                      filename + ": cannot save: target name must be one word without blanks or '#', got " +
                          quote(m_name));
  }
  if (m_landmarks.empty()) {
    throw vpException(vpException::badValue, filename + ": cannot save: the target has no landmark");
  }
  for (const vpSSLTargetLandmark &lm : m_landmarks) {
    std::string pb = fitProblem(lm, *this);
    if (!pb.empty()) {
      throw vpException(vpException::badValue, filename + ": cannot save: " + pb);
    }
  }
  std::ofstream out(filename);
  if (!out) {
    throw vpException(vpException::ioError, filename + ": cannot open for writing");
  }
  out << "# visp-ssl target file (doc/target-file.md): '#' starts a comment, lengths in metres,\n"
      << "# target frame X right, Y down, Z into the sheet, seen from the printed side.\n"
      << "name " << m_name << "\n"
      << "# sheet WIDTH HEIGHT CENTER_X CENTER_Y\n"
      << "sheet " << formatNumber(m_sheetWidth) << " " << formatNumber(m_sheetHeight) << " "
      << formatNumber(m_sheetCenterX) << " " << formatNumber(m_sheetCenterY) << "\n"
      << "# landmark NAME X Y Z RADIUS P\n";
  for (const vpSSLTargetLandmark &lm : m_landmarks) {
    out << "landmark " << lm.name << " " << formatNumber(lm.x) << " " << formatNumber(lm.y) << " " << formatNumber(lm.z)
        << " " << formatNumber(lm.radius) << " " << formatNumber(lm.p) << "\n";
  }
  out.flush();
  if (!out) {
    throw vpException(vpException::ioError, filename + ": write error");
  }
}

void vpSSLTarget::addLandmark(const vpSSLTargetLandmark &landmark)
{
  int other = -1;
  std::pair<std::string, std::string> pb = landmarkProblem(landmark, m_landmarks, other);
  if (!pb.first.empty()) {
    throw vpException(vpException::badValue, "vpSSLTarget::addLandmark: " + pb.first + ": " + pb.second);
  }
  m_landmarks.push_back(landmark);
  if (!m_sheetSet) {
    updateAutomaticSheet();
  }
}

void vpSSLTarget::setSheet(double width, double height, double centerX, double centerY)
{
  std::string pb = sheetProblem(width, height, centerX, centerY);
  if (!pb.empty()) {
    throw vpException(vpException::badValue, "vpSSLTarget::setSheet: " + pb);
  }
  m_sheetWidth = width;
  m_sheetHeight = height;
  m_sheetCenterX = centerX;
  m_sheetCenterY = centerY;
  m_sheetSet = true;
}

void vpSSLTarget::updateAutomaticSheet()
{
  // Bounding box of the discs plus one largest radius on every side: room for the printed labels.
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const vpSSLTargetLandmark &lm : m_landmarks) {
    x0 = std::min(x0, lm.x - lm.radius);
    x1 = std::max(x1, lm.x + lm.radius);
    y0 = std::min(y0, lm.y - lm.radius);
    y1 = std::max(y1, lm.y + lm.radius);
  }
  double margin = getMaxRadius();
  m_sheetWidth = x1 - x0 + 2. * margin;
  m_sheetHeight = y1 - y0 + 2. * margin;
  m_sheetCenterX = 0.5 * (x0 + x1);
  m_sheetCenterY = 0.5 * (y0 + y1);
}

const vpSSLTargetLandmark &vpSSLTarget::getLandmark(size_t i) const
{
  if (i >= m_landmarks.size()) {
    throw vpException(vpException::badValue, "vpSSLTarget::getLandmark: index " + std::to_string(i) +
                                                 " out of range (target " + quote(m_name) + " has " +
                                                 std::to_string(m_landmarks.size()) + " landmarks)");
  }
  return m_landmarks[i];
}

int vpSSLTarget::findLandmark(const std::string &name) const
{
  for (size_t i = 0; i < m_landmarks.size(); ++i) {
    if (m_landmarks[i].name == name) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

std::vector<vpPoint> vpSSLTarget::getPoints() const
{
  std::vector<vpPoint> points;
  points.reserve(m_landmarks.size());
  for (const vpSSLTargetLandmark &lm : m_landmarks) {
    points.emplace_back(lm.x, lm.y, lm.z);
  }
  return points;
}

double vpSSLTarget::getP() const
{
  if (m_landmarks.empty()) {
    throw vpException(vpException::badValue, "vpSSLTarget::getP: target " + quote(m_name) + " has no landmark");
  }
  double p = m_landmarks.front().p;
  for (const vpSSLTargetLandmark &lm : m_landmarks) {
    if (lm.p != p) {
      std::ostringstream os;
      os << "vpSSLTarget::getP: landmarks of target " << quote(m_name) << " have different p (" << p << " for "
         << quote(m_landmarks.front().name) << ", " << lm.p << " for " << quote(lm.name) << ")";
      throw vpException(vpException::badValue, os.str());
    }
  }
  return p;
}

double vpSSLTarget::getMaxRadius() const
{
  if (m_landmarks.empty()) {
    throw vpException(vpException::badValue, "vpSSLTarget::getMaxRadius: target " + quote(m_name) + " has no landmark");
  }
  double r = 0.;
  for (const vpSSLTargetLandmark &lm : m_landmarks) {
    r = std::max(r, lm.radius);
  }
  return r;
}

double vpSSLTarget::getMinRadius() const
{
  if (m_landmarks.empty()) {
    throw vpException(vpException::badValue, "vpSSLTarget::getMinRadius: target " + quote(m_name) + " has no landmark");
  }
  double r = std::numeric_limits<double>::infinity();
  for (const vpSSLTargetLandmark &lm : m_landmarks) {
    r = std::min(r, lm.radius);
  }
  return r;
}
