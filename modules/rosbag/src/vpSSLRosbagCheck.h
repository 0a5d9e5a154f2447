/*
  Internal to visp_ssl_rosbag (not installed): the checks a bag and its messages pass before rosbag_storage and
  roscpp_serialization read them. Both trust the lengths they read: rosbag_storage allocates a record's declared
  header length before reading it (4 GB for a corrupt length), parses the records of a chunk at the offsets of the
  index without comparing them with the chunk's size, and roscpp_serialization resizes a message's array to its
  declared length before checking that the message holds it.
*/
#ifndef VP_SSL_ROSBAG_CHECK_H
#define VP_SSL_ROSBAG_CHECK_H

#include <cstddef>
#include <cstdint>
#include <string>

namespace vpSSLRosbagCheck {

/*
  Walks every record of a ROS bag 2.0 file and throws a vpException (ioError) "FILE: cannot read the bag: byte N:
  problem" unless:
  each record's header and data lie within the file, its header's fields within the header, and its op is one of
  the format's; the file header comes first, without an encryptor, and its index position is the start of its
  connection_count connection records and chunk_count chunk info records; a chunk's compression is none, bz2 or
  lz4, an uncompressed chunk's records lie within it (and its size field equals its data length) and a compressed
  one declares at most maxChunkSize() bytes; an index record follows its chunk, holds count entries of 12 bytes,
  names a connection of the index section and, after an uncompressed chunk, points each entry at a message record
  of that chunk; a chunk info record holds count entries of 8 bytes and points at a chunk.
  What is not checked: the records inside a compressed chunk (it would take decompressing every chunk).
*/
void checkBagFile(const std::string &filename);

//! Largest uncompressed size a compressed chunk may declare: 512 MiB, room for one image of the image limits.
constexpr uint64_t maxChunkSize()
{
  return uint64_t(1) << 29;
}

/*
  Checks that the serialized message \e data of \e type (sensor_msgs/Image, sensor_msgs/CompressedImage,
  sensor_msgs/CameraInfo or nav_msgs/Odometry) holds every string and array its lengths declare.
  \exception vpException (badValue) "\e where: problem".
*/
void checkMessage(const std::string &type, const uint8_t *data, size_t size, const std::string &where);

} // namespace vpSSLRosbagCheck

#endif
