//! \example tutorial-ssl-check-sequence.cpp
//! Checks recorded sequence folders against doc/sequence-format.md and lists every problem, one per line.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <visp3/core/vpException.h>
#include <visp3/core/vpImage.h>
#include <visp3/ssl/vpSSLTarget.h>
#include <visp3/ssl_io/vpSSLCameraFile.h>
#include <visp3/ssl_io/vpSSLImageIo.h>
#include <visp3/ssl_io/vpSSLSequenceFrame.h>
#include <visp3/ssl_io/vpSSLSequenceInfo.h>
#include <visp3/ssl_io/vpSSLSequenceReader.h>
#include <visp3/ssl_sim/vpSSLAprilTagSheet.h>

namespace fs = std::filesystem;

namespace {
const char *kUsage = R"(Usage: tutorial-ssl-check-sequence [--no-images] [--quiet] FOLDER...

Checks each recorded sequence folder against every rule of doc/sequence-format.md: the four
entries of the folder, camera.xml (camera "Camera"), sequence.json and its target, the
frames.csv header and every row (cell count, frame index, increasing time stamp, complete
pose groups, numbers) and every row's image (present, readable, one size for all).

Every problem is one line on standard output:
  FILE:LINE: FIELD: problem
LINE counts from 1; it is 0 when the problem is about the file as a whole. Problems of an
image are reported on the frames.csv row that refers to it. A folder without problems
gives one line "FOLDER: ok: N frames, ..." unless --quiet.

Options:
  --no-images   Check that each row's image exists, without decoding it (fast).
  --quiet       Print problems only.
  --help        This help.

Exit status: 0 when every folder conforms, 1 when one does not, 2 on a usage error.
)";

const char *const kColumns[14] = {"frame",    "t",     "odom_tx", "odom_ty", "odom_tz", "odom_tux", "odom_tuy",
                                  "odom_tuz", "gt_tx", "gt_ty",   "gt_tz",   "gt_tux",  "gt_tuy",   "gt_tuz"};
const char *const kImageExtensions[] = {"png", "jpg", "jpeg", "pgm", "ppm"};

std::string trim(const std::string &s)
{
  const size_t b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) {
    return std::string();
  }
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

// RFC 4180 cells of one line; false on an unterminated quote.
bool splitCsv(const std::string &line, std::vector<std::string> &cells)
{
  cells.clear();
  std::string cell;
  bool quoted = false, inQuotes = false;
  for (size_t i = 0; i <= line.size(); ++i) {
    if (i == line.size()) {
      if (inQuotes) {
        return false;
      }
      cells.push_back(cell);
      break;
    }
    const char c = line[i];
    if (inQuotes) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cell += '"';
        ++i;
      } else if (c == '"') {
        inQuotes = false;
      } else {
        cell += c;
      }
    } else if (c == '"' && !quoted && trim(cell).empty()) {
      cell.clear();
      inQuotes = quoted = true;
    } else if (c == ',') {
      cells.push_back(cell);
      cell.clear();
      quoted = false;
    } else {
      cell += c;
    }
  }
  return true;
}

// A finite number in C locale filling the whole (trimmed) cell; an empty string when it is one.
std::string numberProblem(const std::string &cell, double &value)
{
  const std::string s = trim(cell);
  const char *b = s.data(), *e = s.data() + s.size();
  if (b != e && *b == '+') {
    ++b;
  }
  const auto r = std::from_chars(b, e, value);
  if (s.empty() || r.ec != std::errc() || r.ptr != e || !std::isfinite(value)) {
    return "not a number: \"" + cell + "\"";
  }
  return std::string();
}

// The checks of one folder; every problem is printed at once and counted.
class SequenceChecker
{
public:
  SequenceChecker(const std::string &folder, bool decodeImages)
      : m_folder(folder), m_decodeImages(decodeImages), m_problems(0), m_frames(0), m_withGroundTruth(0),
        m_withOdometry(0), m_width(0), m_height(0)
  {
  }

  int check()
  {
    std::error_code ec;
    if (!fs::is_directory(m_folder, ec)) {
      problem(m_folder, 0, "folder", "missing or not a directory");
      return m_problems;
    }
    const bool haveCamera = requireFile("camera.xml"), haveInfo = requireFile("sequence.json");
    const bool haveFrames = requireFile("frames.csv");
    if (!fs::is_directory(path("images"), ec)) {
      problem(path("images"), 0, "file", "missing or not a directory (the frames' images go in images/)");
    }
    if (haveCamera) {
      checkCamera();
    }
    if (haveInfo) {
      checkInfo();
    }
    if (haveFrames) {
      checkFrames();
    }
    if (m_problems == 0) {
      crossCheckWithReader();
    }
    return m_problems;
  }

