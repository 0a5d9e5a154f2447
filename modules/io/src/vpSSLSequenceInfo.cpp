#include <visp3/ssl/vpSSLSequenceInfo.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <visp3/core/vpException.h>
#include <visp3/ssl/vpSSLInputLimits.h>

namespace {
// A JSON value with the source span and line it came from, so that errors name the line and "water" can be
// kept verbatim.
struct JsonValue
{
  enum Kind
  {
    Null,
    Bool,
    Number,
    String,
    Array,
    Object
  };
  Kind kind = Null;
  double number = 0.;
  std::string text;               // String value
  std::vector<std::string> names; // Object member names, parallel to items
  std::vector<JsonValue> items;   // Array elements or object member values
  int line = 1;
  size_t begin = 0, end = 0;
};

// Strict RFC 8259 recursive-descent parser; sequence.json is tiny, so clarity beats speed.
class JsonParser
{
public:
  JsonParser(const std::string &text, const std::string &file) : m_s(text), m_file(file) {}

  JsonValue parseDocument()
  {
    JsonValue v = parseValue(0);
    skipSpace();
    if (m_pos != m_s.size())
      fail("unexpected " + describe() + " after the end of the JSON value");
    return v;
  }

  [[noreturn]] void fail(const std::string &what, int line = 0) const
  {
    throw vpException(vpException::badValue, m_file + ":" + std::to_string(line > 0 ? line : m_line) + ": " + what);
  }

private:
  // Nesting limit so that a hostile file cannot overflow the stack.
  static constexpr int maxDepth = 64;

  std::string describe() const
  {
    if (m_pos >= m_s.size())
      return "end of file";
    return std::string("'") + m_s[m_pos] + "'";
  }

  void skipSpace()
  {
    while (m_pos < m_s.size()) {
      char c = m_s[m_pos];
      if (c == '\n')
        ++m_line;
      else if (c != ' ' && c != '\t' && c != '\r')
        return;
      ++m_pos;
    }
  }

  bool accept(char c)
  {
    skipSpace();
    if (m_pos < m_s.size() && m_s[m_pos] == c) {
      ++m_pos;
      return true;
    }
    return false;
  }

  void expect(char c, const char *context)
  {
    if (!accept(c))
      fail(std::string("expected '") + c + "' " + context + ", got " + describe());
  }

  JsonValue parseValue(int depth)
  {
    if (depth > maxDepth)
      fail("nesting deeper than " + std::to_string(maxDepth) + " levels");
    skipSpace();
    JsonValue v;
    v.line = m_line;
    v.begin = m_pos;
    if (m_pos >= m_s.size())
      fail("expected a value, got end of file");
    char c = m_s[m_pos];
    if (c == '{') {
      v.kind = JsonValue::Object;
      ++m_pos;
      if (!accept('}')) {
        do {
          skipSpace();
          if (m_pos >= m_s.size() || m_s[m_pos] != '"')
            fail("expected a member name in double quotes, got " + describe());
          int nameLine = m_line;
          std::string name = parseString();
          for (const std::string &n : v.names)
            if (n == name)
              fail("member \"" + name + "\" appears twice", nameLine);
          expect(':', "after a member name");
          v.names.push_back(name);
          v.items.push_back(parseValue(depth + 1));
        } while (accept(','));
        expect('}', "or ',' after an object member");
      }
    } else if (c == '[') {
      v.kind = JsonValue::Array;
      ++m_pos;
      if (!accept(']')) {
        do {
          v.items.push_back(parseValue(depth + 1));
        } while (accept(','));
        expect(']', "or ',' after an array element");
      }
    } else if (c == '"') {
      v.kind = JsonValue::String;
      v.text = parseString();
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      v.kind = JsonValue::Number;
      v.number = parseNumber();
    } else if (m_s.compare(m_pos, 4, "true") == 0 || m_s.compare(m_pos, 4, "null") == 0) {
      v.kind = c == 't' ? JsonValue::Bool : JsonValue::Null;
      m_pos += 4;
    } else if (m_s.compare(m_pos, 5, "false") == 0) {
      v.kind = JsonValue::Bool;
      m_pos += 5;
    } else {
      fail("expected a value, got " + describe());
    }
    v.end = m_pos;
    return v;
  }

