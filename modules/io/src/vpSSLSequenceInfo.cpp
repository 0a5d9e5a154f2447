#include <visp3/ssl_io/vpSSLSequenceInfo.h>

#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include <visp3/core/vpException.h>
#include <visp3/ssl/vpSSLInputLimits.h>

namespace {
using Json = nlohmann::ordered_json;

// A character iterator that publishes how far nlohmann's lexer has read: SAX events carry no position, and
// every error must name a line, and "water" must be kept verbatim (its byte span).
class TrackedIterator
{
public:
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char *;
  using reference = const char &;

  TrackedIterator(const char *p, const char **read) : m_p(p), m_read(read) {}
  reference operator*() const { return *m_p; }
  TrackedIterator &operator++()
  {
    *m_read = ++m_p;
    return *this;
  }
  TrackedIterator operator++(int)
  {
    TrackedIterator old = *this;
    ++*this;
    return old;
  }
  bool operator==(const TrackedIterator &o) const { return m_p == o.m_p; }
  bool operator!=(const TrackedIterator &o) const { return m_p != o.m_p; }

private:
  const char *m_p;
  const char **m_read;
};

// A top-level member of sequence.json, as much of it as the checks need.
struct Member
{
  enum Kind
  {
    Other,
    String,
    Array,
    Object
  };
  Kind kind = Other;
  int line = 1;
  std::string text;            // a string's value
  size_t begin = 0, end = 0;   // an object's span in the text ("water")
  size_t size = 0;             // an array's number of elements
  std::vector<bool> isNumber;  // its first six elements: numbers or not
  std::vector<double> numbers; // their values
  std::vector<int> lines;      // their lines
};

// Strict RFC 8259 reading through nlohmann's SAX parser, keeping the root object's members with their lines.
class Reader : public nlohmann::json_sax<Json>
{
public:
  Reader(const std::string &text, const std::string &file) : m_text(text), m_file(file), m_read(text.data()) {}

  void parse()
  {
    const TrackedIterator first(m_text.data(), &m_read), last(m_text.data() + m_text.size(), &m_read);
    Json::sax_parse(first, last, this, nlohmann::detail::input_format_t::json, true, false);
  }

  [[noreturn]] void fail(const std::string &what, int line) const
  {
    throw vpException(vpException::badValue, m_file + ":" + std::to_string(line) + ": " + what);
  }

  int rootLine = 1;
  bool rootIsObject = false;
  std::vector<std::string> names;
  std::vector<Member> members;

  bool null() override { return scalar(false, 0.); }
  bool boolean(bool) override { return scalar(false, 0.); }
  bool number_integer(number_integer_t v) override { return scalar(true, static_cast<double>(v)); }
  bool number_unsigned(number_unsigned_t v) override { return scalar(true, static_cast<double>(v)); }
  bool number_float(number_float_t v, const string_t &) override { return scalar(true, v); }
  bool binary(binary_t &) override { return scalar(false, 0.); }
  bool string(string_t &s) override
  {
    if (m_depth == 1 && rootIsObject) {
      Member &m = member();
      m.kind = Member::String;
      m.text = s;
    }
    return scalar(false, 0.);
  }

  bool start_object(std::size_t) override
  {
    open();
    if (m_depth == 0) {
      rootIsObject = true;
    } else if (m_depth == 1 && rootIsObject) {
      member().kind = Member::Object;
      member().begin = at();
    }
    m_keys.emplace_back();
    ++m_depth;
    return true;
  }
  bool end_object() override
  {
    --m_depth;
    m_keys.pop_back();
    if (m_depth == 1 && rootIsObject) {
      member().end = at() + 1;
    }
    return true;
  }
  bool key(string_t &name) override
  {
    const int line = lineOf(at());
    if (!m_keys.back().insert(name).second) {
      fail("member \"" + name + "\" appears twice", line);
    }
    if (m_depth == 1 && rootIsObject) {
      names.push_back(name);
      members.emplace_back();
    }
    return true;
  }
  bool start_array(std::size_t) override
  {
    open();
    if (m_depth == 1 && rootIsObject) {
      member().kind = Member::Array;
    }
    m_keys.emplace_back(); // no keys in an array: the stack follows the nesting
    ++m_depth;
    return true;
  }
  bool end_array() override
  {
    --m_depth;
    m_keys.pop_back();
    return true;
  }

