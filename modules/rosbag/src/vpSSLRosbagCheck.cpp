#include "vpSSLRosbagCheck.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <vector>

#include <visp3/core/vpException.h>

namespace {
// Record ops of the bag format 2.0.
const uint8_t kMessageData = 0x02, kFileHeader = 0x03, kIndexData = 0x04, kChunk = 0x05, kChunkInfo = 0x06,
              kConnection = 0x07;
// A connection header, the longest record header, holds a message definition of a few kilobytes.
const uint32_t kMaxHeaderLength = 1 << 24;

uint32_t le32(const uint8_t *p)
{
  return uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16) | (uint32_t(p[3]) << 24);
}

uint64_t le64(const uint8_t *p)
{
  return uint64_t(le32(p)) | (uint64_t(le32(p + 4)) << 32);
}

// One record: its position, op, header fields and data.
struct Record
{
  uint64_t pos = 0;
  uint8_t op = 0;
  std::map<std::string, std::string> fields;
  uint64_t dataPos = 0;
  uint32_t dataLength = 0;
};

class BagFile
{
public:
  explicit BagFile(const std::string &filename) : m_filename(filename), m_in(filename, std::ios::binary)
  {
    if (!m_in)
      throw vpException(vpException::ioError, filename + ": cannot read the bag: missing or unreadable");
    m_in.seekg(0, std::ios::end);
    m_size = static_cast<uint64_t>(m_in.tellg());
  }

  [[noreturn]] void fail(uint64_t at, const std::string &problem) const
  {
    throw vpException(vpException::ioError,
                      m_filename + ": cannot read the bag: byte " + std::to_string(at) + ": " + problem);
  }

  uint64_t size() const { return m_size; }

  void read(uint64_t at, void *buffer, size_t n)
  {
    m_in.clear();
    m_in.seekg(static_cast<std::streamoff>(at));
    m_in.read(static_cast<char *>(buffer), static_cast<std::streamsize>(n));
    if (static_cast<size_t>(m_in.gcount()) != n)
      fail(at, "read error");
  }

  uint32_t read32(uint64_t at)
  {
    uint8_t b[4];
    read(at, b, 4);
    return le32(b);
  }

  // The fields of a header (4-byte length, then "name=value", repeated) of n bytes at \e at.
  std::map<std::string, std::string> readFields(uint64_t at, uint32_t n)
  {
    std::vector<uint8_t> bytes(n);
    read(at, bytes.data(), n);
    std::map<std::string, std::string> fields;
    for (size_t p = 0; p < n;) {
      if (n - p < 4)
        fail(at + p, "header field length cut by the end of the header");
      const uint32_t length = le32(&bytes[p]);
      if (length > n - p - 4)
        fail(at + p, "header field of " + std::to_string(length) + " bytes beyond the end of the header");
      const std::string field(reinterpret_cast<const char *>(&bytes[p + 4]), length);
      const size_t eq = field.find('=');
      if (eq == std::string::npos)
        fail(at + p, "header field without '='");
      fields[field.substr(0, eq)] = field.substr(eq + 1);
      p += 4 + length;
    }
    return fields;
  }

  // The record at \e pos, which must lie before \e end.
  Record readRecord(uint64_t pos, uint64_t end)
  {
    Record r;
    r.pos = pos;
    if (end - pos < 4)
      fail(pos, "record header length cut by the end of its " + std::string(end == m_size ? "file" : "chunk"));
    const uint32_t headerLength = read32(pos);
    if (headerLength > kMaxHeaderLength || headerLength + uint64_t(8) > end - pos)
      fail(pos, "record header of " + std::to_string(headerLength) + " bytes beyond the end of its " +
                    (end == m_size ? "file" : "chunk"));
    r.fields = readFields(pos + 4, headerLength);
    const std::string op = field(r, "op");
    if (op.size() != 1)
      fail(pos, "record op of " + std::to_string(op.size()) + " bytes");
    r.op = static_cast<uint8_t>(op[0]);
    r.dataPos = pos + 8 + headerLength;
    r.dataLength = read32(pos + 4 + headerLength);
    if (r.dataLength > end - r.dataPos)
      fail(pos, "record data of " + std::to_string(r.dataLength) + " bytes beyond the end of its " +
                    (end == m_size ? "file" : "chunk"));
    return r;
  }

  std::string field(const Record &r, const std::string &name) const
  {
    auto f = r.fields.find(name);
    if (f == r.fields.end())
      fail(r.pos, "record without its '" + name + "' field");
    return f->second;
  }

  uint64_t number(const Record &r, const std::string &name, size_t bytes) const
  {
    const std::string value = field(r, name);
    if (value.size() != bytes)
      fail(r.pos,
           "field '" + name + "' of " + std::to_string(value.size()) + " bytes, expected " + std::to_string(bytes));
    const uint8_t *p = reinterpret_cast<const uint8_t *>(value.data());
    return bytes == 8 ? le64(p) : le32(p);
  }

