// The datagrams' byte layout (docs/realtime.md): written and read byte by byte, little-endian
// whatever the host, and signed with HMAC-SHA256 (OpenSSL), truncated to 16 bytes.

#include "cbbg/realtime/wire.h"

#include <openssl/evp.h>
#include <openssl/hmac.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace cbbg::realtime {
namespace {

constexpr std::uint8_t kMagic[4] = {'C', 'B', 'B', 'G'};

void put(std::vector<std::uint8_t>& bytes, std::uint64_t value, int size) {
  for (int i = 0; i < size; ++i) bytes.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

std::uint64_t get(const std::uint8_t* bytes, int size) {
  std::uint64_t value = 0;
  for (int i = 0; i < size; ++i) value |= static_cast<std::uint64_t>(bytes[i]) << (8 * i);
  return value;
}

std::array<std::uint8_t, kTagBytes> tag_of(const std::uint8_t* bytes, std::size_t size,
                                           const Key& key) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  // HMAC of an empty key is HMAC with a key of zero bytes: a hash that still catches damage.
  static const unsigned char kNoKey = 0;
  const void* key_bytes = key.empty() ? static_cast<const void*>(&kNoKey) : key.data();
  if (HMAC(EVP_sha256(), key_bytes, static_cast<int>(key.size()), bytes, size, digest, &length) ==
          nullptr ||
      length < kTagBytes) {
    throw std::runtime_error("the datagram's HMAC-SHA256 could not be computed");
  }
  std::array<std::uint8_t, kTagBytes> tag{};
  std::copy_n(digest, kTagBytes, tag.begin());
  return tag;
}

bool known_kind(std::uint8_t kind) {
  return kind >= static_cast<std::uint8_t>(DatagramKind::kHello) &&
         kind <= static_cast<std::uint8_t>(DatagramKind::kStop);
}

}  // namespace

const char* to_string(DatagramKind kind) {
  switch (kind) {
    case DatagramKind::kHello:
      return "hello";
    case DatagramKind::kWelcome:
      return "welcome";
    case DatagramKind::kStart:
      return "start";
    case DatagramKind::kMeasurement:
      return "measurement";
    case DatagramKind::kTorque:
      return "torque";
    case DatagramKind::kStop:
      return "stop";
  }
  return "unknown";
}

const char* to_string(Refusal refusal) {
  switch (refusal) {
    case Refusal::kMalformed:
      return "malformed";
    case Refusal::kForged:
      return "forged";
    case Refusal::kNonFinite:
      return "non_finite";
    case Refusal::kOtherSource:
      return "other_source";
    case Refusal::kOtherSession:
      return "other_session";
    case Refusal::kOutOfSequence:
      return "out_of_sequence";
  }
  return "unknown";
}

std::string joined_names(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ",") + name;
  return text;
}

Key read_key_file(const std::string& path, std::string_view what) {
  std::ifstream file(path, std::ios::binary);
  Key key((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (!file.is_open() || file.bad()) {
    throw std::invalid_argument(std::string(what) + ": cannot read the key file '" + path + "'");
  }
  if (!key.empty() && key.back() == '\n') key.pop_back();
  if (!key.empty() && key.back() == '\r') key.pop_back();
  if (key.empty() || key.size() > 1024) {
    throw std::invalid_argument(std::string(what) + ": the key file '" + path +
                                "' must hold 1 to 1024 bytes; it holds " +
                                std::to_string(key.size()));
  }
  return key;
}

std::vector<std::uint8_t> encode(const Datagram& datagram, const Key& key) {
  if (datagram.values.size() > kMaxValues || datagram.text.size() > kMaxTextBytes) {
    throw std::invalid_argument("a datagram holds at most " + std::to_string(kMaxValues) +
                                " values and " + std::to_string(kMaxTextBytes) + " bytes of text");
  }
  std::vector<std::uint8_t> bytes(std::begin(kMagic), std::end(kMagic));
  bytes.reserve(kMaxDatagramBytes);
  bytes.push_back(kWireVersion);
  bytes.push_back(static_cast<std::uint8_t>(datagram.kind));
  put(bytes, datagram.values.size(), 2);
  put(bytes, datagram.session, 4);
  put(bytes, datagram.sequence, 4);
  put(bytes, std::bit_cast<std::uint64_t>(datagram.time), 8);
  put(bytes, datagram.stamp, 8);
  for (const double value : datagram.values) put(bytes, std::bit_cast<std::uint64_t>(value), 8);
  put(bytes, datagram.text.size(), 1);
  bytes.insert(bytes.end(), datagram.text.begin(), datagram.text.end());
  const auto tag = tag_of(bytes.data(), bytes.size(), key);
  bytes.insert(bytes.end(), tag.begin(), tag.end());
  return bytes;
}

Decoded decode(const std::uint8_t* bytes, std::size_t size, const Key& key) {
  if (size < kHeaderBytes + 1 + kTagBytes || !std::equal(kMagic, kMagic + 4, bytes) ||
      bytes[4] != kWireVersion || !known_kind(bytes[5])) {
    return {};
  }
  const std::size_t count = get(bytes + 6, 2);
  const std::size_t text_at = kHeaderBytes + 8 * count;
  if (count > kMaxValues || size < text_at + 1 + kTagBytes ||
      size != text_at + 1 + bytes[text_at] + kTagBytes) {
    return {};
  }
  const auto tag = tag_of(bytes, size - kTagBytes, key);
  // Constant time: a forger learns nothing from how long the comparison took.
  if (CRYPTO_memcmp(tag.data(), bytes + size - kTagBytes, kTagBytes) != 0) {
    return {std::nullopt, Refusal::kForged};
  }
  Datagram datagram;
  datagram.kind = static_cast<DatagramKind>(bytes[5]);
  datagram.session = static_cast<std::uint32_t>(get(bytes + 8, 4));
  datagram.sequence = static_cast<std::uint32_t>(get(bytes + 12, 4));
  datagram.time = std::bit_cast<double>(get(bytes + 16, 8));
  datagram.stamp = get(bytes + 24, 8);
  for (std::size_t i = 0; i < count; ++i) {
    datagram.values.push_back(std::bit_cast<double>(get(bytes + kHeaderBytes + 8 * i, 8)));
  }
  datagram.text.assign(reinterpret_cast<const char*>(bytes + text_at + 1), bytes[text_at]);
  const bool finite = std::isfinite(datagram.time) &&
                      std::all_of(datagram.values.begin(), datagram.values.end(),
                                  [](double value) { return std::isfinite(value); });
  if (!finite) return {std::nullopt, Refusal::kNonFinite};
  return {std::move(datagram), Refusal::kMalformed};
}

}  // namespace cbbg::realtime