  unsigned hex4()
  {
    if (m_pos + 4 > m_s.size())
      fail("truncated \\u escape");
    unsigned u = 0;
    auto r = std::from_chars(m_s.data() + m_pos, m_s.data() + m_pos + 4, u, 16);
    if (r.ptr != m_s.data() + m_pos + 4)
      fail("bad \\u escape");
    m_pos += 4;
    return u;
  }

  static void appendUtf8(std::string &out, unsigned cp)
  {
    if (cp < 0x80) {
      out += char(cp);
    } else if (cp < 0x800) {
      out += char(0xC0 | (cp >> 6));
      out += char(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      out += char(0xE0 | (cp >> 12));
      out += char(0x80 | ((cp >> 6) & 0x3F));
      out += char(0x80 | (cp & 0x3F));
    } else {
      out += char(0xF0 | (cp >> 18));
      out += char(0x80 | ((cp >> 12) & 0x3F));
      out += char(0x80 | ((cp >> 6) & 0x3F));
      out += char(0x80 | (cp & 0x3F));
    }
  }

  std::string parseString()
  {
    ++m_pos; // opening quote
    std::string out;
    while (true) {
      if (m_pos >= m_s.size())
        fail("unterminated string");
      char c = m_s[m_pos++];
      if (c == '"')
        return out;
      if (static_cast<unsigned char>(c) < 0x20)
        fail("control character inside a string (a missing closing quote?)");
      if (c != '\\') {
        out += c;
        continue;
      }
      if (m_pos >= m_s.size())
        fail("unterminated string");
      char e = m_s[m_pos++];
      switch (e) {
      case '"':
        out += '"';
        break;
      case '\\':
        out += '\\';
        break;
      case '/':
        out += '/';
        break;
      case 'b':
        out += '\b';
        break;
      case 'f':
        out += '\f';
        break;
      case 'n':
        out += '\n';
        break;
      case 'r':
        out += '\r';
        break;
      case 't':
        out += '\t';
        break;
      case 'u': {
        unsigned cp = hex4();
        if (cp >= 0xD800 && cp < 0xDC00 && m_s.compare(m_pos, 2, "\\u") == 0) {
          m_pos += 2;
          unsigned lo = hex4();
          if (lo < 0xDC00 || lo >= 0xE000)
            fail("bad UTF-16 surrogate pair");
          cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
        }
        appendUtf8(out, cp);
        break;
      }
      default:
        fail(std::string("bad escape '\\") + e + "' in a string");
      }
    }
  }

  double parseNumber()
  {
    // JSON grammar: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
    size_t start = m_pos;
    auto digits = [&]() {
      size_t d = m_pos;
      while (m_pos < m_s.size() && m_s[m_pos] >= '0' && m_s[m_pos] <= '9')
        ++m_pos;
      return m_pos - d;
    };
    if (m_s[m_pos] == '-')
      ++m_pos;
    size_t intStart = m_pos;
    size_t n = digits();
    if (n == 0 || (n > 1 && m_s[intStart] == '0'))
      fail("malformed number");
    if (m_pos < m_s.size() && m_s[m_pos] == '.') {
      ++m_pos;
      if (digits() == 0)
        fail("malformed number: no digit after '.'");
    }
    if (m_pos < m_s.size() && (m_s[m_pos] == 'e' || m_s[m_pos] == 'E')) {
      ++m_pos;
      if (m_pos < m_s.size() && (m_s[m_pos] == '+' || m_s[m_pos] == '-'))
        ++m_pos;
      if (digits() == 0)
        fail("malformed number: no digit in the exponent");
    }
    double value = 0.;
    auto r = std::from_chars(m_s.data() + start, m_s.data() + m_pos, value);
    if (r.ec != std::errc() || !std::isfinite(value))
      fail("number out of range: " + m_s.substr(start, m_pos - start));
    return value;
  }

  const std::string &m_s;
  std::string m_file;
  size_t m_pos = 0;
  int m_line = 1;
};

const JsonValue *findMember(const JsonValue &object, const std::string &name)
{
  for (size_t i = 0; i < object.names.size(); ++i)
    if (object.names[i] == name)
      return &object.items[i];
  return nullptr;
}

std::string formatNumber(double v)
{
  // %.9g: enough digits for poses (nanometre, nanoradian) while staying readable; to_chars ignores the locale.
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof(buf), v, std::chars_format::general, 9);
  return std::string(buf, r.ptr);
}

std::string quote(const std::string &s)
{
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof(buf), "\\u%04x", static_cast<unsigned>(c));
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}
} // namespace

