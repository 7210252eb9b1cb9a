#pragma once
// The datagrams between a controller (`cbbg drive`) and a robot (`cbbg robot`, or a real
// robot's firmware): a fixed little-endian layout, one datagram per UDP packet, each signed
// with a keyed hash. docs/realtime.md gives the byte layout and the session it carries:
//
//   controller                          robot
//   hello(session, period) ------------>
//   <------------ welcome(session, period, signal names)   (or stop with the reason)
//   start(theta0) ---------------------->                  the robot resets, its clock starts
//   <------------ measurement(seq k, t_k, signals..., link figures)   every period
//   torque(seq k, tau_l, tau_r) -------->                  before the deadline, else held
//   ...   start(theta0) for the next trial, or stop: zero torque, the session ends

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cbbg::realtime {

inline constexpr std::uint8_t kWireVersion = 1;

enum class DatagramKind : std::uint8_t {
  kHello = 1,
  kWelcome = 2,
  kStart = 3,
  kMeasurement = 4,
  kTorque = 5,
  kStop = 6,
};
const char* to_string(DatagramKind kind);

struct Datagram {
  DatagramKind kind = DatagramKind::kStop;
  std::uint32_t session = 0;   // chosen by the controller's hello, the same in every datagram
  std::uint32_t sequence = 0;  // measurement: its own, rising; torque: the one it answers
  double time = 0.0;           // measurement: s since its trial started; torque: echoed
  std::uint64_t stamp = 0;     // measurement: the robot's clock, ns; torque: echoed
  std::vector<double> values;  // what the kind carries (below)
  std::string text;            // hello, welcome, stop: a name or a reason, at most 255 bytes
};
// What each kind carries:
//   hello        values {period s}; text: the controller's name
//   welcome      values {period s}; text: the robot's name, a newline, its signals' names
//                joined by commas
//   start        values {theta0 rad}
//   measurement  values {the signals..., the round trip of the torque that answered the
//                previous measurement, s: kMissedDeadline when none came in time,
//                kNoTorqueAsked for a trial's first}
//   torque       values {tau_l, tau_r N m}; sequence, time and stamp those of the measurement
//                it answers
//   stop         text: why
inline constexpr double kMissedDeadline = -1.0;
inline constexpr double kNoTorqueAsked = -2.0;

// `names` joined by commas: the signals as a welcome's text lists them.
std::string joined_names(const std::vector<std::string>& names);

// The shared key both sides sign with; empty: an unkeyed hash, which catches corruption only.
using Key = std::string;

// The key in the file at `path`: its bytes, a final line break dropped; 1 to 1024 bytes.
// Throws std::invalid_argument naming `what` (a flag or key) and the path.
Key read_key_file(const std::string& path, std::string_view what);

// Most values one datagram carries, and its largest size in bytes.
inline constexpr std::size_t kMaxValues = 64;
inline constexpr std::size_t kMaxTextBytes = 255;
inline constexpr std::size_t kHeaderBytes = 32;
inline constexpr std::size_t kTagBytes = 16;
inline constexpr std::size_t kMaxDatagramBytes =
    kHeaderBytes + 8 * kMaxValues + 1 + kMaxTextBytes + kTagBytes;

// The bytes of `datagram`, signed with `key`. Throws std::invalid_argument for more values or
// text than a datagram holds.
std::vector<std::uint8_t> encode(const Datagram& datagram, const Key& key);

// Why a received datagram was not applied.
enum class Refusal {
  kMalformed,    // too short or long, wrong magic, version or kind, sizes that disagree
  kForged,       // its tag is not the key's
  kNonFinite,    // a value is NaN or infinite
  kOtherSource,  // from an address that is not the session's peer
  kOtherSession,
  kOutOfSequence,  // older than, or a repeat of, what was applied
};
const char* to_string(Refusal refusal);

// The datagram in `bytes` when it is well formed, signed with `key` and finite; else why not.
struct Decoded {
  std::optional<Datagram> datagram;
  Refusal refusal = Refusal::kMalformed;
};
Decoded decode(const std::uint8_t* bytes, std::size_t size, const Key& key);

}  // namespace cbbg::realtime
