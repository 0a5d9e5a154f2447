#include <visp3/ssl_io/vpSSLSequenceReader.h>

#include <visp3/ssl_io/vpSSLCameraFile.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include <visp3/core/vpException.h>
#include <visp3/ssl_io/vpSSLImageIo.h>

#include "vpSSLCsv.h"

namespace fs = std::filesystem;
using namespace vpSSLCsv;

namespace {
const char *const standardColumns[14] = {"frame",    "t",     "odom_tx", "odom_ty", "odom_tz", "odom_tux", "odom_tuy",
                                         "odom_tuz", "gt_tx", "gt_ty",   "gt_tz",   "gt_tux",  "gt_tuy",   "gt_tuz"};
const char *const imageExtensions[] = {"png", "jpg", "jpeg", "pgm", "ppm"};

// After an error the reader stays failed: the next call repeats the error instead of reading on out of step.
template <typename Read> bool sticky(std::string &error, Read read)
{
  if (!error.empty())
    throw vpException(vpException::badValue, error);
  try {
    return read();
  } catch (const vpException &e) {
    error = e.getStringMessage();
    throw;
  }
}

} // namespace

vpSSLSequenceReader::vpSSLSequenceReader()
    : m_lineNumber(0), m_rowIndex(0), m_ended(true), m_lastTimeValue(0.), m_width(0), m_height(0)
{
}

void vpSSLSequenceReader::open(const std::string &folder)
{
  close();
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw vpException(vpException::ioError, folder + ": not a sequence folder (missing or not a directory)");
  m_folder = folder;
  readCamera();
  m_info = vpSSLSequenceInfo::load((fs::path(folder) / "sequence.json").string());
  m_csvPath = (fs::path(folder) / "frames.csv").string();
  m_csv.open(m_csvPath, std::ios::binary);
  if (!m_csv)
    throw vpException(vpException::ioError, m_csvPath + ": missing or unreadable");
  m_lineNumber = 0;
  m_rowIndex = 0;
  m_ended = false;
  m_imagePath.clear();
  readHeader();
}

std::string vpSSLSequenceReader::getTargetPath() const
{
  const std::string &t = m_info.target;
  if (t.empty() || fs::path(t).is_absolute())
    return t;
  const fs::path inFolder = fs::path(m_folder) / t;
  std::error_code ec;
  // A name (ssl3-a3, an AprilTag sheet) has no file of that name in the folder; a relative path always names
  // one there, never one in the working folder.
  if (fs::exists(inFolder, ec) || t.find('/') != std::string::npos || t.find('\\') != std::string::npos ||
      (t.size() > 4 && t.compare(t.size() - 4, 4, ".txt") == 0))
    return inFolder.string();
  return t;
}

void vpSSLSequenceReader::close()
{
  if (m_csv.is_open())
    m_csv.close();
  m_csv.clear();
  m_ended = true;
  m_error.clear();
}

void vpSSLSequenceReader::readCamera()
{
  const std::string path = (fs::path(m_folder) / "camera.xml").string();
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw vpException(vpException::ioError, path + ": missing");
  m_cam = vpSSLCameraFile::load(path, "Camera", &m_width, &m_height);
}

void vpSSLSequenceReader::readHeader()
{
  std::string expected;
  for (const char *c : standardColumns)
    expected += std::string(expected.empty() ? "" : ",") + c;
  if (!getLine(m_csv, m_line, m_csvPath + ":1: "))
    throw vpException(vpException::badValue, m_csvPath + ":1: empty file, expected the header " + expected);
  m_lineNumber = 1;
  if (m_line.compare(0, 3, "\xEF\xBB\xBF") == 0) // UTF-8 byte order mark written by spreadsheets
    m_line.erase(0, 3);
  if (!m_line.empty() && m_line.back() == '\r')
    m_line.pop_back();
  checkLineEnd(m_line, m_csvPath + ":1: ");
  if (!splitCsv(m_line, m_cells))
    throw vpException(vpException::badValue, m_csvPath + ":1: unterminated quote in the header");
  for (unsigned int i = 0; i < 14; ++i) {
    std::string col = std::to_string(i + 1);
    if (i >= m_cells.size())
      throw vpException(vpException::badValue, m_csvPath + ":1: column " + col + " \"" + standardColumns[i] +
                                                   "\": missing (header has " + std::to_string(m_cells.size()) +
                                                   " columns, expected " + expected + ")");
    if (trim(m_cells[i]) != standardColumns[i])
      throw vpException(vpException::badValue, m_csvPath + ":1: column " + col + ": expected \"" + standardColumns[i] +
                                                   "\", got \"" + m_cells[i] + "\" (the header starts with " +
                                                   expected + ")");
  }
  m_extraColumns.clear();
  for (size_t i = 14; i < m_cells.size(); ++i) {
    std::string name = trim(m_cells[i]);
    std::string col = m_csvPath + ":1: column " + std::to_string(i + 1);
    if (name.empty())
      throw vpException(vpException::badValue, col + ": empty column name");
    for (size_t j = 0; j < i; ++j)
      if (trim(m_cells[j]) == name)
        throw vpException(vpException::badValue, col + ": \"" + name + "\" is also column " + std::to_string(j + 1));
    m_extraColumns.push_back(name);
  }
}

