// The wire (realtime/wire.h): a datagram survives encoding whole, and everything else a
// receiver may be sent is refused with its reason, before any of it is read.

#include "cbbg/realtime/wire.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "cbbg/realtime/udp_endpoint.h"

namespace cbbg::realtime {
namespace {

Datagram measurement() {
  return {DatagramKind::kMeasurement, 0xdeadbeef, 41, 0.25, 123456789, {0.1, -2.5, 3.0}, {}};
}

TEST(Wire, ADatagramDecodesToWhatWasEncoded) {
  Datagram sent = measurement();
  sent.text = "cbbg robot (analytic)\ntheta_b";
  const auto bytes = encode(sent, "key");
  EXPECT_EQ(bytes.size(), kHeaderBytes + 8 * 3 + 1 + sent.text.size() + kTagBytes);
  const Decoded got = decode(bytes.data(), bytes.size(), "key");
  ASSERT_TRUE(got.datagram.has_value());
  EXPECT_EQ(got.datagram->kind, DatagramKind::kMeasurement);
  EXPECT_EQ(got.datagram->session, 0xdeadbeefu);
  EXPECT_EQ(got.datagram->sequence, 41u);
  EXPECT_EQ(got.datagram->time, 0.25);
  EXPECT_EQ(got.datagram->stamp, 123456789u);
  EXPECT_EQ(got.datagram->values, sent.values);
  EXPECT_EQ(got.datagram->text, sent.text);
}

TEST(Wire, TheLayoutIsLittleEndianAsDocumented) {
  const auto bytes = encode(measurement(), "");
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 4), "CBBG");
  EXPECT_EQ(bytes[4], kWireVersion);
  EXPECT_EQ(bytes[5], static_cast<std::uint8_t>(DatagramKind::kMeasurement));
  EXPECT_EQ(bytes[6], 3);  // three values
  EXPECT_EQ(bytes[7], 0);
  EXPECT_EQ(bytes[8], 0xef);  // session, low byte first
  EXPECT_EQ(bytes[11], 0xde);
  EXPECT_EQ(bytes[12], 41);  // sequence
  // time 0.25 = 0x3FD0000000000000: its high byte last.
  EXPECT_EQ(bytes[23], 0x3f);
  EXPECT_EQ(bytes[22], 0xd0);
}

TEST(Wire, AnotherKeysDatagramIsForged) {
  const auto bytes = encode(measurement(), "the robot's key");
  EXPECT_EQ(decode(bytes.data(), bytes.size(), "another key").refusal, Refusal::kForged);
  EXPECT_EQ(decode(bytes.data(), bytes.size(), "").refusal, Refusal::kForged);
  EXPECT_FALSE(decode(bytes.data(), bytes.size(), "").datagram.has_value());
}

TEST(Wire, AnyChangedByteIsRefused) {
  const auto bytes = encode(measurement(), "key");
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    auto changed = bytes;
    changed[i] ^= 0x01;
    const Decoded got = decode(changed.data(), changed.size(), "key");
    EXPECT_FALSE(got.datagram.has_value()) << "byte " << i;
  }
}

TEST(Wire, MalformedDatagramsAreRefusedAsSuch) {
  const auto bytes = encode(measurement(), "");
  const auto refusal = [](std::vector<std::uint8_t> b) {
    return decode(b.data(), b.size(), "").refusal;
  };
  EXPECT_EQ(refusal({}), Refusal::kMalformed);
  EXPECT_EQ(refusal({bytes.begin(), bytes.begin() + 20}), Refusal::kMalformed);
  auto longer = bytes;
  longer.push_back(0);
  EXPECT_EQ(refusal(longer), Refusal::kMalformed);
  auto magic = bytes;
  magic[0] = 'X';
  EXPECT_EQ(refusal(magic), Refusal::kMalformed);
  auto version = bytes;
  version[4] = 2;
  EXPECT_EQ(refusal(version), Refusal::kMalformed);
  auto kind = bytes;
  kind[5] = 9;
  EXPECT_EQ(refusal(kind), Refusal::kMalformed);
  auto count = bytes;
  count[6] = 200;  // more values than the bytes hold
  EXPECT_EQ(refusal(count), Refusal::kMalformed);
}

TEST(Wire, NonFiniteValuesAreRefusedEvenWhenSigned) {
  for (const double bad : {std::nan(""), std::numeric_limits<double>::infinity()}) {
    Datagram sent = measurement();
    sent.values[1] = bad;
    const auto bytes = encode(sent, "key");
    EXPECT_EQ(decode(bytes.data(), bytes.size(), "key").refusal, Refusal::kNonFinite);
    sent = measurement();
    sent.time = bad;
    const auto timed = encode(sent, "key");
    EXPECT_EQ(decode(timed.data(), timed.size(), "key").refusal, Refusal::kNonFinite);
  }
}

TEST(Wire, ADatagramHoldsAtMost64ValuesAnd255BytesOfText) {
  Datagram big = measurement();
  big.values.assign(65, 0.0);
  EXPECT_THROW(encode(big, ""), std::invalid_argument);
  big.values.assign(64, 0.0);
  big.text.assign(256, 'x');
  EXPECT_THROW(encode(big, ""), std::invalid_argument);
  big.text.assign(255, 'x');
  EXPECT_EQ(encode(big, "").size(), kMaxDatagramBytes);
}

TEST(Wire, AKeyFileIsReadWithoutItsLineBreakAndRefusedEmptyOrMissing) {
  const auto path = std::filesystem::path(testing::TempDir()) / "cbbg_wire_key";
  std::ofstream(path) << "s3cret\n";
  EXPECT_EQ(read_key_file(path.string(), "--key-file"), "s3cret");
  std::ofstream(path) << "\n";
  try {
    read_key_file(path.string(), "--key-file");
    FAIL() << "an empty key was read";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()), "--key-file: the key file '" + path.string() +
                                             "' must hold 1 to 1024 bytes; it holds 0");
  }
  std::filesystem::remove(path);
  try {
    read_key_file(path.string(), "remote.key_file");
    FAIL() << "a missing key file was read";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()),
              "remote.key_file: cannot read the key file '" + path.string() + "'");
  }
}

TEST(Wire, AddressesAreIpv4HostAndPort) {
  EXPECT_EQ(parse_address("127.0.0.1:5005", "--robot").text(), "127.0.0.1:5005");
  EXPECT_EQ(parse_address("localhost:0", "--bind").text(), "127.0.0.1:0");
  for (const char* bad :
       {"127.0.0.1", "robot:5005", "127.0.0.1:65536", "127.0.0.1:", ":5005", "127.0.0.1:50x5"}) {
    try {
      parse_address(bad, "--robot");
      FAIL() << bad << " was taken";
    } catch (const std::invalid_argument& error) {
      EXPECT_EQ(std::string(error.what()),
                "--robot must be HOST:PORT, HOST an IPv4 address or localhost and PORT 0..65535 "
                "(e.g. 127.0.0.1:5005); got '" +
                    std::string(bad) + "'");
    }
  }
}

}  // namespace
}  // namespace cbbg::realtime