  bool parse_error(std::size_t position, const std::string &, const nlohmann::detail::exception &e) override
  {
    fail(syntaxError(position, e.what()), lineOf(lastReadBefore(position)));
  }

private:
  // Nesting limit, as for any input of the plugin: a hostile file cannot make the reader hold deep stacks.
  static constexpr int maxDepth = 64;

  Member &member() { return members.back(); }

  // Offset of the last byte read, and line of the last non-blank byte at or before an offset: a number is
  // only known to end when the byte after it is read, and that byte may be a line feed.
  size_t at() const { return static_cast<size_t>(m_read - m_text.data()) - 1; }
  size_t lastReadBefore(size_t position) const
  {
    size_t p = std::min(position, m_text.size());
    while (p > 0 && (m_text[p - 1] == ' ' || m_text[p - 1] == '\t' || m_text[p - 1] == '\r' || m_text[p - 1] == '\n')) {
      --p;
    }
    return p == 0 ? 0 : p - 1;
  }
  // Lines are counted incrementally: events come in text order, so a large file costs one pass.
  int lineOf(size_t offset)
  {
    if (offset < m_counted) {
      m_counted = 0;
      m_countedLine = 1;
    }
    for (; m_counted < offset && m_counted < m_text.size(); ++m_counted) {
      m_countedLine += m_text[m_counted] == '\n';
    }
    return m_countedLine;
  }

  // A value starts at the last byte read (a container) or ends there (a scalar, but for a number's lookahead).
  void value(bool isNumber, double number, int line)
  {
    if (m_depth == 0) {
      rootLine = line;
    } else if (!rootIsObject) {
      return; // a root array: an error once parsed, whatever it holds
    } else if (m_depth == 1) {
      member().line = line;
    } else if (m_depth == 2 && member().kind == Member::Array) {
      Member &m = member();
      if (m.size < 6) {
        m.isNumber.push_back(isNumber);
        m.numbers.push_back(number);
        m.lines.push_back(line);
      }
      ++m.size;
    }
  }

  void open()
  {
    const int line = lineOf(at());
    if (m_depth >= maxDepth) {
      fail("nesting deeper than " + std::to_string(maxDepth) + " levels", line);
    }
    value(false, 0., line);
  }

  bool scalar(bool isNumber, double number)
  {
    value(isNumber, number, lineOf(lastReadBefore(at() + 1)));
    return true;
  }