std::string vpSSLSequenceReader::where() const
{
  return m_csvPath + ":" + std::to_string(m_lineNumber) + ": ";
}

bool vpSSLSequenceReader::readRow(vpSSLSequenceFrame &frame)
{
  if (!m_csv.is_open())
    throw vpException(vpException::notInitialized, "vpSSLSequenceReader: call open() before next()");
  if (m_ended)
    return false;
  if (!getLine(m_csv, m_line, m_csvPath + ":" + std::to_string(m_lineNumber + 1) + ": ")) {
    m_ended = true;
    return false;
  }
  ++m_lineNumber;
  if (!m_line.empty() && m_line.back() == '\r')
    m_line.pop_back();
  checkLineEnd(m_line, where());
  if (m_line.empty()) {
    // Trailing empty lines end the table; an empty line followed by rows is a hole in it.
    unsigned int emptyLine = m_lineNumber;
    while (getLine(m_csv, m_line, m_csvPath + ":" + std::to_string(m_lineNumber + 1) + ": ")) {
      ++m_lineNumber;
      if (!m_line.empty() && m_line != "\r")
        throw vpException(vpException::badValue, m_csvPath + ":" + std::to_string(emptyLine) +
                                                     ": empty line inside the table (rows go on at line " +
                                                     std::to_string(m_lineNumber) + ")");
    }
    m_ended = true;
    return false;
  }
  if (!splitCsv(m_line, m_cells))
    throw vpException(vpException::badValue, where() + "unterminated quote");
  size_t nColumns = 14 + m_extraColumns.size();
  auto columnName = [&](size_t i) { return i < 14 ? std::string(standardColumns[i]) : m_extraColumns[i - 14]; };
  if (m_cells.size() < nColumns)
    throw vpException(vpException::badValue, where() + columnName(m_cells.size()) + ": missing (row has " +
                                                 std::to_string(m_cells.size()) + " cells, expected " +
                                                 std::to_string(nColumns) + ")");
  if (m_cells.size() > nColumns)
    throw vpException(vpException::badValue, where() + "cell " + std::to_string(nColumns + 1) +
                                                 ": no column for it (row has " + std::to_string(m_cells.size()) +
                                                 " cells, the header " + std::to_string(nColumns) + ")");

  std::string index = trim(m_cells[0]);
  unsigned long long value = 0;
  auto r = std::from_chars(index.data(), index.data() + index.size(), value);
  if (index.empty() || r.ec != std::errc() || r.ptr != index.data() + index.size())
    throw vpException(vpException::badValue, where() + "frame: not an integer: \"" + m_cells[0] + "\"");
  if (value != m_rowIndex)
    throw vpException(vpException::badValue, where() + "frame: " + index + ", expected " + std::to_string(m_rowIndex) +
                                                 " (frames are numbered from 0 in row order)");

  double t = 0.;
  std::string error = parseNumber(m_cells[1], t, maxTime(), "s");
  if (!error.empty())
    throw vpException(vpException::badValue, where() + "t: " + error);
  if (m_rowIndex > 0 && !(t > m_lastTimeValue))
    throw vpException(vpException::badValue,
                      where() + "t: not increasing (" + trim(m_cells[1]) + " after " + m_lastTime + ")");

  // A pose group is either 6 numbers or 6 empty cells: a partial pose is a broken recording, not "absent".
  auto readPose = [&](size_t first, vpPoseVector &pose) {
    size_t nEmpty = 0;
    for (size_t i = first; i < first + 6; ++i)
      nEmpty += trim(m_cells[i]).empty() ? 1 : 0;
    if (nEmpty == 6)
      return false;
    for (size_t i = first; i < first + 6; ++i) {
      if (nEmpty > 0 && trim(m_cells[i]).empty())
        throw vpException(vpException::badValue, where() + columnName(i) + ": empty, but " +
                                                     std::to_string(6 - nEmpty) + " other " +
                                                     columnName(first).substr(0, columnName(first).find('_')) +
                                                     "_* cells are set (the 6 cells are all numbers or all empty)");
      const bool translation = i < first + 3;
      std::string err = parseNumber(m_cells[i], pose[static_cast<unsigned int>(i - first)],
                                    translation ? maxTranslation() : maxRotation(), translation ? "m" : "rad");
      if (!err.empty())
        throw vpException(vpException::badValue, where() + columnName(i) + ": " + err);
    }
    return true;
  };
  frame.hasOdometry = readPose(2, frame.oMv);
  frame.hasGroundTruth = readPose(8, frame.cMo);
  frame.index = m_rowIndex;
  frame.t = t;
  frame.extras.clear();
  for (size_t i = 0; i < m_extraColumns.size(); ++i)
    frame.extras[m_extraColumns[i]] = m_cells[14 + i];

  char name[32];
  std::snprintf(name, sizeof(name), "%06u.", m_rowIndex);
  fs::path images = fs::path(m_folder) / "images";
  m_imagePath.clear();
  for (const char *ext : imageExtensions) {
    fs::path p = images / (name + std::string(ext));
    std::error_code ec;
    if (fs::is_regular_file(p, ec)) {
      m_imagePath = p.string();
      break;
    }
  }
  if (m_imagePath.empty())
    throw vpException(vpException::ioError, (images / (name + std::string("png"))).string() +
                                                ": missing (frames.csv:" + std::to_string(m_lineNumber) +
                                                "; also looked for .jpg, .jpeg, .pgm, .ppm)");
  m_lastTime = trim(m_cells[1]);
  m_lastTimeValue = t;
  ++m_rowIndex;
  return true;
}