  // A connection record's data: the connection header, whose fields must lie within it.
  void checkConnection(const Record &r)
  {
    number(r, "conn", 4);
    field(r, "topic");
    if (r.dataLength > kMaxHeaderLength)
      fail(r.pos, "connection header of " + std::to_string(r.dataLength) + " bytes");
    readFields(r.dataPos, r.dataLength);
  }

private:
  std::string m_filename;
  std::ifstream m_in;
  uint64_t m_size = 0;
};

// What the walk keeps of a chunk: whether it is compressed, and the offsets of its message records.
struct Chunk
{
  bool compressed = false;
  std::vector<uint32_t> messages;
};
} // namespace

void vpSSLRosbagCheck::checkBagFile(const std::string &filename)
{
  BagFile bag(filename);
  const std::string magic = "#ROSBAG V2.0\n";
  std::string line(magic.size(), '\0');
  if (bag.size() < magic.size())
    bag.fail(0, "not a ROS bag 2.0 (no \"#ROSBAG V2.0\" line)");
  bag.read(0, &line[0], line.size());
  if (line != magic)
    bag.fail(0, "not a ROS bag 2.0 (no \"#ROSBAG V2.0\" line)");

  uint64_t indexPos = 0, connectionCount = 0, chunkCount = 0;
  std::vector<std::pair<uint64_t, uint8_t>> records; // position and op of every top-level record
  std::map<uint64_t, Chunk> chunks;
  std::set<uint64_t> connections;                              // of the index section
  std::vector<std::pair<uint64_t, uint64_t>> indexConnections; // index record, connection it names
  std::vector<std::pair<uint64_t, uint64_t>> chunkInfos;       // chunk info record, chunk it points at
  const Chunk *lastChunk = nullptr;                            // the chunk the index records that follow belong to
  for (uint64_t pos = magic.size(); pos < bag.size();) {
    const Record r = bag.readRecord(pos, bag.size());
    switch (r.op) {
    case kFileHeader: {
      if (!records.empty())
        bag.fail(pos, "a second file header");
      indexPos = bag.number(r, "index_pos", 8);
      connectionCount = bag.number(r, "conn_count", 4);
      chunkCount = bag.number(r, "chunk_count", 4);
      auto encryptor = r.fields.find("encryptor");
      if (encryptor != r.fields.end() && !encryptor->second.empty() && encryptor->second != "rosbag/NoEncryptor")
        bag.fail(pos, "encrypted bag (" + encryptor->second + "): not supported");
      break;
    }
    case kChunk: {
      const std::string compression = bag.field(r, "compression");
      const uint64_t size = bag.number(r, "size", 4);
      Chunk &chunk = chunks[pos];
      if (compression == "none") {
        if (size != r.dataLength)
          bag.fail(pos, "uncompressed chunk of " + std::to_string(r.dataLength) + " bytes whose size field says " +
                            std::to_string(size));
        const uint64_t end = r.dataPos + r.dataLength;
        for (uint64_t p = r.dataPos; p < end;) {
          const Record inner = bag.readRecord(p, end);
          if (inner.op == kMessageData) {
            bag.number(inner, "conn", 4);
            bag.number(inner, "time", 8);
            chunk.messages.push_back(static_cast<uint32_t>(p - r.dataPos));
          } else if (inner.op == kConnection) {
            bag.checkConnection(inner);
          } else {
            bag.fail(p, "record of op " + std::to_string(inner.op) + " inside a chunk");
          }
          p = inner.dataPos + inner.dataLength;
        }
      } else if (compression == "bz2" || compression == "lz4") {
        chunk.compressed = true;
        if (size > maxChunkSize())
          bag.fail(pos, compression + " chunk of " + std::to_string(size) + " bytes once uncompressed, more than " +
                            std::to_string(maxChunkSize()));
      } else {
        bag.fail(pos, "chunk compression \"" + compression + "\" (none, bz2 or lz4 expected)");
      }
      break;
    }
    case kIndexData: {
      if (lastChunk == nullptr)
        bag.fail(pos, "index record not after a chunk");
      if (bag.number(r, "ver", 4) != 1)
        bag.fail(pos, "index record version other than 1");
      indexConnections.emplace_back(pos, bag.number(r, "conn", 4));
      const uint64_t count = bag.number(r, "count", 4);
      if (count * 12 != r.dataLength)
        bag.fail(pos,
                 "index record of " + std::to_string(count) + " entries in " + std::to_string(r.dataLength) + " bytes");
      if (!lastChunk->compressed) {
        std::vector<uint8_t> entries(r.dataLength);
        bag.read(r.dataPos, entries.data(), entries.size());
        for (uint64_t i = 0; i < count; ++i) {
          const uint32_t offset = le32(&entries[i * 12 + 8]);
          if (!std::binary_search(lastChunk->messages.begin(), lastChunk->messages.end(), offset))
            bag.fail(r.dataPos + i * 12,
                     "index entry at offset " + std::to_string(offset) + ", not a message record of its chunk");
        }
      }
      break;
    }
    case kConnection:
      bag.checkConnection(r);
      connections.insert(bag.number(r, "conn", 4));
      break;
    case kChunkInfo: {
      if (bag.number(r, "ver", 4) != 1)
        bag.fail(pos, "chunk info record version other than 1");
      chunkInfos.emplace_back(pos, bag.number(r, "chunk_pos", 8));
      bag.number(r, "start_time", 8);
      bag.number(r, "end_time", 8);
      const uint64_t count = bag.number(r, "count", 4);
      if (count * 8 != r.dataLength)
        bag.fail(pos, "chunk info record of " + std::to_string(count) + " entries in " + std::to_string(r.dataLength) +
                          " bytes");
      break;
    }
    case kMessageData:
      bag.fail(pos, "message record outside a chunk");
    default:
      bag.fail(pos, "record of unknown op " + std::to_string(r.op));
    }
    if (records.empty() && r.op != kFileHeader)
      bag.fail(pos, "first record is not the file header");
    if (r.op == kChunk)
      lastChunk = &chunks[pos];
    else if (r.op != kIndexData)
      lastChunk = nullptr;
    records.emplace_back(pos, r.op);
    pos = r.dataPos + r.dataLength;
  }
  if (records.empty())
    bag.fail(magic.size(), "no file header");

  // rosbag_storage reads connection_count connection records from the index position, then chunk_count chunk
  // info records.
  auto index = std::find_if(records.begin(), records.end(),
                            [indexPos](const std::pair<uint64_t, uint8_t> &r) { return r.first == indexPos; });
  if (index == records.end())
    bag.fail(records.front().first, "index position " + std::to_string(indexPos) + " is not the start of a record");
  for (uint64_t i = 0; i < connectionCount + chunkCount; ++i, ++index) {
    const uint8_t expected = i < connectionCount ? kConnection : kChunkInfo;
    if (index == records.end() || index->second != expected)
      bag.fail(index == records.end() ? bag.size() : index->first,
               std::string("expected the index section's ") + (i < connectionCount ? "connection" : "chunk info") +
                   " record " + std::to_string(i < connectionCount ? i : i - connectionCount) + " (the file header " +
                   "announces " + std::to_string(connectionCount) + " and " + std::to_string(chunkCount) + ")");
  }
  for (const auto &info : chunkInfos)
    if (chunks.find(info.second) == chunks.end())
      bag.fail(info.first, "chunk info pointing at byte " + std::to_string(info.second) + ", not a chunk");
  for (const auto &i : indexConnections)
    if (connections.find(i.second) == connections.end())
      bag.fail(i.first,
               "index record of connection " + std::to_string(i.second) + ", which the index section does not declare");
}