  // nlohmann's message "syntax error while parsing CONTEXT - PROBLEM; expected TOKEN" said in the plugin's words.
  // Its last token string is not used: the lexer keeps structural characters in it across tokens.
  std::string syntaxError(size_t position, const std::string &message) const
  {
    const size_t dash = message.find(" - ");
    std::string problem = dash == std::string::npos ? message : message.substr(dash + 3);
    const size_t lastRead = problem.find("; last read");
    const std::string lexer = lastRead == std::string::npos ? std::string() : problem.substr(0, lastRead);
    if (lexer.compare(0, 34, "invalid string: control character ") == 0) {
      return "control character inside a string (a missing closing quote?)";
    }
    if (lexer.compare(0, 16, "invalid number; ") == 0) {
      return "malformed number: " + lexer.substr(16);
    }
    if (lexer.compare(0, 15, "invalid string:") == 0) {
      return lexer;
    }
    const size_t overflow = message.find("number overflow parsing ");
    if (overflow != std::string::npos) {
      return "number out of range: " + message.substr(overflow + 24);
    }
    // What was found: a token's kind, or the byte the lexer stopped at.
    std::string got;
    if (problem.compare(0, 11, "unexpected ") == 0) {
      got = problem.substr(11, problem.find(';') == std::string::npos ? std::string::npos : problem.find(';') - 11);
      if (got == "end of input") {
        got = "end of file";
      }
    } else {
      const size_t at = lastReadBefore(position);
      got = at < m_text.size() ? std::string("'") + m_text[at] + "'" : "end of file";
    }
    // A number right after a digit: a leading zero ("01"), which the lexer reads as two numbers.
    if (got == "number literal") {
      const size_t at = lastReadBefore(position);
      size_t start = at;
      while (start > 0 && std::strchr("0123456789+-.eE", m_text[start - 1]) != nullptr) {
        --start;
      }
      if (start < at && m_text[start] == '0' && m_text[start + 1] >= '0' && m_text[start + 1] <= '9') {
        return "malformed number: a leading zero";
      }
    }
    if (message.find("while parsing object key") != std::string::npos) {
      return "expected a member name in double quotes, got " + got;
    }
    if (message.find("while parsing object separator") != std::string::npos) {
      return "expected ':' after a member name, got " + got;
    }
    if (message.find("while parsing object ") != std::string::npos) {
      return "expected '}' or ',' after an object member, got " + got;
    }
    if (message.find("while parsing array") != std::string::npos) {
      return "expected ']' or ',' after an array element, got " + got;
    }
    if (message.find("; expected end of input") != std::string::npos) {
      return "unexpected " + got + " after the end of the JSON value";
    }
    return "expected a value, got " + got;
  }

  const std::string &m_text;
  std::string m_file;
  const char *m_read;
  int m_depth = 0;
  size_t m_counted = 0;
  int m_countedLine = 1;
  std::vector<std::set<std::string>> m_keys;
};

std::string formatNumber(double v)
{
  // %.9g: enough digits for poses (nanometre, nanoradian) while staying readable; to_chars ignores the locale.
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof(buf), v, std::chars_format::general, 9);
  return std::string(buf, r.ptr);
}
} // namespace

vpSSLSequenceInfo vpSSLSequenceInfo::fromJson(const std::string &textIn, const std::string &filename)
{
  // A UTF-8 byte order mark (spreadsheets and some editors write one) is skipped, as in frames.csv; the spans
  // kept below ("water") index the text without it.
  const std::string text = textIn.compare(0, 3, "\xEF\xBB\xBF") == 0 ? textIn.substr(3) : textIn;
  Reader reader(text, filename);
  reader.parse();
  if (!reader.rootIsObject) {
    reader.fail("expected a JSON object { \"target\": ..., \"camera_to_vehicle\": [...], \"source\": ... }",
                reader.rootLine);
  }
  auto find = [&](const char *name) -> const Member * {
    for (size_t i = 0; i < reader.names.size(); ++i) {
      if (reader.names[i] == name) {
        return &reader.members[i];
      }
    }
    return nullptr;
  };
  auto require = [&](const char *name) -> const Member & {
    const Member *m = find(name);
    if (m == nullptr) {
      reader.fail(std::string(name) + ": missing (required)", reader.rootLine);
    }
    return *m;
  };

  vpSSLSequenceInfo info;
  const Member &target = require("target");
  if (target.kind != Member::String || target.text.empty()) {
    reader.fail("target: expected a target name or a target file path as a non-empty string", target.line);
  }
  info.target = target.text;

  const Member &vMc = require("camera_to_vehicle");
  if (vMc.kind != Member::Array || vMc.size != 6) {
    reader.fail("camera_to_vehicle: expected an array of 6 numbers [tx, ty, tz, tux, tuy, tuz]" +
                    (vMc.kind == Member::Array ? ", got " + std::to_string(vMc.size) : std::string()),
                vMc.line);
  }
  for (unsigned int i = 0; i < 6; ++i) {
    if (!vMc.isNumber[i]) {
      reader.fail("camera_to_vehicle: element " + std::to_string(i + 1) + " is not a number", vMc.lines[i]);
    }
    const double bound = i < 3 ? vpSSLInputLimits::maxMountTranslation() : vpSSLInputLimits::maxMountRotation();
    if (std::fabs(vMc.numbers[i]) > bound) {
      std::ostringstream os;
      os << "camera_to_vehicle: element " << i + 1 << " is " << vMc.numbers[i] << ", beyond +-" << bound
         << (i < 3 ? " m" : " rad");
      reader.fail(os.str(), vMc.lines[i]);
    }
    info.vMc[i] = vMc.numbers[i];
  }

  const Member &source = require("source");
  if (source.kind != Member::String || (source.text != "simulated" && source.text != "recorded")) {
    reader.fail("source: expected \"simulated\" or \"recorded\"", source.line);
  }
  info.source = source.text;

  if (const Member *water = find("water")) {
    if (water->kind != Member::Object) {
      reader.fail("water: expected a JSON object { ... }", water->line);
    }
    info.water = text.substr(water->begin, water->end - water->begin);
  }
  return info;
}