vpSSLSequenceInfo vpSSLSequenceInfo::fromJson(const std::string &textIn, const std::string &filename)
{
  // A UTF-8 byte order mark (spreadsheets and some editors write one) is skipped, as in frames.csv; the spans
  // kept below ("water") index the text without it.
  const std::string text = textIn.compare(0, 3, "\xEF\xBB\xBF") == 0 ? textIn.substr(3) : textIn;
  JsonParser parser(text, filename);
  JsonValue root = parser.parseDocument();
  if (root.kind != JsonValue::Object)
    parser.fail("expected a JSON object { \"target\": ..., \"camera_to_vehicle\": [...], \"source\": ... }", root.line);

  auto require = [&](const char *name) -> const JsonValue & {
    const JsonValue *v = findMember(root, name);
    if (!v)
      parser.fail(std::string(name) + ": missing (required)", root.line);
    return *v;
  };

  vpSSLSequenceInfo info;
  const JsonValue &target = require("target");
  if (target.kind != JsonValue::String || target.text.empty())
    parser.fail("target: expected a target name or a target file path as a non-empty string", target.line);
  info.target = target.text;

  const JsonValue &vMc = require("camera_to_vehicle");
  if (vMc.kind != JsonValue::Array || vMc.items.size() != 6)
    parser.fail("camera_to_vehicle: expected an array of 6 numbers [tx, ty, tz, tux, tuy, tuz]" +
                    (vMc.kind == JsonValue::Array ? ", got " + std::to_string(vMc.items.size()) : std::string()),
                vMc.line);
  for (unsigned int i = 0; i < 6; ++i) {
    if (vMc.items[i].kind != JsonValue::Number)
      parser.fail("camera_to_vehicle: element " + std::to_string(i + 1) + " is not a number", vMc.items[i].line);
    const double bound = i < 3 ? vpSSLInputLimits::maxMountTranslation() : vpSSLInputLimits::maxMountRotation();
    if (std::fabs(vMc.items[i].number) > bound) {
      std::ostringstream os;
      os << "camera_to_vehicle: element " << i + 1 << " is " << vMc.items[i].number << ", beyond +-" << bound
         << (i < 3 ? " m" : " rad");
      parser.fail(os.str(), vMc.items[i].line);
    }
    info.vMc[i] = vMc.items[i].number;
  }

  const JsonValue &source = require("source");
  if (source.kind != JsonValue::String || (source.text != "simulated" && source.text != "recorded"))
    parser.fail("source: expected \"simulated\" or \"recorded\"", source.line);
  info.source = source.text;

  if (const JsonValue *water = findMember(root, "water")) {
    if (water->kind != JsonValue::Object)
      parser.fail("water: expected a JSON object { ... }", water->line);
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
  std::string json = "{\n  \"target\": " + quote(target) + ",\n  \"camera_to_vehicle\": [";
  for (unsigned int i = 0; i < 6; ++i) {
    if (!std::isfinite(vMc[i]))
      throw vpException(vpException::badValue, "sequence info: camera_to_vehicle has a non-finite value");
    json += (i ? ", " : "") + formatNumber(vMc[i]);
  }
  json += "],\n  \"source\": " + quote(source);
  if (!water.empty()) {
    try {
      JsonValue w = JsonParser(water, "water").parseDocument();
      if (w.kind != JsonValue::Object)
        throw vpException(vpException::badValue, "water:1: expected a JSON object { ... }");
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
