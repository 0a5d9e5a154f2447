#include <visp3/ssl_io/vpSSLSequenceWriter.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include <visp3/core/vpException.h>
#include <visp3/core/vpXmlParserCamera.h>
#include <visp3/io/vpImageIo.h>

namespace fs = std::filesystem;

namespace {
const char *const standardHeader =
    "frame,t,odom_tx,odom_ty,odom_tz,odom_tux,odom_tuy,odom_tuz,gt_tx,gt_ty,gt_tz,gt_tux,gt_tuy,gt_tuz";
const char *const standardColumns[14] = {"frame",    "t",     "odom_tx", "odom_ty", "odom_tz", "odom_tux", "odom_tuy",
                                         "odom_tuz", "gt_tx", "gt_ty",   "gt_tz",   "gt_tux",  "gt_tuy",   "gt_tuz"};

// to_chars ignores the C locale, so a program that set LC_NUMERIC to a comma locale still writes valid CSV.
std::string format(double v, std::chars_format fmt, int precision)
{
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof(buf), v, fmt, precision);
  return std::string(buf, r.ptr);
}

// RFC 4180 quoting, only when the cell needs it.
std::string csvCell(const std::string &s)
{
  if (s.find_first_of(",\"") == std::string::npos)
    return s;
  std::string out = "\"";
  for (char c : s)
    out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

bool isSequenceFile(const fs::path &p)
{
  static const std::set<std::string> exts = {".png", ".jpg", ".jpeg", ".pgm", ".ppm"};
  std::string stem = p.stem().string();
  return stem.size() >= 6 && stem.find_first_not_of("0123456789") == std::string::npos &&
         exts.count(p.extension().string()) > 0;
}

[[noreturn]] void fail(int code, const std::string &msg)
{
  throw vpException(code, msg);
}
} // namespace

vpSSLSequenceWriter::vpSSLSequenceWriter() : m_overwrite(false), m_count(0), m_width(0), m_height(0), m_lastTime(0.) {}

vpSSLSequenceWriter::~vpSSLSequenceWriter()
{
  try {
    close();
  } catch (...) {
    // A destructor must not throw; close() explicitly to see write errors.
  }
}

void vpSSLSequenceWriter::open(const std::string &folder, const vpCameraParameters &cam, const vpSSLSequenceInfo &info,
                               const std::vector<std::string> &extraColumns)
{
  close();
  // Everything is checked before the folder is touched, so a refused open() leaves no trace.
  std::string json = info.toJson();
  std::set<std::string> names(standardColumns, standardColumns + 14);
  for (const std::string &name : extraColumns) {
    if (name.empty() || name.find_first_of(",\"\r\n") != std::string::npos || name.front() == ' ' || name.back() == ' ')
      fail(vpException::badValue, "vpSSLSequenceWriter: extra column \"" + name +
                                      "\": a name must be non-empty, without comma, quote, line break or "
                                      "surrounding space");
    if (!names.insert(name).second)
      fail(vpException::badValue, "vpSSLSequenceWriter: extra column \"" + name + "\" given twice or is standard");
  }
  if (!(cam.get_px() > 0.) || !(cam.get_py() > 0.))
    fail(vpException::badValue, "vpSSLSequenceWriter: camera px and py must be > 0");

  fs::path dir(folder);
  try {
    if (fs::exists(dir)) {
      if (!fs::is_directory(dir))
        fail(vpException::ioError, folder + ": exists and is not a folder");
      if (!fs::is_empty(dir)) {
        if (!m_overwrite)
          fail(vpException::ioError, folder + ": folder is not empty; refusing to overwrite it (choose another "
                                              "folder, or call setOverwrite(true) to replace the sequence in it)");
        for (const char *f : {"camera.xml", "sequence.json", "frames.csv"})
          fs::remove(dir / f);
        if (fs::is_directory(dir / "images"))
          for (const auto &entry : fs::directory_iterator(dir / "images"))
            if (entry.is_regular_file() && isSequenceFile(entry.path()))
              fs::remove(entry.path());
      }
    }
    fs::create_directories(dir / "images");
  } catch (const fs::filesystem_error &e) {
    fail(vpException::ioError, folder + ": cannot create the sequence folder: " + e.what());
  }

  m_folder = folder;
  m_cam = cam;
  m_count = 0;
  m_width = 0;
  m_height = 0;
  m_extraColumns = extraColumns;
  saveCamera(0, 0);
  std::string jsonPath = (dir / "sequence.json").string();
  std::ofstream jsonFile(jsonPath, std::ios::binary | std::ios::trunc);
  jsonFile << json;
  jsonFile.close();
  if (!jsonFile)
    fail(vpException::ioError, jsonPath + ": cannot write");
  m_csvPath = (dir / "frames.csv").string();
  m_csv.open(m_csvPath, std::ios::binary | std::ios::trunc);
  m_csv << standardHeader;
  for (const std::string &name : m_extraColumns)
    m_csv << ',' << name;
  m_csv << '\n';
  if (!m_csv)
    fail(vpException::ioError, m_csvPath + ": cannot write");
}