  std::string summary() const
  {
    return m_folder + ": ok: " + std::to_string(m_frames) + " frames, " + std::to_string(m_withGroundTruth) +
           " with ground truth, " + std::to_string(m_withOdometry) + " with odometry, target " + m_target;
  }

private:
  std::string path(const std::string &name) const { return (fs::path(m_folder) / name).string(); }

  void problem(const std::string &file, unsigned long line, const std::string &field, const std::string &what)
  {
    std::cout << file << ":" << line << ": " << field << ": " << what << std::endl;
    ++m_problems;
  }

  bool requireFile(const std::string &name)
  {
    std::error_code ec;
    if (!fs::is_regular_file(path(name), ec)) {
      problem(path(name), 0, "file", "missing or not a regular file");
      return false;
    }
    return true;
  }

  // The library's messages start with the file name; drop it, the problem line names the file already.
  static std::string withoutPrefix(const std::string &message, const std::string &file)
  {
    if (message.compare(0, file.size() + 2, file + ": ") == 0) {
      return message.substr(file.size() + 2);
    }
    return message;
  }

  void checkCamera()
  {
    const std::string file = path("camera.xml");
    try {
      vpSSLCameraFile::load(file, "Camera", &m_width, &m_height);
    } catch (const vpException &e) {
      problem(file, 0, "camera", withoutPrefix(e.getStringMessage(), file));
    }
  }

  void checkInfo()
  {
    const std::string file = path("sequence.json");
    vpSSLSequenceInfo info;
    try {
      info = vpSSLSequenceInfo::load(file);
    } catch (const vpException &e) {
      // vpSSLSequenceInfo says "FILE:LINE: member: problem", or "FILE:LINE: problem" for the JSON syntax.
      std::string rest = e.getStringMessage();
      unsigned long line = 0;
      if (rest.compare(0, file.size() + 1, file + ":") == 0) {
        rest = rest.substr(file.size() + 1);
        const size_t colon = rest.find(": ");
        if (colon != std::string::npos && rest.find_first_not_of("0123456789") == colon) {
          line = std::stoul(rest.substr(0, colon));
          rest = rest.substr(colon + 2);
        }
      }
      std::string field = "json";
      for (const std::string member : {"target", "camera_to_vehicle", "source", "water"}) {
        if (rest.compare(0, member.size() + 2, member + ": ") == 0) {
          field = member;
          rest = rest.substr(member.size() + 2);
        }
      }
      problem(file, line, field, rest);
      return;
    }
    m_target = info.target;
    checkTarget(file, info.target);
  }

  // Rule 4: the target can be built, as the programs that read the sequence build it.
  void checkTarget(const std::string &file, const std::string &target)
  {
    unsigned long line = 0;
    {
      std::ifstream in(file);
      std::string text;
      for (unsigned long n = 1; line == 0 && std::getline(in, text); ++n) {
        line = text.find("\"target\"") != std::string::npos ? n : 0;
      }
    }
    try {
      if (vpSSLAprilTagSheet::isName(target)) {
        vpSSLAprilTagSheet::fromName(target);
      } else if (target == "ssl3-a3") {
        vpSSLTarget::fromName(target);
      } else {
        // A relative path is resolved against the sequence folder, never the working folder, as every reader of
        // the sequence resolves it.
        vpSSLTarget::load(fs::path(target).is_absolute() ? target : path(target));
      }
    } catch (const vpException &e) {
      problem(file, line, "target",
              "\"" + target + "\" is neither a built-in target, an AprilTag sheet nor a readable target file (" +
                  e.getStringMessage() + ")");
    }
  }

  void checkFrames()
  {
    const std::string file = path("frames.csv");
    std::ifstream in(file, std::ios::binary);
    std::string line;
    std::vector<std::string> cells;
    if (!std::getline(in, line)) {
      problem(file, 1, "header", "empty file, expected the header line");
      return;
    }
    if (line.compare(0, 3, "\xEF\xBB\xBF") == 0) {
      line.erase(0, 3);
    }
    // Lines end in LF or CRLF: a file with CR alone is one line to every reader of the format.
    const size_t cr = line.find('\r');
    if (cr != std::string::npos && cr + 1 != line.size()) {
      problem(file, 1, "line end",
              "a carriage return inside the line: lines must end in LF or CRLF, not CR alone (convert the file, e.g. "
              "with tr '\\r' '\\n')");
      return;
    }
    if (!checkHeader(file, line, cells)) {
      problem(file, 1, "header", "rows not checked (their columns are unknown)");
      return;
    }

    unsigned long lineNumber = 1, emptyLine = 0;
    double lastTime = 0.;
    bool haveTime = false;
    while (std::getline(in, line)) {
      ++lineNumber;
      if (!line.empty() && line.back() == '\r') {
        line.pop_back();
      }
      if (line.find('\r') != std::string::npos) {
        problem(file, lineNumber, "line end", "a carriage return inside the line: lines must end in LF or CRLF");
        continue;
      }
      if (line.empty()) {
        emptyLine = emptyLine == 0 ? lineNumber : emptyLine;
        continue;
      }
      if (emptyLine != 0) {
        problem(file, emptyLine, "row",
                "empty line inside the table (rows go on at line " + std::to_string(lineNumber) + ")");
        emptyLine = 0;
      }
      checkRow(file, lineNumber, line, cells, lastTime, haveTime);
      ++m_frames;
    }
  }

