/*
  Internal to visp_ssl (not installed): the CSV cells of frames.csv and of an odometry CSV, read the same way.
*/
#ifndef VP_SSL_CSV_H
#define VP_SSL_CSV_H

#include <charconv>
#include <cmath>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

#include <visp3/core/vpException.h>

namespace vpSSLCsv {

// Longest line of a CSV read by getLine(): rows of a few hundred bytes, with room for extra columns.
const size_t kMaxLineLength = 1 << 20;

// std::getline() with a bound, so that a file without line ends cannot grow the line to the file's size: reads the
// next line of \e in without its LF into \e line; false at the end of the file (as std::getline()).
// \exception vpException naming \e where (the file and line) once the line exceeds kMaxLineLength bytes.
inline bool getLine(std::istream &in, std::string &line, const std::string &where)
{
  line.clear();
  std::streambuf *buffer = in.rdbuf();
  if (!in.good() || buffer == nullptr) {
    in.setstate(std::ios::failbit);
    return false;
  }
  for (;;) {
    const int c = buffer->sbumpc();
    if (c == std::char_traits<char>::eof()) {
      in.setstate(line.empty() ? std::ios::eofbit | std::ios::failbit : std::ios::eofbit);
      return !line.empty();
    }
    if (c == '\n') {
      return true;
    }
    if (line.size() >= kMaxLineLength) {
      throw vpException(vpException::badValue,
                        where + "line longer than " + std::to_string(kMaxLineLength) + " bytes (no line end?)");
    }
    line.push_back(static_cast<char>(c));
  }
}

inline std::string trim(const std::string &s)
{
  size_t b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos)
    return std::string();
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

// RFC 4180 cells on one line; quotes are only needed for extra columns, but a converter may add them anywhere.
// Returns false on an unterminated quote.
inline bool splitCsv(const std::string &line, std::vector<std::string> &cells)
{
  cells.clear();
  std::string cell;
  size_t i = 0;
  while (true) {
    cell.clear();
    if (i < line.size() && line[i] == '"') {
      ++i;
      while (true) {
        if (i >= line.size())
          return false;
        if (line[i] == '"') {
          if (i + 1 < line.size() && line[i + 1] == '"') {
            cell += '"';
            i += 2;
            continue;
          }
          ++i;
          break;
        }
        cell += line[i++];
      }
      size_t comma = line.find(',', i);
      cell += line.substr(i, comma == std::string::npos ? std::string::npos : comma - i);
      i = comma;
    } else {
      size_t comma = line.find(',', i);
      cell.assign(line, i, comma == std::string::npos ? std::string::npos : comma - i);
      i = comma;
    }
    cells.push_back(cell);
    if (i == std::string::npos)
      return true;
    ++i;
  }
}

// Locale-independent, whole-cell, finite number within +-bound; an empty string means "ok".
inline std::string parseNumber(const std::string &cell, double &value, double bound, const char *unit)
{
  std::string s = trim(cell);
  const char *b = s.data(), *e = s.data() + s.size();
  if (b != e && *b == '+') {
    ++b;
    // from_chars takes a sign of its own: "+-0.1" is not a number.
    if (b != e && (*b == '-' || *b == '+'))
      return "not a number: \"" + cell + "\"";
  }
  auto r = std::from_chars(b, e, value);
  if (s.empty() || r.ec != std::errc() || r.ptr != e || !std::isfinite(value))
    return "not a number: \"" + cell + "\"";
  if (std::fabs(value) > bound) {
    std::ostringstream os;
    os << s << " is beyond +-" << bound << " " << unit;
    return os.str();
  }
  return std::string();
}

// Lines ending in CR alone (classic Mac OS) read as one line holding every row.
inline void checkLineEnd(const std::string &line, const std::string &where)
{
  if (line.find('\r') != std::string::npos)
    throw vpException(vpException::badValue, where + "a carriage return inside the line: lines must end in LF or "
                                                     "CRLF, not CR alone (convert the file, e.g. with tr '\\r' "
                                                     "'\\n')");
}

} // namespace vpSSLCsv

#endif