template <typename Type> bool vpSSLSequenceReader::nextWithImage(vpSSLSequenceFrame &frame, vpImage<Type> &I)
{
  if (!readRow(frame))
    return false;
  std::string line = "frames.csv:" + std::to_string(m_lineNumber);
  // vpSSLImageIo checks the header's size before decoding, and its messages name the file.
  try {
    vpSSLImageIo::read(I, m_imagePath);
  } catch (const vpException &e) {
    throw vpException(vpException::ioError, e.getStringMessage() + " (" + line + ")");
  } catch (const std::exception &e) {
    throw vpException(vpException::ioError, m_imagePath + ": cannot read the image (" + line + "): " + e.what());
  }
  if (I.getWidth() == 0 || I.getHeight() == 0)
    throw vpException(vpException::ioError, m_imagePath + ": empty image (" + line + ")");
  // All images share one size: camera.xml's when it gives one, else the first image's.
  if (m_width == 0 || m_height == 0) {
    m_width = I.getWidth();
    m_height = I.getHeight();
  } else if (I.getWidth() != m_width || I.getHeight() != m_height) {
    throw vpException(vpException::badValue, m_imagePath + ": " + std::to_string(I.getWidth()) + "x" +
                                                 std::to_string(I.getHeight()) + " pixels, expected " +
                                                 std::to_string(m_width) + "x" + std::to_string(m_height) +
                                                 " as in camera.xml or the first image (" + line + ")");
  }
  return true;
}

bool vpSSLSequenceReader::next(vpSSLSequenceFrame &frame, vpImage<unsigned char> &I)
{
  return sticky(m_error, [&]() { return nextWithImage(frame, I); });
}

bool vpSSLSequenceReader::next(vpSSLSequenceFrame &frame, vpImage<vpRGBa> &I)
{
  return sticky(m_error, [&]() { return nextWithImage(frame, I); });
}

bool vpSSLSequenceReader::next(vpSSLSequenceFrame &frame)
{
  return sticky(m_error, [&]() { return readRow(frame); });
}