vpSSLSequenceInfo vpSSLSequenceInfo::load(const std::string &filename)
{
  std::error_code ec;
  if (std::filesystem::is_directory(filename, ec))
    throw vpException(vpException::ioError, filename + ": is a folder, not a file");
  std::ifstream in(filename, std::ios::binary);
  if (!in)
    throw vpException(vpException::ioError, filename + ": missing or unreadable");
  // sequence.json is a few hundred bytes: a large file is not one, and is not read whole into memory.
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size > static_cast<std::streamoff>(maxFileSize()))
    throw vpException(vpException::badValue, filename + ": " + std::to_string(size) + " bytes, more than the " +
                                                 std::to_string(maxFileSize()) + " a sequence.json may have");
  in.seekg(0);
  std::ostringstream text;
  text << in.rdbuf();
  return fromJson(text.str(), filename);
}

std::string vpSSLSequenceInfo::toJson() const
{
  if (target.empty())
    throw vpException(vpException::badValue, "sequence info: target is empty (give a target name or file path)");
  if (source != "simulated" && source != "recorded")
    throw vpException(vpException::badValue,
                      "sequence info: source is \"" + source + "\", expected \"simulated\" or \"recorded\"");
  // The layout (one member a line, the pose on one line, "water" verbatim) is the format's, not nlohmann's
  // dump(): nlohmann quotes the strings and checks "water".
  std::string targetJson;
  try {
    targetJson = Json(target).dump();
  } catch (const Json::exception &) {
    throw vpException(vpException::badValue, "sequence info: target is not valid UTF-8");
  }
  std::string json = "{\n  \"target\": " + targetJson + ",\n  \"camera_to_vehicle\": [";
  for (unsigned int i = 0; i < 6; ++i) {
    if (!std::isfinite(vMc[i]))
      throw vpException(vpException::badValue, "sequence info: camera_to_vehicle has a non-finite value");
    json += (i ? ", " : "") + formatNumber(vMc[i]);
  }
  json += "],\n  \"source\": " + Json(source).dump();
  if (!water.empty()) {
    try {
      Reader check(water, "water");
      check.parse();
      if (!check.rootIsObject)
        check.fail("expected a JSON object { ... }", check.rootLine);
    } catch (const vpException &e) {
      throw vpException(vpException::badValue,
                        "sequence info: water is not a valid JSON object: " + e.getStringMessage());
    }
    json += ",\n  \"water\": " + water;
  }
  return json + "\n}\n";
}

void vpSSLSequenceInfo::save(const std::string &filename) const
{
  std::string json = toJson();
  std::ofstream out(filename, std::ios::binary | std::ios::trunc);
  out << json;
  out.close();
  if (!out)
    throw vpException(vpException::ioError, filename + ": cannot write");
}