void vpSSLSequenceWriter::saveCamera(unsigned int width, unsigned int height)
{
  // vpXmlParserCamera::save() adds to an existing file and refuses a name already there: start afresh.
  std::string path = (fs::path(m_folder) / "camera.xml").string();
  std::error_code ec;
  fs::remove(path, ec);
  vpXmlParserCamera parser;
  if (parser.save(m_cam, path, "Camera", width, height) != vpXmlParserCamera::SEQUENCE_OK)
    fail(vpException::ioError, path + ": cannot write");
}

void vpSSLSequenceWriter::checkRow(const vpSSLSequenceFrame &frame, unsigned int width, unsigned int height)
{
  if (!m_csv.is_open())
    fail(vpException::notInitialized, "vpSSLSequenceWriter: call open() before write()");
  std::string id = m_csvPath + ": frame " + std::to_string(frame.index) + ": ";
  if (frame.index != m_count)
    fail(vpException::badValue, id + "index must be " + std::to_string(m_count) + " (frames are numbered from 0)");
  if (!std::isfinite(frame.t))
    fail(vpException::badValue, id + "t is not finite");
  // The reader sees the written text: compare what will be read back.
  m_timeCell = format(frame.t, std::chars_format::fixed, 6);
  double t = 0.;
  std::from_chars(m_timeCell.data(), m_timeCell.data() + m_timeCell.size(), t);
  if (m_count > 0 && !(t > m_lastTime))
    fail(vpException::badValue, id + "t: not increasing at 6 decimals (" + m_timeCell + " after " +
                                    format(m_lastTime, std::chars_format::fixed, 6) + ")");
  for (unsigned int i = 0; i < 6; ++i)
    if ((frame.hasOdometry && !std::isfinite(frame.oMv[i])) || (frame.hasGroundTruth && !std::isfinite(frame.cMo[i])))
      fail(vpException::badValue, id + "a pose value is not finite");
  for (const auto &extra : frame.extras) {
    bool declared = false;
    for (const std::string &name : m_extraColumns)
      declared = declared || name == extra.first;
    if (!declared)
      fail(vpException::badValue, id + "extra \"" + extra.first + "\" is not a column declared at open()");
    if (extra.second.find_first_of("\r\n") != std::string::npos)
      fail(vpException::badValue, id + "extra \"" + extra.first + "\": a cell cannot hold a line break");
  }
  if (width == 0 || height == 0)
    fail(vpException::badValue, id + "empty image");
  if (m_count > 0 && (width != m_width || height != m_height))
    fail(vpException::badValue, id + "image is " + std::to_string(width) + "x" + std::to_string(height) +
                                    ", the sequence's images are " + std::to_string(m_width) + "x" +
                                    std::to_string(m_height));
}

void vpSSLSequenceWriter::appendRow(const vpSSLSequenceFrame &frame)
{
  std::string row = std::to_string(frame.index) + "," + m_timeCell;
  auto pose = [&row](bool present, const vpPoseVector &p) {
    for (unsigned int i = 0; i < 6; ++i)
      row += "," + (present ? format(p[i], std::chars_format::general, 9) : std::string());
  };
  pose(frame.hasOdometry, frame.oMv);
  pose(frame.hasGroundTruth, frame.cMo);
  for (const std::string &name : m_extraColumns) {
    auto it = frame.extras.find(name);
    row += "," + (it == frame.extras.end() ? std::string() : csvCell(it->second));
  }
  m_csv << row << '\n';
  if (!m_csv)
    fail(vpException::ioError, m_csvPath + ": cannot write frame " + std::to_string(frame.index));
}

template <typename Type> void vpSSLSequenceWriter::writeFrame(const vpSSLSequenceFrame &frame, const vpImage<Type> &I)
{
  checkRow(frame, I.getWidth(), I.getHeight());
  char name[32];
  std::snprintf(name, sizeof(name), "%06u.png", frame.index);
  std::string path = (fs::path(m_folder) / "images" / name).string();
  try {
    vpImageIo::write(I, path);
  } catch (const vpException &e) {
    fail(vpException::ioError, path + ": cannot write: " + e.getStringMessage());
  }
  if (m_count == 0) {
    m_width = I.getWidth();
    m_height = I.getHeight();
    saveCamera(m_width, m_height);
  }
  // Image first, row second: a crash never leaves a row without its image.
  appendRow(frame);
  double t = 0.;
  std::from_chars(m_timeCell.data(), m_timeCell.data() + m_timeCell.size(), t);
  m_lastTime = t;
  ++m_count;
}

void vpSSLSequenceWriter::write(const vpSSLSequenceFrame &frame, const vpImage<unsigned char> &I)
{
  writeFrame(frame, I);
}

void vpSSLSequenceWriter::write(const vpSSLSequenceFrame &frame, const vpImage<vpRGBa> &I)
{
  writeFrame(frame, I);
}

void vpSSLSequenceWriter::close()
{
  if (!m_csv.is_open())
    return;
  m_csv.flush();
  bool ok = static_cast<bool>(m_csv);
  m_csv.close();
  ok = ok && !m_csv.fail();
  m_csv.clear();
  if (!ok)
    fail(vpException::ioError, m_csvPath + ": cannot write (disk full?)");
}
