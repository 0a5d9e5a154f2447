/*
  Helpers shared by the libFuzzer targets: a scratch folder of the process, files written from the fuzzer's
  bytes, and the rule every target checks: bad input gives a vpException, never anything else. A target that
  lets any other exception escape, crashes, leaks or reads out of bounds is a finding (ASan, UBSan and LSan
  are on in the fuzz build).
*/
#ifndef SSL_FUZZ_COMMON_H
#define SSL_FUZZ_COMMON_H

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace sslfuzz {
//! A folder of this process, removed at exit: in /dev/shm when there is one (the targets write a file per
//! input, 15 times faster in memory than on a disk), else under TMPDIR or /tmp.
inline const std::filesystem::path &scratch()
{
  struct Folder
  {
    std::filesystem::path path;
    Folder()
    {
      std::error_code ec;
      const char *tmp = std::getenv("TMPDIR");
      const std::filesystem::path base = std::filesystem::is_directory("/dev/shm", ec)
                                             ? std::filesystem::path("/dev/shm")
                                             : std::filesystem::path(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp");
      path = base / ("visp-ssl-fuzz-" + std::to_string(::getpid()));
      std::filesystem::create_directories(path);
    }
    ~Folder()
    {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  };
  static const Folder folder;
  return folder.path;
}

//! Writes \e size bytes to \e path (replacing it).
inline void writeFile(const std::filesystem::path &path, const uint8_t *data, size_t size)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char *>(data), static_cast<std::streamsize>(size));
}

inline void writeFile(const std::filesystem::path &path, const std::string &text)
{
  writeFile(path, reinterpret_cast<const uint8_t *>(text.data()), text.size());
}

//! Reads bytes from the fuzzer's input, zeros once it is used up.
class Input
{
public:
  Input(const uint8_t *data, size_t size) : m_data(data), m_size(size), m_pos(0) {}
  uint8_t byte() { return m_pos < m_size ? m_data[m_pos++] : 0; }
  uint16_t u16() { return static_cast<uint16_t>(byte() | (byte() << 8)); }
  uint32_t u32() { return static_cast<uint32_t>(u16()) | (static_cast<uint32_t>(u16()) << 16); }
  //! Any double, NaN and infinities included (its 8 bytes as they come).
  double anyDouble()
  {
    uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) {
      bits |= static_cast<uint64_t>(byte()) << (8 * i);
    }
    double d;
    static_assert(sizeof(d) == sizeof(bits), "IEEE double");
    std::memcpy(&d, &bits, sizeof(d));
    return d;
  }
  //! A double in [lo, hi].
  double range(double lo, double hi) { return lo + (hi - lo) * (u16() / 65535.); }
  size_t left() const { return m_size - m_pos; }
  const uint8_t *rest() const { return m_data + m_pos; }
  void skip(size_t n) { m_pos += n < left() ? n : left(); }

private:
  const uint8_t *m_data;
  size_t m_size;
  size_t m_pos;
};
} // namespace sslfuzz

#endif