  bool checkHeader(const std::string &file, std::string line, std::vector<std::string> &cells)
  {
    if (!line.empty() && line.back() == '\r') {
      line.pop_back();
    }
    if (!splitCsv(line, cells)) {
      problem(file, 1, "header", "unterminated quote");
      return false;
    }
    bool ok = true;
    for (size_t i = 0; i < 14; ++i) {
      const std::string column = "column " + std::to_string(i + 1);
      if (i >= cells.size()) {
        problem(file, 1, column,
                std::string("missing, expected \"") + kColumns[i] + "\" (the header has " +
                    std::to_string(cells.size()) + " columns, at least 14 are required)");
        ok = false;
        break;
      }
      if (trim(cells[i]) != kColumns[i]) {
        problem(file, 1, column, std::string("expected \"") + kColumns[i] + "\", got \"" + cells[i] + "\"");
        ok = false;
      }
    }
    m_columns.clear();
    for (size_t i = 0; i < cells.size(); ++i) {
      const std::string name = trim(cells[i]);
      if (i >= 14 && name.empty()) {
        problem(file, 1, "column " + std::to_string(i + 1), "empty column name");
        ok = false;
      }
      for (size_t j = 0; i >= 14 && !name.empty() && j < i; ++j) {
        if (m_columns[j] == name) {
          problem(file, 1, "column " + std::to_string(i + 1),
                  "\"" + name + "\" is also column " + std::to_string(j + 1));
          ok = false;
        }
      }
      m_columns.push_back(name);
    }
    return ok;
  }

  void checkRow(const std::string &file, unsigned long lineNumber, const std::string &line,
                std::vector<std::string> &cells, double &lastTime, bool &haveTime)
  {
    const unsigned long rank = m_frames;
    if (!splitCsv(line, cells)) {
      problem(file, lineNumber, "row", "unterminated quote");
      cells.clear();
    } else if (cells.size() != m_columns.size()) {
      problem(file, lineNumber, "row",
              std::to_string(cells.size()) + " cells, the header has " + std::to_string(m_columns.size()));
    }

    if (cells.size() > 0) {
      const std::string index = trim(cells[0]);
      unsigned long long value = 0;
      const auto r = std::from_chars(index.data(), index.data() + index.size(), value);
      if (index.empty() || r.ec != std::errc() || r.ptr != index.data() + index.size()) {
        problem(file, lineNumber, "frame", "not an integer: \"" + cells[0] + "\"");
      } else if (value != rank) {
        problem(file, lineNumber, "frame",
                index + ", expected " + std::to_string(rank) + " (frames are numbered from 0 in row order)");
      }
    }
    if (cells.size() > 1) {
      double t = 0.;
      const std::string error = numberProblem(cells[1], t);
      if (!error.empty()) {
        problem(file, lineNumber, "t", error);
      } else {
        if (haveTime && !(t > lastTime)) {
          char buf[96];
          std::snprintf(buf, sizeof(buf), "not increasing (%s after %.6f)", trim(cells[1]).c_str(), lastTime);
          problem(file, lineNumber, "t", buf);
        } else {
          lastTime = t;
          haveTime = true;
        }
      }
    }
    if (checkPose(file, lineNumber, cells, 2)) {
      ++m_withOdometry;
    }
    if (checkPose(file, lineNumber, cells, 8)) {
      ++m_withGroundTruth;
    }
    checkImage(file, lineNumber, rank);
  }