namespace {
// Reads a serialized message's fields in order, each within the message.
class Cursor
{
public:
  Cursor(const uint8_t *data, size_t size, const std::string &where) : m_data(data), m_left(size), m_where(where) {}
  void skip(uint64_t n, const char *field)
  {
    if (n > m_left)
      throw vpException(vpException::badValue, m_where + field + ": " + std::to_string(n) + " bytes, the message has " +
                                                   std::to_string(m_left) + " left");
    m_data += n;
    m_left -= static_cast<size_t>(n);
  }
  uint32_t u32(const char *field)
  {
    const uint8_t *p = m_data;
    skip(4, field);
    return le32(p);
  }
  void string(const char *field) { skip(u32(field), field); }
  void array(uint64_t elementSize, const char *field) { skip(elementSize * u32(field), field); }
  void header()
  {
    skip(12, "header"); // seq, stamp
    string("header.frame_id");
  }

private:
  const uint8_t *m_data;
  size_t m_left;
  std::string m_where;
};
} // namespace

void vpSSLRosbagCheck::checkMessage(const std::string &type, const uint8_t *data, size_t size, const std::string &where)
{
  Cursor c(data, size, where);
  c.header();
  if (type == "sensor_msgs/Image") {
    c.skip(8, "height, width");
    c.string("encoding");
    c.skip(5, "is_bigendian, step");
    c.array(1, "data");
  } else if (type == "sensor_msgs/CompressedImage") {
    c.string("format");
    c.array(1, "data");
  } else if (type == "sensor_msgs/CameraInfo") {
    c.skip(8, "height, width");
    c.string("distortion_model");
    c.array(8, "D");
    c.skip(8 * (9 + 9 + 12) + 8 + 17, "K, R, P, binning, roi");
  } else if (type == "nav_msgs/Odometry") {
    c.string("child_frame_id");
    c.skip(8 * (7 + 36 + 6 + 36), "pose, twist");
  } else {
    throw vpException(vpException::badValue, where + "message type " + type + " (not one the reader reads)");
  }
}