  // A pose group is six numbers (true) or six empty cells (false).
  bool checkPose(const std::string &file, unsigned long lineNumber, const std::vector<std::string> &cells, size_t first)
  {
    if (cells.size() < first + 6) {
      return false;
    }
    size_t empty = 0;
    for (size_t i = first; i < first + 6; ++i) {
      empty += trim(cells[i]).empty() ? 1 : 0;
    }
    if (empty == 6) {
      return false;
    }
    bool ok = true;
    for (size_t i = first; i < first + 6; ++i) {
      double value = 0.;
      if (trim(cells[i]).empty()) {
        problem(file, lineNumber, kColumns[i],
                "empty, but " + std::to_string(6 - empty) + " other " + (first == 2 ? "odom_*" : "gt_*") +
                    " cells are set (the 6 cells are all numbers or all empty)");
        ok = false;
      } else {
        const std::string error = numberProblem(cells[i], value);
        if (!error.empty()) {
          problem(file, lineNumber, kColumns[i], error);
          ok = false;
        }
      }
    }
    return ok;
  }

  void checkImage(const std::string &file, unsigned long lineNumber, unsigned long rank)
  {
    char stem[32];
    std::snprintf(stem, sizeof(stem), "%06lu.", rank);
    std::string found;
    for (const char *ext : kImageExtensions) {
      std::error_code ec;
      const std::string candidate = std::string("images/") + stem + ext;
      if (found.empty() && fs::is_regular_file(path(candidate), ec)) {
        found = candidate;
      }
    }
    if (found.empty()) {
      problem(file, lineNumber, "image",
              std::string("images/") + stem + "png: missing (also looked for .jpg, .jpeg, .pgm, .ppm)");
      return;
    }
    if (!m_decodeImages) {
      return;
    }
    vpImage<unsigned char> I;
    try {
      // The header's size is checked against the image limits before anything is decoded.
      vpSSLImageIo::read(I, path(found));
    } catch (const vpException &e) {
      problem(file, lineNumber, "image", found + ": cannot be read (" + e.getStringMessage() + ")");
      return;
    } catch (const std::exception &e) { // the OpenCV backend throws cv::Exception
      problem(file, lineNumber, "image", found + ": cannot be read (" + e.what() + ")");
      return;
    }
    if (I.getWidth() == 0 || I.getHeight() == 0) {
      problem(file, lineNumber, "image", found + ": empty image");
      return;
    }
    if (m_width == 0 || m_height == 0) {
      m_width = I.getWidth();
      m_height = I.getHeight();
      m_sizeFrom = "the first image";
    } else if (I.getWidth() != m_width || I.getHeight() != m_height) {
      problem(file, lineNumber, "image",
              found + ": " + std::to_string(I.getWidth()) + "x" + std::to_string(I.getHeight()) + " pixels, expected " +
                  std::to_string(m_width) + "x" + std::to_string(m_height) + " (" + m_sizeFrom + ")");
    }
  }

  // The checks above follow doc/sequence-format.md; the library's reader must agree that the folder reads to its
  // end. A disagreement is reported as a problem so that neither can drift from the document unnoticed.
  void crossCheckWithReader()
  {
    try {
      vpSSLSequenceReader reader;
      reader.open(m_folder);
      vpSSLSequenceFrame frame;
      unsigned long n = 0;
      while (reader.next(frame)) {
        ++n;
      }
      if (n != m_frames) {
        problem(path("frames.csv"), 0, "reader",
                "vpSSLSequenceReader reads " + std::to_string(n) + " frames, the checker counted " +
                    std::to_string(m_frames));
      }
    } catch (const vpException &e) {
      problem(m_folder, 0, "reader", "vpSSLSequenceReader rejects the folder: " + e.getStringMessage());
    }
  }

  std::string m_folder;
  bool m_decodeImages;
  int m_problems;
  unsigned long m_frames;
  unsigned long m_withGroundTruth;
  unsigned long m_withOdometry;
  unsigned int m_width;  // the sequence's image size, from camera.xml or the first image; 0 before it is known
  unsigned int m_height; // see m_width
  std::string m_sizeFrom = "camera.xml";
  std::string m_target;
  std::vector<std::string> m_columns; // frames.csv header names, trimmed
};
} // namespace

int main(int argc, char **argv)
{
  bool decodeImages = true, quiet = false;
  std::vector<std::string> folders;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::cout << kUsage;
      return 0;
    } else if (a == "--no-images") {
      decodeImages = false;
    } else if (a == "--quiet") {
      quiet = true;
    } else if (a.size() > 1 && a[0] == '-') {
      std::cerr << "tutorial-ssl-check-sequence: unknown option \"" << a << "\" (see --help)" << std::endl;
      return 2;
    } else {
      folders.push_back(a);
    }
  }
  if (folders.empty()) {
    std::cerr << "tutorial-ssl-check-sequence: no sequence folder given (see --help)" << std::endl;
    return 2;
  }
  int status = 0;
  for (const std::string &folder : folders) {
    SequenceChecker checker(folder, decodeImages);
    if (checker.check() > 0) {
      status = 1;
    } else if (!quiet) {
      std::cout << checker.summary() << std::endl;
    }
  }
  return status;
}
